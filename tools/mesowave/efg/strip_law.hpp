#pragma once
// The laws `mw-efg wave` runs on its strip, by name (a plug-in registry: one entry per law, its
// keys declared, no if-chain on the name). Each gives the point material of the explicit solver
// and the same law under uniaxial strain, p = f(s) (efg/characteristics), which the method of
// characteristics traces for the reference the strip is compared with:
//   linear     sigma = D eps (p = M s), the continuum of the linear check;
//   quadratic  d sigma = (1 + 2 beta |eps_v|) D d eps, p = M s (1 + beta s): the smooth stiffening
//              law of the clean analytic comparison (not the paper's; lab-data/shock-concrete/
//              shock-steepening-smooth.toml);
//   hugoniot   the paper's Y-function, Eqs. (24)-(26), with Eq. (27)'s unloading when
//              `unloading` (Section 4.2's steepening test runs without it; lab-data/shock-concrete/
//              hugoniot.toml). The characteristics follow the loading branch only, which is what
//              a compressive front travels on.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "mesowave/efg/characteristics.hpp"
#include "mesowave/efg/hugoniot.hpp"
#include "mesowave/efg/point_material.hpp"

namespace mesowave::efg {

struct StripLawParameters {
  double beta = 10;              ///< quadratic: p = M s (1 + beta s)
  HugoniotParameters hugoniot;   ///< hugoniot: Eq. (26), Eq. (27) on or off
};

struct StripLaw {
  std::string name;
  std::unique_ptr<PointMaterial> point;           ///< the explicit solver's law at a Gauss point
  std::unique_ptr<CompressionLaw> compression;    ///< the same under uniaxial strain, p = f(s)
  bool nonlinear = false;                         ///< false: the linear law (no shock forms)
  /// true: the point law unloads on another path than `compression` (hugoniot with Eq. (27)), so a
  /// 1D bar of `compression` is not the same material behind the front (efg/shock_front's bar reference)
  bool unloads = false;
};

struct StripLawEntry {
  std::string summary;
  std::vector<std::string> keys;  ///< the StripLawParameters it reads (for the run's record)
  std::function<StripLaw(const ElasticMaterial2D&, const StripLawParameters&)> make;
};

/// Every law by name.
const std::map<std::string, StripLawEntry>& strip_laws();
/// "linear | quadratic | hugoniot", for an option's help.
std::string strip_law_names();
/// The law `name` of plane-strain `material` (its M = D_11 is the uniaxial-strain modulus).
/// InputError: an unknown name (listing the known), beta <= 0 or not finite, bad Hugoniot parameters.
StripLaw make_strip_law(const std::string& name, const ElasticMaterial2D& material, const StripLawParameters& p);

}  // namespace mesowave::efg
