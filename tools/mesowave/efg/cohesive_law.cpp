#include "mesowave/efg/cohesive_law.hpp"

#include <algorithm>
#include <cmath>

#include "mesowave/core/check.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"

namespace mesowave::efg {

namespace {

/// The entry's keys from `p.keys`: fallbacks for absent ones, InputError for unknown or out-of-range ones.
std::map<std::string, double> read_keys(const CohesiveLawEntry& entry, const CohesiveParameters& p) {
  require_positive("cohesive law " + entry.name + ": f_t_Pa", p.f_t_Pa);
  require_positive("cohesive law " + entry.name + ": G_f_J_m2", p.G_f_J_m2);
  std::map<std::string, double> out;
  for (const auto& [key, value] : p.keys) {
    auto spec = std::find_if(entry.keys.begin(), entry.keys.end(), [&](const CohesiveKeySpec& k) { return k.key == key; });
    if (spec == entry.keys.end()) {
      std::string known;
      for (const auto& k : entry.keys) known += (known.empty() ? "" : ", ") + k.key;
      throw InputError("cohesive law " + entry.name + ": unknown key " + key + " (known: " + known + ")");
    }
    if (!(value >= spec->min && value <= spec->max))
      throw InputError("cohesive law " + entry.name + ": " + key + " (" + format_number(value) + ") must be in [" +
                       format_number(spec->min) + ", " + format_number(spec->max) + "] " + spec->unit);
    out[key] = value;
  }
  for (const auto& k : entry.keys) out.emplace(k.key, k.fallback);
  return out;
}

std::vector<CohesiveLawEntry> build_registry() {
  std::vector<CohesiveLawEntry> laws;
  laws.push_back({"exponential",
                  "sigma = f_t (1 - w/w_max)^alpha, w_max = (1 + alpha) G_f / f_t, Eqs. (19)-(20)",
                  {{"alpha", "1", 0.1, 20, 2.0,
                    "exponent of Eq. (19); not given in the paper, assumed 2: a convex curve like the measured softening "
                    "curves of concrete, w_max = 3 G_f / f_t by Eq. (20), and a lower initial slope than the bilinear "
                    "law's, so that it carries more load just after the peak, as the paper finds (Section 4.1)"}},
                  [](const CohesiveParameters& p) -> std::unique_ptr<CohesiveLaw> {
                    auto k = read_keys(cohesive_law_entry("exponential"), p);
                    return std::make_unique<ExponentialCohesiveLaw>(p.f_t_Pa, p.G_f_J_m2, k["alpha"]);
                  }});
  laws.push_back({"bilinear",
                  "Akkermann: f_t to beta_t f_t at alpha_t w_max, then to 0 at w_max = 2 G_f / (f_t (alpha_t + beta_t)), "
                  "Eqs. (21)-(23); beta_t from the concrete's f_c by Eq. (22)",
                  {{"alpha_t", "1", 0.01, 0.99, 0.14, "kink opening over w_max, Eq. (21) (the paper after Roelfstra: 0.14)"}},
                  [](const CohesiveParameters& p) -> std::unique_ptr<CohesiveLaw> {
                    auto k = read_keys(cohesive_law_entry("bilinear"), p);
                    double beta_t = 0.25;  // Eq. (22) below 30 MPa
                    if (p.f_c_Pa && !(*p.f_c_Pa > 0 && *p.f_c_Pa <= 190e6))
                      throw InputError("cohesive law bilinear: f_c (" + format_number(*p.f_c_Pa * 1e-6) +
                                       " MPa) must be in (0, 190] MPa (Eq. (22) keeps beta_t above 0.01 there)");
                    if (p.f_c_Pa) beta_t = bilinear_beta_t(*p.f_c_Pa);
                    return std::make_unique<BilinearCohesiveLaw>(p.f_t_Pa, p.G_f_J_m2, k["alpha_t"], beta_t);
                  }});
  return laws;
}

}  // namespace

const std::vector<CohesiveLawEntry>& cohesive_laws() {
  static const std::vector<CohesiveLawEntry> laws = build_registry();
  return laws;
}

const CohesiveLawEntry& cohesive_law_entry(std::string_view name) {
  const auto& laws = cohesive_laws();
  for (const auto& e : laws)
    if (e.name == name) return e;
  std::string listing;
  for (std::size_t i = 0; i < laws.size(); ++i)
    listing += (i == 0 ? "" : i + 1 == laws.size() ? " or " : ", ") + laws[i].name;
  throw InputError("cohesive law (\"" + std::string(name) + "\") must be " + listing);
}

std::unique_ptr<CohesiveLaw> make_cohesive_law(std::string_view name, const CohesiveParameters& parameters) {
  return cohesive_law_entry(name).make(parameters);
}

// ---- exponential, Eqs. (19)-(20) ----

ExponentialCohesiveLaw::ExponentialCohesiveLaw(double f_t_Pa, double G_f_J_m2, double alpha)
    : f_t_(f_t_Pa), alpha_(alpha), w_max_((1 + alpha) * G_f_J_m2 / f_t_Pa) {
  require_positive("exponential cohesive law: f_t_Pa", f_t_Pa);
  require_positive("exponential cohesive law: G_f_J_m2", G_f_J_m2);
  require_positive("exponential cohesive law: alpha", alpha);
}

double ExponentialCohesiveLaw::traction_Pa(double w_m) const {
  if (w_m >= w_max_) return 0;
  return f_t_ * std::pow(1 - std::max(w_m, 0.0) / w_max_, alpha_);
}

double ExponentialCohesiveLaw::tangent_Pa_per_m(double w_m) const {
  if (w_m >= w_max_) return 0;
  return -alpha_ * f_t_ / w_max_ * std::pow(1 - std::max(w_m, 0.0) / w_max_, alpha_ - 1);
}

// ---- bilinear, Eqs. (21)-(23) ----

double bilinear_beta_t(double f_c_Pa) {
  const double f_c_MPa = f_c_Pa * 1e-6;
  return f_c_MPa < 30 ? 0.25 : 0.25 - 0.0015 * (f_c_MPa - 30);
}

BilinearCohesiveLaw::BilinearCohesiveLaw(double f_t_Pa, double G_f_J_m2, double alpha_t, double beta_t)
    : f_t_(f_t_Pa), alpha_t_(alpha_t), beta_t_(beta_t), w_max_(2 * G_f_J_m2 / (f_t_Pa * (alpha_t + beta_t))) {
  require_positive("bilinear cohesive law: f_t_Pa", f_t_Pa);
  require_positive("bilinear cohesive law: G_f_J_m2", G_f_J_m2);
  if (!(alpha_t > 0 && alpha_t < 1)) throw InputError("bilinear cohesive law: alpha_t (" + format_number(alpha_t) + ") must be in (0, 1)");
  if (!(beta_t > 0 && beta_t < 1)) throw InputError("bilinear cohesive law: beta_t (" + format_number(beta_t) + ") must be in (0, 1)");
}

double BilinearCohesiveLaw::traction_Pa(double w_m) const {
  const double w = std::max(w_m, 0.0);
  if (w >= w_max_) return 0;
  if (w < alpha_t_ * w_max_) return (beta_t_ - 1) * f_t_ / (alpha_t_ * w_max_) * w + f_t_;  // Eq. (21), first branch
  return -beta_t_ * f_t_ / (w_max_ * (1 - alpha_t_)) * w + beta_t_ * f_t_ / (1 - alpha_t_);  // second branch
}

double BilinearCohesiveLaw::tangent_Pa_per_m(double w_m) const {
  const double w = std::max(w_m, 0.0);
  if (w >= w_max_) return 0;
  if (w < alpha_t_ * w_max_) return (beta_t_ - 1) * f_t_ / (alpha_t_ * w_max_);
  return -beta_t_ * f_t_ / (w_max_ * (1 - alpha_t_));
}

// ---- history ----

CohesiveResponse cohesive_response(const CohesiveLaw& law, double w_m, double w_hist_m, double w_initial_m) {
  const double w_hist = std::max(w_hist_m, w_initial_m);
  CohesiveResponse r;
  if (w_m < 0) {  // faces pressed together: the penalty against interpenetration
    r.tangent_Pa_per_m = law.f_t_Pa() / w_initial_m;
    r.traction_Pa = r.tangent_Pa_per_m * w_m;
    return r;
  }
  if (w_m >= w_hist) {
    r.traction_Pa = law.traction_Pa(w_m);
    r.tangent_Pa_per_m = law.tangent_Pa_per_m(w_m);
    r.loading = true;
    return r;
  }
  r.tangent_Pa_per_m = law.traction_Pa(w_hist) / w_hist;
  r.traction_Pa = r.tangent_Pa_per_m * w_m;
  return r;
}

double cohesive_dissipated_J_m2(const CohesiveLaw& law, double w_hist_m, double w_initial_m) {
  const double wh = std::min(w_hist_m, law.w_max_m());
  if (wh <= w_initial_m) return 0;
  // Gauss-Legendre 8 on [-1, 1] (tabulated: this file does not reach efg/discretisation's generator)
  static const double x[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290, -0.1834346424956498,
                              0.1834346424956498,  0.5255324099163290,  0.7966664774136267,  0.9602898564975363};
  static const double w[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.3626837833783620,
                              0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
  double area = 0.5 * law.traction_Pa(w_initial_m) * w_initial_m;
  const int pieces = 16;
  const double h = (wh - w_initial_m) / pieces;
  for (int i = 0; i < pieces; ++i)
    for (int q = 0; q < 8; ++q) area += 0.5 * h * w[q] * law.traction_Pa(w_initial_m + h * (i + 0.5 * (1 + x[q])));
  return area - 0.5 * law.traction_Pa(wh) * wh;
}

}  // namespace mesowave::efg
