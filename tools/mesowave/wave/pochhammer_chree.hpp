#pragma once
// Longitudinal guided modes L(0,n) of a free solid isotropic rod: the
// Pochhammer-Chree frequency equation (rod paper Eq. (1), Rose 2014):
//
//   (2 alpha / a)(beta^2 + k^2) J1(alpha a) J1(beta a) - (beta^2 - k^2)^2 J0(alpha a) J1(beta a)
//       - 4 k^2 alpha beta J1(alpha a) J0(beta a) = 0,
//   alpha^2 = omega^2 / cP^2 - k^2,   beta^2 = omega^2 / cS^2 - k^2            (Eqs. (2)-(3))
//
// a the rod radius. As implemented the equation is divided by beta and written
// in x = k a, Omega = omega a / cS, p = (alpha a)^2, q = (beta a)^2:
//
//   D(x, Omega) = 2 (q + x^2) A1(p) C1(q) - (q - x^2)^2 A0(p) C1(q) - 4 x^2 A1(p) A0(q) = 0
//
// with A0(p) = J0(sqrt p), A1(p) = sqrt(p) J1(sqrt p), C1(p) = J1(sqrt p) / sqrt(p). These are
// entire functions of p, real for both signs: for p = -s^2 < 0 (alpha or beta imaginary)
// A0 = I0(s), A1 = -s I1(s), C1 = I1(s) / s. So D is real and smooth over the whole (k, omega)
// plane, with no spurious root from the division. D(x, 0) = 0 identically (double root at
// omega = 0), which the root search steps over.
//
// Group velocity from the implicit-function theorem: c_g = d omega / dk = -F_k / F_omega
// = cS dOmega/dx = -cS D_x / D_Omega, with the partial derivatives in closed form
// (A0' = -C1/2, A1' = A0/2, C1' = -C2/2, C2(p) = J2(sqrt p) / p).
//
// At k = 0 the equation factors: q C1(q) [2 A1(p) - q A0(p)] = 0, i.e. the cut-off
// frequencies are the roots of J1(omega a / cS) = 0 and of 2 J1(y) = kappa^2 y J0(y) with
// y = omega a / cP, kappa = cP / cS.
#include <optional>
#include <string>
#include <vector>

#include "mesowave/wave/elastic.hpp"

namespace mesowave::wave {

class PochhammerChree {
public:
  /// InputError for a bad material or a radius that is not positive.
  PochhammerChree(const IsotropicMaterial& material, double radius_m);

  const IsotropicMaterial& material() const { return material_; }
  const WaveSpeeds& speeds() const { return speeds_; }
  double radius_m() const { return a_; }
  double kappa() const { return kappa_; }  ///< cP / cS

  // Dimensionless variables: x = k a, Omega = omega a / cS.
  double x_of(double k) const { return k * a_; }
  double Omega_of(double omega) const { return omega * a_ / speeds_.cS; }
  double k_of(double x) const { return x / a_; }
  double omega_of(double Omega) const { return Omega * speeds_.cS / a_; }

  /// D and its partial derivatives. All three carry the same positive factor
  /// exp(-s_alpha - s_beta) (s = |alpha a| or |beta a| where imaginary) so that
  /// nothing overflows; signs, roots and the ratio D_x / D_Omega are unaffected.
  struct Value {
    double D = 0, D_x = 0, D_Omega = 0;
    double magnitude = 0;  ///< sum of the three terms' magnitudes (same factor): scale for residuals
  };
  Value evaluate(double x, double Omega) const;
  double D(double x, double Omega) const { return evaluate(x, Omega).D; }

  /// |D| over the sum of its terms' magnitudes at (k, omega): about 1e-16 on a root.
  double relative_residual(double k_rad_m, double omega_rad_s) const;
  /// c_g = -F_k / F_omega at (k, omega) [m/s] (meaningful on a root).
  double group_velocity(double k_rad_m, double omega_rad_s) const;

  enum class CutoffFamily { Shear, Dilatational };
  struct Cutoff {
    double omega_rad_s;
    CutoffFamily family;  ///< Shear: J1(omega a / cS) = 0; Dilatational: 2 J1(y) = kappa^2 y J0(y)
  };
  /// k = 0 cut-offs in (0, omega_max], ascending (closed form: roots of the two factors).
  std::vector<Cutoff> cutoffs(double omega_max_rad_s) const;

  /// Every root omega in (0, omega_max] at wavenumber k > 0, ascending: a scan
  /// in steps of `scan_step` (in Omega) with sign-change brackets, plus a check of
  /// every interval where dD/dOmega changes sign (two close roots without a sign
  /// change between the grid points), each refined by Brent's method.
  std::vector<double> frequencies(double k_rad_m, double omega_max_rad_s, double scan_step = 0.01) const;
  /// Same in the dimensionless variables.
  std::vector<double> roots_in_Omega(double x, double Omega_max, double scan_step) const;

private:
  IsotropicMaterial material_;
  WaveSpeeds speeds_;
  double a_, kappa_;
};

/// One point of a dispersion curve.
struct DispersionPoint {
  int mode = 0;       ///< n of L(0,n), 1-based
  int branch = 0;     ///< 0, 1, ... along the mode from k = 0; a new branch starts at each zero-group-velocity point
  double f_Hz = 0;         ///< omega / (2 pi), kept as given when sampled at a frequency
  double omega_rad_s = 0;
  double k_rad_m = 0;
  double c_phase_m_s = 0;  ///< omega / k (infinite at a cut-off: such points have k = 0 and are not sampled)
  double c_group_m_s = 0;  ///< d omega / dk, negative on a backward-wave branch
};

/// A mode traced in wavenumber from its cut-off: points in increasing k,
/// zero-group-velocity points included exactly. A mode that leaves the traced
/// band through its top and comes back has one ModeCurve per continuous piece.
struct ModeCurve {
  int mode = 0;
  std::vector<DispersionPoint> points;
  std::vector<double> zgv_k_rad_m;  ///< where the group velocity changes sign (branch boundaries)
};

struct TraceOptions {
  double f_max_Hz = 0;
  double ka_step = 0.01;     ///< nominal step in k a (halved where the continuation check asks)
  double scan_step = 0.01;   ///< root-scan step in Omega = omega a / cS
  double margin = 0.2;       ///< scan up to (1 + margin) f_max so modes leaving/entering at the top are seen
};

struct DispersionTrace {
  std::vector<ModeCurve> modes;
  int step_refinements = 0;  ///< how often the continuation check halved the k step
  int unresolved_steps = 0;  ///< steps accepted at the smallest k step without passing the check (0 expected)
};

/// Traces every L(0,n) with a point below f_max: roots in omega at each k on a
/// k grid (the n-th root at fixed k is L(0,n); the curves do not cross), each
/// step checked against the prediction omega + h d omega/dk from the previous
/// step (count and position, roots allowed to leave or enter only through the
/// top of the scan); the step is halved until the check passes. Tracking in k
/// keeps both branches of a backward-wave mode (two k per omega between its
/// zero-group-velocity point and its cut-off).
DispersionTrace trace_longitudinal_modes(const PochhammerChree& pc, const TraceOptions& options);

/// Every branch of every traced mode at each frequency in `f_Hz` (k > 0 only):
/// the branch crossing is located on the traced curve and refined by Brent's
/// method in k at fixed omega. Sorted by mode, branch, frequency.
std::vector<DispersionPoint> sample_at_frequencies(const PochhammerChree& pc, const DispersionTrace& trace,
                                                   const std::vector<double>& f_Hz);

/// The L(0,1) group-velocity minimum, where a pulse's Airy phase travels (Graff 1975, 8.2):
/// the traced curve's lowest interior point brackets it between its two neighbours, and
/// golden-section search in x = k a refines it there, the L(0,1) root Omega(x) solved by
/// Brent's method at each trial x and c_g = -cS D_x / D_Omega taken at the root. The
/// trace's own grid (ka step 0.01) places it only to the step; refined, c_g is the minimum
/// to rounding and k a to ~1e-8. nullopt when the traced L(0,1) has no interior minimum
/// (f_max below it).
struct GroupVelocityMinimum {
  double k_rad_m = 0, omega_rad_s = 0, f_Hz = 0, c_group_m_s = 0;
};
std::optional<GroupVelocityMinimum> l01_group_velocity_minimum(const PochhammerChree& pc, const DispersionTrace& trace);

/// "L(0,2)".
std::string mode_name(int mode);

}  // namespace mesowave::wave
