#pragma once
// Cohesive laws of the fracture process zone (the paper's Section 3.1): the
// normal traction sigma_ccs(w) that the two faces of a crack carry as a
// function of the opening w, falling from the tensile strength f_t at w = 0 to
// zero at the critical opening w_max, with the fracture energy G_f as the area
// under the curve. Registered by name (a small registry like the DEM's
// dem/scene/plugins.hpp: name -> factory, each law's own keys with units and
// ranges), so a tool or a test only names the law.
//
// Unloading and reloading of an opened segment (the rule the paper leaves
// open): secant to the origin, with the largest opening reached, w_hist, as the
// history - sigma = sigma_env(w_hist) w / w_hist for w < w_hist, the envelope
// again once w passes w_hist. Energy already dissipated stays dissipated; a
// closing face gives back only the elastic part stored along the secant.
// A new segment starts with w_hist = w_initial (a small fraction of w_max,
// `initial_opening_fraction`), so before any opening the faces are tied by
// the stiff secant f_t / w_initial instead of the rigid branch at w = 0 that
// an initially rigid law has and Newton cannot take: the area lost is
// f_t w_initial / 2, i.e. initial_opening_fraction (1 + alpha) / 2 of G_f for
// the exponential law (1.5e-3 at the defaults). Interpenetration (w < 0)
// meets the same stiffness as a penalty, sigma = (f_t / w_initial) w.
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mesowave::efg {

/// What every law takes. SI: Pa, J/m^2 = N/m. The concrete's properties (f_t, G_f, f_c: a lab-data
/// file gives them, lab-data/shock-concrete/three-point-bending.toml) apart from the law's own
/// shape parameters in `keys` (CohesiveLawEntry::keys; absent keys take their fallback, the one place
/// their default lives).
struct CohesiveParameters {
  double f_t_Pa = 0;     ///< tensile strength f_t (f_t,dyn, f_ct in the paper: the static one here)
  double G_f_J_m2 = 0;   ///< fracture energy G_f, Eq. (20) / Eq. (23)
  std::map<std::string, double> keys;
  /// Compressive strength f_c: the bilinear law's beta_t by Eq. (22) - the paper's input, beta_t is derived
  /// (the exponential law does not use it). Unset: beta_t = 0.25, Eq. (22)'s value for f_c below 30 MPa.
  std::optional<double> f_c_Pa;
};

class CohesiveLaw {
public:
  virtual ~CohesiveLaw() = default;
  virtual std::string name() const = 0;
  virtual double f_t_Pa() const = 0;
  virtual double w_max_m() const = 0;                ///< Eq. (20) / Eq. (23)
  virtual double traction_Pa(double w_m) const = 0;  ///< on the softening envelope, 0 <= w; 0 beyond w_max
  virtual double tangent_Pa_per_m(double w_m) const = 0;  ///< d traction / dw on the envelope
  /// The shape parameters the law was made with, derived ones included (alpha; alpha_t, beta_t): for the record.
  virtual std::map<std::string, double> parameters() const = 0;
};

/// One law's own key: the unit is in its name (f_c_Pa); values outside [min, max] are an InputError.
struct CohesiveKeySpec {
  std::string key, unit;
  double min = 0, max = 0;
  double fallback = 0;
  std::string meaning;
};

struct CohesiveLawEntry {
  std::string name;
  std::string summary;  ///< one line with its equations
  std::vector<CohesiveKeySpec> keys;
  /// Gets f_t, G_f (validated) and every key of `keys` (filled with fallbacks, range-checked).
  std::function<std::unique_ptr<CohesiveLaw>(const CohesiveParameters&)> make;
};

/// The registered laws, in order: "exponential", "bilinear".
const std::vector<CohesiveLawEntry>& cohesive_laws();
/// The entry named `name`; InputError "cohesive law (\"x\") must be exponential or bilinear".
const CohesiveLawEntry& cohesive_law_entry(std::string_view name);
/// InputError for f_t <= 0, G_f <= 0, f_c <= 0 or above 190 MPa (where Eq. (22) gives beta_t <= 0.01), an
/// unknown key or a key out of its range (naming the value).
std::unique_ptr<CohesiveLaw> make_cohesive_law(std::string_view name, const CohesiveParameters& parameters);

/// The exponential (power) law, Eqs. (19)-(20): sigma = f_t (1 - w/w_max)^alpha, w_max = (1 + alpha) G_f / f_t.
class ExponentialCohesiveLaw final : public CohesiveLaw {
public:
  ExponentialCohesiveLaw(double f_t_Pa, double G_f_J_m2, double alpha);
  std::string name() const override { return "exponential"; }
  double f_t_Pa() const override { return f_t_; }
  double w_max_m() const override { return w_max_; }
  double traction_Pa(double w_m) const override;
  double tangent_Pa_per_m(double w_m) const override;
  std::map<std::string, double> parameters() const override { return {{"alpha", alpha_}}; }
  double alpha() const { return alpha_; }

private:
  double f_t_, alpha_, w_max_;
};

/// Akkermann's bilinear law, Eqs. (21)-(23): from f_t down to beta_t f_t at the kink
/// w = alpha_t w_max, then linearly to zero at w_max = 2 G_f / (f_t (alpha_t + beta_t)).
class BilinearCohesiveLaw final : public CohesiveLaw {
public:
  BilinearCohesiveLaw(double f_t_Pa, double G_f_J_m2, double alpha_t, double beta_t);
  std::string name() const override { return "bilinear"; }
  double f_t_Pa() const override { return f_t_; }
  double w_max_m() const override { return w_max_; }
  double traction_Pa(double w_m) const override;
  double tangent_Pa_per_m(double w_m) const override;
  std::map<std::string, double> parameters() const override { return {{"alpha_t", alpha_t_}, {"beta_t", beta_t_}}; }
  double alpha_t() const { return alpha_t_; }
  double beta_t() const { return beta_t_; }

private:
  double f_t_, alpha_t_, beta_t_, w_max_;
};

/// Eq. (22): beta_t = 0.25 for f_c < 30 MPa, 0.25 - 0.0015 (f_c[MPa] - 30) above
/// (f_c enters the bilinear law only here).
double bilinear_beta_t(double f_c_Pa);

/// Traction and its derivative at an opening, with the history rule of the header comment.
struct CohesiveResponse {
  double traction_Pa = 0;
  double tangent_Pa_per_m = 0;  ///< d traction / dw (the secant on unloading, the penalty when closed)
  bool loading = false;         ///< on the envelope (w >= w_hist): the history grows
};

/// Default initial opening w_initial as a fraction of w_max (header comment).
inline constexpr double initial_opening_fraction = 1e-3;

/// sigma(w) given the largest opening reached so far, w_hist (>= w_initial > 0): the envelope for
/// w >= w_hist, the secant sigma_env(w_hist) w / w_hist for 0 <= w < w_hist (zero once w_hist >=
/// w_max: the segment is traction-free), and for w < 0 the closed-face penalty f_t w / w_initial.
CohesiveResponse cohesive_response(const CohesiveLaw& law, double w_m, double w_hist_m, double w_initial_m);

/// Energy per face area [J/m^2] dissipated by a point that reached w_hist under cohesive_response: the
/// path's area (the initial secant to w_initial, then the envelope to w_hist) less the triangle still
/// stored on the secant at w_hist, 1/2 sigma_env(w_hist) w_hist. Quadrature on the law: 16 pieces of
/// 8-point Gauss-Legendre, the rule of CohesiveInterface::dissipated_energy_J (exact for the
/// exponential law's polynomial envelope at integer alpha; the bilinear kink inside a piece is not
/// resolved exactly). Zero for w_hist <= w_initial.
double cohesive_dissipated_J_m2(const CohesiveLaw& law, double w_hist_m, double w_initial_m);

}  // namespace mesowave::efg
