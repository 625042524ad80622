#include "mesowave/efg/strip_law.hpp"

#include <cmath>

#include "mesowave/core/check.hpp"
#include "mesowave/core/error.hpp"

namespace mesowave::efg {

const std::map<std::string, StripLawEntry>& strip_laws() {
  static const std::map<std::string, StripLawEntry> laws = {
      {"linear",
       {"sigma = D eps", {}, [](const ElasticMaterial2D& m, const StripLawParameters&) {
          StripLaw law;
          law.point = std::make_unique<LinearElasticPoint>(m);
          law.compression = std::make_unique<LinearCompression>(m.D()(0, 0));
          return law;
        }}},
      {"quadratic",
       {"p = M s (1 + beta s), the smooth stiffening law", {"beta"},
        [](const ElasticMaterial2D& m, const StripLawParameters& p) {
          if (!std::isfinite(p.beta) || p.beta <= 0)
            throw InputError("--beta (" + format_number(p.beta) + ") must be > 0 (the quadratic law's stiffening)");
          StripLaw law;
          law.point = std::make_unique<QuadraticStiffeningPoint>(m, p.beta);
          law.compression = std::make_unique<QuadraticStiffening>(m.D()(0, 0), p.beta);
          law.nonlinear = true;
          return law;
        }}},
      {"hugoniot",
       {"the Y-function, Eqs. (24)-(27)", {"e_v_th", "e_v", "a_v", "b_v", "unloading"},
        [](const ElasticMaterial2D& m, const StripLawParameters& p) {
          p.hugoniot.validate();
          StripLaw law;
          law.point = std::make_unique<HugoniotElastic>(m, p.hugoniot);
          law.compression = std::make_unique<HugoniotCompression>(m.D()(0, 0), p.hugoniot);
          law.nonlinear = true;
          law.unloads = p.hugoniot.unloading;
          return law;
        }}},
  };
  return laws;
}

std::string strip_law_names() {
  std::string names;
  for (const auto& [name, entry] : strip_laws()) names += (names.empty() ? "" : " | ") + name;
  return names;
}

StripLaw make_strip_law(const std::string& name, const ElasticMaterial2D& material, const StripLawParameters& p) {
  const auto it = strip_laws().find(name);
  if (it == strip_laws().end()) throw InputError("--law " + name + " is not a strip law (" + strip_law_names() + ")");
  StripLaw law = it->second.make(material, p);
  law.name = name;
  return law;
}

}  // namespace mesowave::efg
