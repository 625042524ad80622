#include "mesowave/dem/scene/plugins.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "mesowave/core/error.hpp"

namespace mesowave::dem {

#define MW_DEM_PLUGIN(id) void register_##id(Plugins&);
#include "mesowave/dem/scene/plugins.def"
#undef MW_DEM_PLUGIN

namespace {

const Plugins& plugins() {
  static const Plugins all = [] {
    Plugins p;
#define MW_DEM_PLUGIN(id) register_##id(p);
#include "mesowave/dem/scene/plugins.def"
#undef MW_DEM_PLUGIN
    return p;
  }();
  return all;
}

}  // namespace

template <class Entry>
void Registry<Entry>::add(Entry entry) {
  if (find(entry.name)) throw std::logic_error(what_ + " \"" + entry.name + "\" registered twice");
  entries_.push_back(std::move(entry));
}

template <class Entry>
std::string Registry<Entry>::listing() const {
  std::string text;
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    if (i > 0) text += i + 1 == entries_.size() ? " or " : ", ";
    text += entries_[i].name;
  }
  return text;
}

template <class Entry>
const Entry& Registry<Entry>::get(const std::string& name, const std::string& who) const {
  if (const Entry* e = find(name)) return *e;
  throw InputError(who + " (\"" + name + "\") must be " + listing());
}

template class Registry<ContactLaw>;
template class Registry<ActuatorKind>;
template class Registry<SensorKind>;

const Registry<ContactLaw>& contact_laws() { return plugins().laws; }
const Registry<ActuatorKind>& actuator_kinds() { return plugins().actuators; }
const Registry<SensorKind>& sensor_kinds() { return plugins().sensors; }

std::unique_ptr<Model> make_model(const std::string& law, const std::string& model, SpherePart spheres, BondNetwork bonds,
                                  const CohesiveFrictionalMaterial& material, const LawParameters& parameters,
                                  std::optional<Vec3> line) {
  return contact_laws().get(law, "contact law").make(model, std::move(spheres), std::move(bonds),
                                                     LawInput{material, parameters, line});
}

double platen_peak_force(const ActuatorSpec& a, std::size_t, double stiffest_kn, double duration_s) {
  return stiffest_kn * (std::abs(a.amplitude) * duration_s);
}

std::vector<std::uint32_t> packing_indices(const SphereStatics& statics, const std::vector<std::size_t>& spheres) {
  std::vector<std::uint32_t> out;
  for (std::size_t k : spheres) out.push_back(statics.packing_index(k));
  std::sort(out.begin(), out.end());
  return out;
}

const SensorKind& sensor_kind_for_quantity(const std::string& quantity, const std::string& who) {
  std::string all;
  const auto& kinds = sensor_kinds().entries();
  std::vector<std::string> names;
  for (const auto& kind : kinds)
    for (const auto& q : kind.quantities) {
      if (q == quantity) return kind;
      names.push_back(q);
    }
  for (std::size_t i = 0; i < names.size(); ++i) all += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  throw InputError(who + ": sensor quantity \"" + quantity + "\" must be " + all);
}

}  // namespace mesowave::dem
