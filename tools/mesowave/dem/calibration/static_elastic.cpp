#include "mesowave/dem/calibration/static_elastic.hpp"

#include <Eigen/IterativeLinearSolvers>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/dem/calibration/boomeramg.hpp"
#include "mesowave/dem/contact/linear_bonded_network.hpp"
#include "mesowave/dem/engine/simulation.hpp"
#include "mesowave/dem/engine/sphere_system.hpp"
#include "mesowave/dem/loading/rigid_wall.hpp"

namespace mesowave::dem {
namespace {

using Matrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;
using Vector = Eigen::VectorXd;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// Each preconditioner StaticElasticOptions knows, with the solver's name in the results.
constexpr std::pair<const char*, const char*> kPreconditioners[] = {
    {"jacobi", "BiCGSTAB (Jacobi)"}, {"ilut", "BiCGSTAB (ILUT)"}, {"amg", "BiCGSTAB (BoomerAMG)"}};

// The solver's name for a preconditioner; InputError for an unknown one.
std::string bicgstab_name(const std::string& preconditioner) {
  std::string known;
  for (const auto& [name, solver] : kPreconditioners) {
    if (preconditioner == name) return solver;
    known += (known.empty() ? "" : ", ") + std::string(name);
  }
  throw InputError("static solve: preconditioner \"" + preconditioner + "\" is none of " + known);
}

// The model as the sensors see it, with the static solution as its displacement
// field (rotations are not read by any sensor of a test).
class StaticField final : public Model {
public:
  StaticField(const Model& base, const Vector& u) : base_(base), u_(u) {}
  std::string name() const override { return "static"; }
  std::size_t sphere_count() const override { return base_.sphere_count(); }
  std::size_t bond_count() const override { return base_.bond_count(); }
  std::size_t degrees_of_freedom() const override { return base_.degrees_of_freedom(); }
  Vec3 reference_position(std::size_t k) const override { return base_.reference_position(k); }
  double radius(std::size_t k) const override { return base_.radius(k); }
  double mass(std::size_t k) const override { return base_.mass(k); }
  std::uint32_t packing_index(std::size_t k) const override { return base_.packing_index(k); }
  Vec3 displacement(std::size_t k) const override { return {u_[6 * k], u_[6 * k + 1], u_[6 * k + 2]}; }
  Vec3 velocity(std::size_t) const override { return {}; }
  Vec3 acceleration(std::size_t) const override { return {}; }
  void add_external_force(std::size_t, const Vec3&) override { unused(); }
  double impose_displacement(std::size_t, const Vec3&, double, double, double) override { unused(); }
  void set_velocity(std::size_t, const Vec3&) override { unused(); }
  void step(double, bool) override { unused(); }
  EnergyAccount energy() const override { return {}; }
  double peak_force_ratio() const override { return 0; }
  bool has_non_finite_state() const override { return !u_.allFinite(); }
  void scaled_stiffness_action(const double* x, double* y) const override { base_.scaled_stiffness_action(x, y); }
  double scaled_stiffness_row_sum_bound() const override { return base_.scaled_stiffness_row_sum_bound(); }
  std::size_t memory_bytes() const override { return 0; }
  int threads() const override { return 1; }
  void save_state(StateGroup&) const override { unused(); }
  void load_state(const StateGroup&) override { unused(); }

private:
  [[noreturn]] static void unused() { throw std::logic_error("StaticField is read-only: sensors only sample it"); }
  const Model& base_;
  const Vector& u_;
};

// One wall of the test: its candidate spheres and which load sensors read it.
struct Wall {
  const RigidWall* wall;
  double travel_per_delta;  // its travel per unit travel of the fastest wall
  bool load;                // read by a load sensor
};

}  // namespace

std::vector<std::string> static_preconditioners() {
  std::vector<std::string> names;
  for (const auto& entry : kPreconditioners) names.emplace_back(entry.first);
  return names;
}

Matrix linear_network_stiffness(const SphereSystem& system) {
  const CohesiveFrictionalMaterial& m = system.material();
  const double two_E_dem = 2.0 * m.E_dem_Pa, ratio = m.stiffness_ratio;
  const auto& radius = system.held_spheres().radius_m;
  const auto n = Eigen::Index(6 * system.sphere_count());
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(system.bond_count() * 144);
  for (std::size_t b = 0; b < system.bond_count(); ++b) {
    const std::uint32_t i = system.bond_first(b), j = system.bond_second(b);
    const BondGeometry g0 = system.bond_geometry0(b);
    const std::size_t dof[2] = {6 * std::size_t(i), 6 * std::size_t(j)};
    for (int col = 0; col < 12; ++col) {
      // Unit value of DOF `col` of the pair (d_i, theta_i, d_j, theta_j).
      Vec3 d_i{}, t_i{}, d_j{}, t_j{};
      Vec3& unit = col < 3 ? d_i : col < 6 ? t_i : col < 9 ? d_j : t_j;
      unit[col % 3] = 1.0;
      const LinearBondResponse r =
          linear_bond_response(two_E_dem, ratio, radius[i], radius[j], g0.overlap_m, g0.normal,
                               d_j - d_i, t_i, t_j);
      // Generalized forces: -f, -arm_i c on i; f, -arm_j c on j (for_each_contact). K = -d(force)/du.
      const Vec3 g[4] = {-1.0 * r.f, -r.arm_i * r.c, r.f, -r.arm_j * r.c};
      const std::size_t c = dof[col / 6] + std::size_t(col % 6);
      for (int block = 0; block < 4; ++block)
        for (int a = 0; a < 3; ++a) {
          const double v = -g[block][a];
          if (v != 0) entries.emplace_back(int(dof[block / 2] + 3 * (block % 2) + a), int(c), v);
        }
    }
  }
  Matrix K(n, n);
  K.setFromTriplets(entries.begin(), entries.end());
  return K;
}

StaticElasticResult static_compression_test(const Scene& scene_in, const Packing& packing,
                                            const StaticElasticOptions& options_in) {
  const StaticElasticOptions& options = options_in;
  const std::string solver_name = bicgstab_name(options.preconditioner);
  const auto start = Clock::now();
  const UniaxialTestSpec& spec = scene_in.test;
  if (spec.kind != UniaxialTestSpec::Kind::compression)
    throw InputError("a static test needs a scene with a compression [test]");
  if (!spec.levels_absolute)
    throw InputError("a static test needs its modulus levels as stresses (--modulus-levels-MPa or [test] "
                     "modulus_levels_MPa): a linear response has no peak to take " +
                     format_number(spec.levels[0] * 100) + " and " + format_number(spec.levels[1] * 100) + " % of");
  SimulationOptions sim_options;
  sim_options.model = "linear";
  sim_options.refuse_unstable_dt = false;  // nothing is stepped
  Simulation sim(scene_in, packing, sim_options);
  const Scene& scene = sim.scene();
  auto* system = dynamic_cast<SphereSystem*>(&sim.model());
  if (!system || system->name() != "linear")
    throw InputError("a static test needs the linearised bonded network; the scene's law gives " + sim.model().name());

  StaticElasticResult result;
  result.spheres = system->sphere_count();
  result.bonds = system->bond_count();
  result.dofs = system->degrees_of_freedom();
  result.solver = solver_name;
  result.setup_s = seconds_since(start);

  // The walls: which move (their travel in proportion to their speeds) and which the load sensors read.
  std::vector<std::string> load_walls;
  for (const auto& name : spec.load)
    for (const auto& s : scene.sensors)
      if (s.name == name) load_walls.push_back(s.actuator);
  std::vector<Wall> walls;
  double v_max = 0;
  for (const auto& a : sim.actuators()) {
    const auto* w = dynamic_cast<const RigidWall*>(a.get());
    if (!w) throw InputError("a static test loads through walls only; actuator " + a->name() + " is not a wall");
    v_max = std::max(v_max, w->motion().velocity_m_s);
    walls.push_back({w, 0, std::find(load_walls.begin(), load_walls.end(), w->name()) != load_walls.end()});
  }
  if (!(v_max > 0)) throw InputError("a static test needs a wall that moves (velocity_mm_s > 0)");
  for (auto& w : walls) w.travel_per_delta = w.wall->motion().velocity_m_s / v_max;
  if (std::none_of(walls.begin(), walls.end(), [](const Wall& w) { return w.load; }))
    throw InputError("[test] load: none of its sensors reads a wall's force");
  const double area = sim.test_specimen()->area_m2;

  // K, and the three supports of the rigid motions across the load axis.
  auto t = Clock::now();
  const Matrix K = linear_network_stiffness(*system);
  result.assemble_s = seconds_since(t);
  const int axis = walls.front().wall->face().axis, p = (axis + 1) % 3, q = (axis + 2) % 3;
  for (const auto& w : walls)
    if (w.wall->face().axis != axis) throw InputError("a static test needs its walls on one axis");
  Vec3 lo = system->reference_position(0), hi = lo;
  for (std::size_t k = 0; k < system->sphere_count(); ++k)
    for (int c = 0; c < 3; ++c) {
      lo[c] = std::min(lo[c], system->reference_position(k)[c]);
      hi[c] = std::max(hi[c], system->reference_position(k)[c]);
    }
  const auto nearest = [&](const Vec3& x) {
    std::size_t best = 0;
    double d2 = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < system->sphere_count(); ++k) {
      const double e = norm2(system->reference_position(k) - x);
      if (e < d2) d2 = e, best = k;
    }
    return best;
  };
  Vec3 centre = 0.5 * (lo + hi), side = centre;
  side[p] = centre[p] + 0.25 * (hi[p] - lo[p]);
  const std::size_t a0 = nearest(centre), b0 = nearest(side);
  std::vector<std::uint8_t> fixed(result.dofs, 0);
  fixed[6 * a0 + p] = fixed[6 * a0 + q] = fixed[6 * b0 + q] = 1;
  // DOFs no bond stiffens (a sphere without bonds): fixed too, and no wall pushes it.
  for (Eigen::Index r = 0; r < K.rows(); ++r)
    if (K.coeff(r, r) == 0) fixed[std::size_t(r)] = 1;

  // The active set: per wall, per candidate, touching or not.
  std::vector<std::vector<std::uint8_t>> active(walls.size());
  for (std::size_t w = 0; w < walls.size(); ++w) active[w].assign(walls[w].wall->spheres().size(), 0);
  const auto dof_of = [&](const Wall& w, std::size_t i) { return 6 * w.wall->spheres()[i] + std::size_t(axis); };

  Vector u = Vector::Zero(Eigen::Index(result.dofs)), u0 = u, u1 = u;
  // The true residual is checked too: BiCGSTAB's recurred one drifts from it.
  const auto solve_with = [&](auto& solver, const Matrix& A, const Vector& rhs, Vector& x) {
    solver.setTolerance(options.tolerance);
    solver.setMaxIterations(options.max_iterations);
    x = solver.solveWithGuess(rhs, x);
    const double residual = rhs.norm() > 0 ? (rhs - A * x).norm() / rhs.norm() : 0;
    if (solver.info() != Eigen::Success || !(residual <= 100 * options.tolerance))
      throw InputError("the static solve did not converge (" + std::to_string(solver.iterations()) +
                       " iterations, relative residual " + format_number(residual) +
                       "): the network with its wall contacts may be a mechanism (spheres or clusters held by no bond)");
    ++result.solves;
    result.iterations_total += int(solver.iterations());
    result.iterations_max = std::max(result.iterations_max, int(solver.iterations()));
    result.residual_max = std::max(result.residual_max, residual);
  };
  // Both right-hand sides with one preconditioner.
  const auto solve = [&](const Matrix& A, const Vector& rhs1, Vector& x1, const Vector& rhs0, Vector& x0) {
    if (options.preconditioner == "ilut" || options.preconditioner == "amg") {
      // Scaled to a unit diagonal first (S A S y = S b, x = S y, S = |diag A|^-1/2): the rows
      // of the rotations (diagonal ~ K_s r^2) and of the translations (~ K_n) then weigh
      // alike in the incomplete factors' drop rule and in AMG's strength of connection.
      Vector scale = A.diagonal().cwiseAbs().cwiseSqrt().cwiseInverse();
      const Matrix scaled = scale.asDiagonal() * A * scale.asDiagonal();
      const auto run = [&](auto& solver) {
        Vector y1 = x1.cwiseQuotient(scale), y0 = x0.cwiseQuotient(scale);
        solve_with(solver, scaled, Vector(scale.cwiseProduct(rhs1)), y1);
        solve_with(solver, scaled, Vector(scale.cwiseProduct(rhs0)), y0);
        x1 = scale.cwiseProduct(y1);
        x0 = scale.cwiseProduct(y0);
      };
      const auto built = Clock::now();
      if (options.preconditioner == "amg") {
        Eigen::BiCGSTAB<Matrix, BoomerAmg> solver;
        solver.preconditioner().set_settings(options.amg);
        solver.compute(scaled);
        result.preconditioner_s += seconds_since(built);  // with MPI's start on the first use
        run(solver);
      } else {
        Eigen::BiCGSTAB<Matrix, Eigen::IncompleteLUT<double>> solver;
        solver.preconditioner().setDroptol(options.ilut_droptol);
        solver.preconditioner().setFillfactor(options.ilut_fill);
        solver.compute(scaled);
        result.preconditioner_s += seconds_since(built);
        run(solver);
      }
    } else {
      Eigen::BiCGSTAB<Matrix, Eigen::DiagonalPreconditioner<double>> solver;
      solver.compute(A);
      solve_with(solver, A, rhs1, x1);
      solve_with(solver, A, rhs0, x0);
    }
  };
  // Wall force per wall at travel delta for the field x: sum of k_w p over its active spheres.
  const auto penetration = [&](std::size_t w, std::size_t i, double delta, const Vector& x) {
    const Wall& wall = walls[w];
    return delta * wall.travel_per_delta - wall.wall->initial_gap_m(i) - wall.wall->inward() * x[Eigen::Index(dof_of(wall, i))];
  };
  const auto load_stress = [&](double delta, const Vector& x, bool with_gaps) {
    double sum = 0;
    int count = 0;
    for (std::size_t w = 0; w < walls.size(); ++w) {
      if (!walls[w].load) continue;
      double f = 0;
      for (std::size_t i = 0; i < active[w].size(); ++i)
        if (active[w][i]) {
          const double pen = with_gaps ? penetration(w, i, delta, x)
                                       : delta * walls[w].travel_per_delta - walls[w].wall->inward() * x[Eigen::Index(dof_of(walls[w], i))];
          f += walls[w].wall->contact_stiffness()[i] * pen;
        }
      sum += f, ++count;
    }
    return sum / double(count) / area;
  };

  // The extensometers of the [test], sampling a field.
  std::vector<Sensor*> axial, lateral;
  for (auto& s : sim.sensors()) {
    if (std::find(spec.axial.begin(), spec.axial.end(), s->name()) != spec.axial.end()) axial.push_back(s.get());
    if (std::find(spec.lateral.begin(), spec.lateral.end(), s->name()) != spec.lateral.end()) lateral.push_back(s.get());
  }
  const auto mean_reading = [&](std::vector<Sensor*>& group, const Model& field) {
    double sum = 0;
    for (Sensor* s : group) {
      s->record(field, 0);
      sum += s->samples().back();
    }
    return group.empty() ? 0.0 : sum / double(group.size());
  };

  // A first guess of who touches: a uniform strain sigma / E_dem over the height.
  const double height = hi[axis] - lo[axis];
  t = Clock::now();
  bool solved = false;  // u1, u0 solve the current active set
  const auto solve_level = [&](double sigma, bool first) {
    StaticLevel level;
    level.sigma_Pa = sigma;
    if (first) {
      const double guess = sigma / scene.material.E_dem_Pa * height;
      for (std::size_t w = 0; w < walls.size(); ++w)
        for (std::size_t i = 0; i < active[w].size(); ++i)
          active[w][i] = !fixed[dof_of(walls[w], i)] && walls[w].wall->initial_gap_m(i) < 0.5 * guess;
      solved = false;
    }
    for (int round = 1;; ++round) {
      if (round > options.max_active_set_rounds)
        throw InputError("the static test's wall contacts did not settle in " + std::to_string(options.max_active_set_rounds) +
                         " active-set rounds at " + format_number(sigma / 1e6) + " MPa");
      // u1, u0 of the last solve hold while the set is the one they were solved for
      // (the second level usually needs no solve: the same walls touch).
      if (!solved) {
        Matrix A = K;
        Vector rhs1 = Vector::Zero(A.rows()), rhs0 = rhs1;
        for (std::size_t w = 0; w < walls.size(); ++w)
          for (std::size_t i = 0; i < active[w].size(); ++i) {
            if (!active[w][i]) continue;
            const auto r = Eigen::Index(dof_of(walls[w], i));
            const double kw = walls[w].wall->contact_stiffness()[i], inward = walls[w].wall->inward();
            A.coeffRef(r, r) += kw;
            rhs1[r] += inward * kw * walls[w].travel_per_delta;
            rhs0[r] -= inward * kw * walls[w].wall->initial_gap_m(i);
          }
        // Fixed DOFs: rows and columns of the identity, zero on the right.
        for (Eigen::Index r = 0; r < A.rows(); ++r)
          for (Matrix::InnerIterator it(A, r); it; ++it)
            if (fixed[std::size_t(it.row())] || fixed[std::size_t(it.col())]) it.valueRef() = it.row() == it.col() ? 1.0 : 0.0;
        for (std::size_t d = 0; d < fixed.size(); ++d)
          if (fixed[d]) rhs0[Eigen::Index(d)] = rhs1[Eigen::Index(d)] = 0;
        solve(A, rhs1, u1, rhs0, u0);
        solved = true;
      }
      // sigma(delta) = delta sigma1 + sigma0 within this set.
      const double s1 = load_stress(1.0, u1, false), s0 = load_stress(0.0, u0, true);
      if (!(s1 > 0)) throw InputError("the static test's walls carry no load: no sphere touches a wall");
      const double delta = (sigma - s0) / s1;
      u = delta * u1 + u0;
      bool changed = false;
      std::size_t touching = 0;
      for (std::size_t w = 0; w < walls.size(); ++w)
        for (std::size_t i = 0; i < active[w].size(); ++i) {
          const std::uint8_t now = !fixed[dof_of(walls[w], i)] && penetration(w, i, delta, u) > 0;
          changed = changed || now != active[w][i];
          solved = solved && now == active[w][i];
          active[w][i] = now;
          touching += now;
        }
      if (!changed) {
        level.travel_m = delta;
        level.wall_contacts = touching;
        level.active_set_rounds = round;
        break;
      }
    }
    const StaticField field(*system, u);
    const double sign = -1.0;  // compression: strains positive in shortening (uniaxial_analysis)
    level.axial_strain = sign * mean_reading(axial, field);
    level.lateral_strain = mean_reading(lateral, field);
    // The supports' reactions: the residual force at the fixed DOFs against the wall force.
    const Vector reaction = K * u;
    double worst = 0;
    for (std::size_t d = 0; d < fixed.size(); ++d)
      if (fixed[d] && K.coeff(Eigen::Index(d), Eigen::Index(d)) != 0) worst = std::max(worst, std::abs(reaction[Eigen::Index(d)]));
    result.support_force_ratio = std::max(result.support_force_ratio, worst / (sigma * area));
    return level;
  };
  result.level_b = solve_level(spec.levels[0], true);
  result.level_a = solve_level(spec.levels[1], false);
  result.solve_s = seconds_since(t);

  const StaticLevel &b = result.level_b, &a = result.level_a;
  if (!(a.axial_strain > b.axial_strain))
    throw InputError("the static test's axial strain does not grow with the stress (" + format_number(b.axial_strain) +
                     " at " + format_number(b.sigma_Pa / 1e6) + " MPa, " + format_number(a.axial_strain) + " at " +
                     format_number(a.sigma_Pa / 1e6) + " MPa)");
  result.E_glob_Pa = (a.sigma_Pa - b.sigma_Pa) / (a.axial_strain - b.axial_strain);
  if (!lateral.empty()) result.nu_glob = (a.lateral_strain - b.lateral_strain) / (a.axial_strain - b.axial_strain);
  result.nonzeros = std::size_t(K.nonZeros());

  UniaxialTestResult& r = result.test;
  r.kind = spec.kind_name();
  r.area_m2 = area;
  r.time_s = {0, 1, 2};
  r.stress_Pa = {0, b.sigma_Pa, a.sigma_Pa};
  r.axial_strain = {0, b.axial_strain, a.axial_strain};
  if (!lateral.empty()) r.lateral_strain = {0, b.lateral_strain, a.lateral_strain};
  r.peak_index = 2;
  r.peak_stress_Pa = a.sigma_Pa;
  r.strain_at_peak = a.axial_strain;
  r.peak_reached = false;  // a linear response has no peak
  r.sigma_b_Pa = b.sigma_Pa, r.sigma_a_Pa = a.sigma_Pa, r.eps_b = b.axial_strain, r.eps_a = a.axial_strain;
  r.E_secant_Pa = result.E_glob_Pa;
  r.nu_secant = result.nu_glob;
  r.notes.push_back("static solve of the linearised network (" + result.solver + "): the stress-strain points are "
                    "the unloaded state and the two levels, t_s is the solve's index");
  result.wall_s = seconds_since(start);
  return result;
}

}  // namespace mesowave::dem
