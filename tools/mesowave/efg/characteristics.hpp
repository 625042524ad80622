#pragma once
// The method-of-characteristics reference for shock formation (issue 16, must-show 1; shock paper
// Section 4.2): where and when a pressure pulse on the end of a bar steepens into a shock, for a
// stress-strain law whose tangent stiffens with compression, and the speed of the shock from the
// jump condition.
//
// Set-up. A semi-infinite bar x >= 0 in uniaxial strain (a plane-strain strip held laterally, or a
// 1D bar with the constrained modulus), at rest, density rho; compression s = -du/dx >= 0 and the
// compressive stress p = f(s), f' > 0 (CompressionLaw). The end x = 0 carries the pressure p(t)
// (TriangularPulse). The equations rho dv/dt = -dp/dx, ds/dt = -dv/dx are hyperbolic with the
// speeds +-c(s), c = sqrt(f'(s) / rho), and the Riemann invariants v -+ integral of c ds. The
// pulse is the explicit solver's TriangularPulse (efg/pressure_load: peak, rise, fall, start);
// here with peak > 0 and rise > 0 (a rise of 0 is a shock from the start: no formation to find).
//
// Simple wave. Into material at rest, s is constant along each C+ characteristic, so each is the
// straight line x = c(tau) (t - tau) leaving the end at the time tau with s(tau) = f^-1(p(tau)).
// Neighbouring lines tau and tau + dtau meet where d x / d tau = dc/dtau (t - tau) - c = 0, i.e.
//     t - tau = T(tau) = c / (dc/dtau) = 2 f'(s)^2 / (f''(s) dp/dtau)
// (dc/dtau = c_s ds/dtau, c_s = f'' / (2 rho c), ds/dtau = (dp/dtau) / f'). As long as dx/dtau < 0
// for every tau the map tau -> x is one-to-one and no two characteristics - neighbours or not -
// have crossed; it first fails at
//     t_b = min over tau with f'' dp/dtau > 0 of [tau + T(tau)],   x_b = c(tau_b) T(tau_b),
// the time and place where the shock forms (the cusp of the envelope). Levels with f'' dp/dtau <= 0
// fan out. (The smallest x = c T over tau is another number where T varies: the shock forms first
// in TIME at t_b.) shock_formation() evaluates this; traced_first_crossing() is the second method:
// it emits n characteristics, intersects them pairwise, and takes the earliest crossing.
//
// Closed form: p = M s (1 + beta s) (QuadraticStiffening) and a linear rise dp/dtau = p_max / t_r:
// f' = M (1 + 2 beta s), f'' = 2 beta M, T = M (1 + 2 beta s)^2 / (beta dp/dtau) grows with s, so
// the front (tau = 0, s = 0) breaks first:
//     t_b = M t_r / (beta p_max),   x_b = c_0 t_b,   c_0 = sqrt(M / rho);
// the fall (dp/dtau < 0) fans out. A linear law (f'' = 0) never forms a shock.
//
// Jump condition. A shock between the states s_a (ahead) and s_b (behind) moves at U with
// rho U^2 = [p] / [s] (mass and momentum across it): U = c_0 for a linear law,
// U^2 = (M / rho) (1 + beta (s_a + s_b)) for the quadratic one.
//
// The paper's Y-function (HugoniotCompression, p = M P(s), f' = M Y, f'' = M dY/ds, hugoniot.hpp):
// - s <= e_v,th: f'' = 0, an elastic precursor of amplitude M e_v,th running at c_0 unchanged;
// - the kink at e_v,th makes f'' jump from 0 to -M a_v / e_v: a jump of dc/ds, not of c (c is
//   continuous, Y = 1 there). Characteristics would cross at once only if c jumped UP at the kink;
//   Eq. (25) falls first, so the levels just past the threshold travel slower and fan out while the
//   pressure rises: a slower plastic wave spreading behind the elastic precursor;
// - past the minimum of Y (|eps_v| = 0.0475 at Eq. (26)) f'' > 0: the rising part steepens (and its
//   levels above |eps_v| = 0.114, with Y > 1, outrun the precursor); the shock forms there, at the
//   t_b above, only when the pulse's peak compression passes the minimum of Y;
// - on the fall, the dip levels (f'' < 0, dp/dtau < 0) converge: an unloading shock of the
//   nonlinear elastic law (HugoniotParameters::unloading = false), which Eq. (27)'s straight
//   unloading does not have. shock_formation() reports which came first (ShockFormation::loading).
#include "mesowave/efg/hugoniot.hpp"
#include "mesowave/efg/pressure_load.hpp"  // TriangularPulse, the solver's own load

namespace mesowave::efg {

/// A compressive stress-strain law of uniaxial strain: p = f(s) [Pa] for the compression s >= 0.
class CompressionLaw {
 public:
  virtual ~CompressionLaw() = default;
  virtual double pressure_Pa(double s) const = 0;   ///< f(s)
  virtual double tangent_Pa(double s) const = 0;    ///< f'(s) > 0
  virtual double curvature_Pa(double s) const = 0;  ///< f''(s)
};

/// p = M s.
class LinearCompression final : public CompressionLaw {
 public:
  explicit LinearCompression(double M_Pa);
  double pressure_Pa(double s) const override { return M_ * s; }
  double tangent_Pa(double) const override { return M_; }
  double curvature_Pa(double) const override { return 0; }

 private:
  double M_;
};

/// p = M s (1 + beta s): the smooth stiffening law of the clean analytic check.
class QuadraticStiffening final : public CompressionLaw {
 public:
  QuadraticStiffening(double M_Pa, double beta);
  double pressure_Pa(double s) const override { return M_ * s * (1 + beta_ * s); }
  double tangent_Pa(double s) const override { return M_ * (1 + 2 * beta_ * s); }
  double curvature_Pa(double) const override { return 2 * beta_ * M_; }

 private:
  double M_, beta_;
};

/// The quadratic law as a point material of the explicit solver, for the strip: d sigma = g D d eps
/// with g = 1 + 2 beta max(0, -eps_v), Y-function style (all of D scaled, the increment's mean of g),
/// so that uniaxial strain gives exactly -sigma_xx = QuadraticStiffening(D_11, beta).pressure_Pa(s).
/// Nonlinear elastic (no unloading rule); modulus_scale = g.
class QuadraticStiffeningPoint final : public PointMaterial {
 public:
  QuadraticStiffeningPoint(const ElasticMaterial2D& material, double beta);
  Eigen::Vector3d update(const Eigen::Vector3d& strain, PointState& state) const override;

 private:
  ElasticMaterial2D material_;
  double beta_;
  Eigen::Matrix3d D_;
};

/// p = M P(s), the Y-function of Eqs. (24)-(26) under uniaxial strain (eps_v = -s), loading branch
/// both ways (no Eq. (27)): what HugoniotElastic gives a plane-strain point held laterally.
class HugoniotCompression final : public CompressionLaw {
 public:
  HugoniotCompression(double M_Pa, const HugoniotParameters& parameters);
  double pressure_Pa(double s) const override;
  double tangent_Pa(double s) const override;
  double curvature_Pa(double s) const override;

 private:
  double M_;
  HugoniotParameters p_;
};

/// c(s) = sqrt(f'(s) / rho).
double wave_speed_m_s(const CompressionLaw& law, double density_kg_m3, double s);
/// f^-1(p) for p >= 0 (bisection on f alone, to 1e-15 relative).
double compression_at_pressure(const CompressionLaw& law, double p_Pa);

struct ShockFormation {
  bool forms = false;         ///< false: no two characteristics cross (a linear law, or no f'' dp > 0)
  double time_s = 0;          ///< t_b
  double distance_m = 0;      ///< x_b
  double emitted_at_s = 0;    ///< tau_b, when the breaking characteristic left the end
  double compression = 0;     ///< s(tau_b), the level that breaks first
  double wave_speed_m_s = 0;  ///< c(s(tau_b))
  bool loading = true;        ///< tau_b on the pulse's rise (else on its fall)
};

/// t_b and x_b from the envelope formula above: T(tau) on `samples` points of the rise and of the
/// fall each, the smallest refined by golden-section search between its neighbours. InputError:
/// the pulse invalid (TriangularPulse::validate), its peak or rise not positive.
ShockFormation shock_formation(const CompressionLaw& law, double density_kg_m3, const TriangularPulse& pulse,
                               int samples = 20000);

/// The second method: `count` + 1 characteristics emitted at tau_i = start + duration i / count, each
/// traced as its straight line, the earliest crossing of consecutive ones (`all_pairs`: of any
/// two, O(count^2)). Its error is of the order of the spacing duration / count.
ShockFormation traced_first_crossing(const CompressionLaw& law, double density_kg_m3, const TriangularPulse& pulse,
                                     int count, bool all_pairs = false);

/// U = sqrt([p] / (rho [s])) between s_ahead and s_behind (s_behind != s_ahead), the jump condition.
double shock_speed_m_s(const CompressionLaw& law, double density_kg_m3, double s_ahead, double s_behind);

}  // namespace mesowave::efg
