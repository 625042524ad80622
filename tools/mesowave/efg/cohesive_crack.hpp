#pragma once
// The cohesive crack in the EFG model (the paper's Sections 3.1 and 4.1): the
// crack polyline cuts the MLS weights (efg/crack.hpp), so the displacement
// jumps across it, and on its cohesive segments the faces carry the normal
// traction of a cohesive law (efg/cohesive_law.hpp) as a function of the
// opening w = [u] . n. A notch is the same polyline without cohesion
// (traction-free segments).
//
// Each cohesive segment has `gauss` Gauss-Legendre points; at each the jump is
// u^h(x + eps n) - u^h(x - eps n), the MLS displacement evaluated just off the
// line on each face (eps = 1e-6 of the nodal spacing: a point ON the line is
// hidden from both sides). Its work sum t_n [u].n t w gives the internal force
// f_c = sum (N+ - N-)^T n t_n t w and the tangent K_c = sum (N+ - N-)^T n k n^T
// (N+ - N-) t w (t the thickness, w the Gauss weight times the segment length,
// k the law's tangent or secant: cohesive_response). Only the normal component
// carries traction: the sliding of the faces is free (the paper's model is
// mode I, and the beam's crack runs on its symmetry line where the sliding is
// zero). Closed faces (w < 0) meet the penalty f_t / w_initial against
// interpenetration (cohesive_law.hpp).
//
// History: each point's largest opening w_hist moves on only in commit(), so the
// nonlinear solver may evaluate trial states freely.
#include <cstdint>
#include <memory>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "mesowave/efg/cohesive_law.hpp"
#include "mesowave/efg/constraints.hpp"
#include "mesowave/efg/elastic_model.hpp"
#include "mesowave/efg/mls.hpp"
#include "mesowave/efg/nonlinear_solver.hpp"

namespace mesowave::efg {

/// One Gauss point on a cohesive segment.
struct CohesivePoint {
  Vec2 x, normal;           ///< on the line; unit normal (the + face is x + eps normal)
  double length_weight_m;   ///< Gauss weight times segment length
  ShapeFunctions plus, minus;
  double w_hist_m = 0;      ///< largest opening reached (committed)
  std::size_t segment = 0;
};

/// What a cohesive point carries at a displacement (ParaView's crack cell data, efg/vtk_output.hpp).
struct CohesivePointState {
  double opening_m = 0;    ///< normal opening w = [u] . n (< 0: the faces pressed together)
  double traction_Pa = 0;  ///< the normal traction of cohesive_response at w with the committed history
  /// 1 - sigma_env(max(w_hist, w)) / f_t: the share of the strength lost (0 on the initial secant, 1 once
  /// traction-free: w_hist >= w_max).
  double damage = 0;
};

class CohesiveInterface {
public:
  /// `law` is shared by every point; `w_initial_m` the initial opening (cohesive_law.hpp).
  CohesiveInterface(const MlsApproximation& mls, std::shared_ptr<const CohesiveLaw> law, double thickness_m,
                    double face_offset_m, int gauss = 4);
  /// A cohesive segment a-b (its points' shape functions are evaluated at once).
  void add_segment(const Segment& s);
  /// Shape functions of every point again (after the cracks changed: CrackSet::version).
  void update_shape_functions();
  /// Adds f_c(u) to `force` and, when `triplets` is not null, K_c to them (full dof numbering).
  void assemble(const Eigen::VectorXd& u, Eigen::VectorXd& force, std::vector<Eigen::Triplet<double>>* triplets) const;
  /// Normal opening at point p.
  double opening_m(std::size_t p, const Eigen::VectorXd& u) const;
  /// Every point's state at u, in points() order.
  std::vector<CohesivePointState> point_states(const Eigen::VectorXd& u) const;
  /// The history moves on: w_hist = max(w_hist, w).
  void commit(const Eigen::VectorXd& u);
  /// Energy dissipated so far [J]: sum over points of the area under the envelope up to w_hist, minus the
  /// elastic part still stored on the secant, times t w (quadrature on the law).
  double dissipated_energy_J() const;
  /// Energy stored in the faces' secants and penalties at u [J]: sum 1/2 sigma w t w (both branches are linear
  /// through the origin).
  double stored_energy_J(const Eigen::VectorXd& u) const;

  const std::vector<CohesivePoint>& points() const { return points_; }
  const std::vector<Segment>& segments() const { return segments_; }
  const CohesiveLaw& law() const { return *law_; }
  double w_initial_m() const { return w_initial_; }

private:
  const MlsApproximation* mls_;
  std::shared_ptr<const CohesiveLaw> law_;
  double thickness_, offset_, w_initial_;
  int gauss_;
  std::vector<Segment> segments_;
  std::vector<CohesivePoint> points_;
  void evaluate_point(CohesivePoint& p) const;
};

/// The EFG model with cohesive cracks under displacement control as a NonlinearProblem: unknowns v (the
/// constraint set's reduced unknowns), lambda the factor on every constraint's value, u = T v + g(lambda),
/// r(v, lambda) = T^T (K u + f_c(u) - f_ext) with f_ext = 0 (every load is a prescribed displacement).
class CohesiveCrackProblem : public NonlinearProblem {
public:
  CohesiveCrackProblem(ElasticModel& model, const ConstraintSet& constraints, CohesiveInterface& interface);
  std::size_t size() const override { return constraints_->reduced_size(); }
  void evaluate(const Eigen::VectorXd& v, double lambda, Eigen::VectorXd& residual, Eigen::SparseMatrix<double>* tangent,
                Eigen::VectorXd* load_derivative) override;
  void commit(const Eigen::VectorXd& v, double lambda) override;
  /// No opening may change by more than a quarter of w_max in one Newton iteration.
  double step_limit(const Eigen::VectorXd& v, const Eigen::VectorXd& dv, double lambda) override;
  /// After the cracks changed: shape functions of the model and the interface, and K again.
  void update();
  /// Full internal force f_int(u) = K u + f_c(u) (its reactions are the constraint forces).
  Eigen::VectorXd internal_force(const Eigen::VectorXd& u) const;
  /// Elastic energy at u [J]: 1/2 u^T K u in the continuum plus the faces' (stored_energy_J).
  double stored_energy_J(const Eigen::VectorXd& u) const;

private:
  ElasticModel* model_;
  const ConstraintSet* constraints_;
  CohesiveInterface* interface_;
  Eigen::SparseMatrix<double> K_;  ///< elastic stiffness (full), rebuilt by update()
  Eigen::SparseMatrix<double> K_reduced_;
};

}  // namespace mesowave::efg
