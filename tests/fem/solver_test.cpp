// The explicit continuum solver (mw-fem): element matrices against exact
// energies, the stable step against the mesh's highest frequency and against
// an actual divergence, a bar against the 1D impedance solution, the
// axisymmetric rod against the 3D rod, the group velocity against
// Pochhammer-Chree theory with its convergence order, and determinism.
#include <gtest/gtest.h>
#include <omp.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstring>
#include <numbers>

#include "mesowave/core/error.hpp"
#include "mesowave/signal/correlation.hpp"
#include "mesowave/signal/fft.hpp"
#include "mesowave/signal/time_of_flight.hpp"
#include "mesowave/fem/case.hpp"
#include "mesowave/fem/element.hpp"
#include "mesowave/fem/solver.hpp"
#include "mesowave/wave/pochhammer_chree.hpp"

using namespace mesowave;
using namespace mesowave::wave;
using namespace mesowave::fem;

namespace {

const IsotropicMaterial steel{208.72e9, 0.3, 7850.66};   // rod paper Section 4.1
const IsotropicMaterial concrete{36.67e9, 0.162, 2129.56};  // cube paper: E_d, nu_d, rho
constexpr double kR = 5.1e-3;

// Eigenvalues of a dense symmetric row-major matrix.
Eigen::VectorXd eigenvalues(const std::vector<double>& K, int n) {
  Eigen::MatrixXd A(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) A(i, j) = K[std::size_t(i * n + j)];
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(A, Eigen::EigenvaluesOnly).eigenvalues();
}

// Strain energy density eps : D : eps / 2 for a symmetric strain (isotropic).
double energy_density(const IsotropicMaterial& m, const Eigen::Matrix3d& eps) {
  return 0.5 * lame_lambda(m) * eps.trace() * eps.trace() + lame_mu(m) * (eps.array() * eps.array()).sum();
}

// Time of the energy centroid sum t x^2 / sum x^2 of a record.
double energy_centroid(const signal::Signal& s) {
  double num = 0, den = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    num += s.time(i) * s.samples[i] * s.samples[i];
    den += s.samples[i] * s.samples[i];
  }
  return num / den;
}

}  // namespace

TEST(FemElement, HexahedronRigidModesPatchTestAndMass) {
  // A distorted hexahedron: isoparametric elements still represent linear fields exactly.
  const std::array<std::array<double, 3>, 8> x{{{0, 0, 0},
                                                {1.1e-3, 0.05e-3, 0},
                                                {1.0e-3, 0.9e-3, 0.1e-3},
                                                {-0.1e-3, 1.0e-3, 0},
                                                {0.05e-3, 0, 1.0e-3},
                                                {1.0e-3, 0.1e-3, 1.1e-3},
                                                {1.05e-3, 1.0e-3, 0.95e-3},
                                                {0, 1.1e-3, 1.0e-3}}};
  const auto K = hex8_stiffness(x, steel);
  const auto ev = eigenvalues(K, 24);
  for (int i = 0; i < 6; ++i) EXPECT_LT(std::abs(ev(i)), 1e-9 * ev(23)) << "rigid mode " << i;
  EXPECT_GT(ev(6), 1e-4 * ev(23));  // full integration: no hourglass (zero-energy) modes
  // Volume from the mass (rho = 1) and the energy of a uniform strain.
  const auto mass = hex8_lumped_mass(x, 1.0);
  double V = 0;
  for (double m : mass) V += m;
  Eigen::Matrix3d grad;
  grad << 1e-4, 2e-5, -3e-5, 0.5e-5, -2e-4, 1e-5, 4e-5, 0, 3e-4;
  Eigen::VectorXd u(24);
  for (int a = 0; a < 8; ++a)
    for (int i = 0; i < 3; ++i) u(3 * a + i) = grad.row(i).dot(Eigen::Vector3d(x[a][0], x[a][1], x[a][2]));
  Eigen::Map<const Eigen::Matrix<double, 24, 24, Eigen::RowMajor>> Km(K.data());
  const Eigen::Matrix3d eps = 0.5 * (grad + grad.transpose());
  EXPECT_NEAR(0.5 * u.dot(Km * u) / (energy_density(steel, eps) * V), 1.0, 1e-12);
  // Volume of this hexahedron by the divergence theorem on its (bilinear) faces is what
  // the Gauss rule integrates exactly; compare with the cube of side ~1 mm roughly and exactly with rho = 2.
  const auto mass2 = hex8_lumped_mass(x, 2.0);
  double M2 = 0;
  for (double m : mass2) M2 += m;
  EXPECT_NEAR(M2 / V, 2.0, 1e-12);
  EXPECT_NEAR(V, 1.1e-9, 0.15e-9);
}

TEST(FemElement, AxisymmetricRingUniformStrainAndMass) {
  const double r1 = 1e-3, r2 = 1.8e-3, dz = 0.7e-3;
  const std::array<std::array<double, 2>, 4> x{{{r1, 0}, {r2, 0}, {r2, dz}, {r1, dz}}};
  const auto K = quad4_axisymmetric_stiffness(x, steel);
  Eigen::Map<const Eigen::Matrix<double, 8, 8, Eigen::RowMajor>> Km(K.data());
  // Rigid axial translation: no force.
  Eigen::VectorXd t(8);
  t << 0, 1, 0, 1, 0, 1, 0, 1;
  EXPECT_LT((Km * t).norm(), 1e-6 * Km.norm());
  // u_r = a r, u_z = b z: eps_rr = eps_tt = a, eps_zz = b, uniform; energy = w V exactly.
  const double a = 1e-4, b = -3e-4;
  Eigen::VectorXd u(8);
  for (int n = 0; n < 4; ++n) {
    u(2 * n) = a * x[std::size_t(n)][0];
    u(2 * n + 1) = b * x[std::size_t(n)][1];
  }
  const double V = std::numbers::pi * (r2 * r2 - r1 * r1) * dz;
  Eigen::Matrix3d eps = Eigen::Vector3d(a, a, b).asDiagonal();
  EXPECT_NEAR(0.5 * u.dot(Km * u) / (energy_density(steel, eps) * V), 1.0, 1e-12);
  const auto m = quad4_axisymmetric_lumped_mass(x, steel.rho_kg_m3);
  EXPECT_NEAR((m[0] + m[1] + m[2] + m[3]) / (steel.rho_kg_m3 * V), 1.0, 1e-12);
}

TEST(FemModel, MassesAreExact) {
  const double L = 20e-3;
  const double V = std::numbers::pi * kR * kR * L;
  EXPECT_NEAR(rod_axisymmetric(steel, kR, L, 1e-3).total_mass() / (steel.rho_kg_m3 * V), 1.0, 1e-12);
  // The O-grid polygon's vertices are placed so that its area is pi R^2.
  EXPECT_NEAR(rod_hexahedra(steel, kR, L, 1e-3).total_mass() / (steel.rho_kg_m3 * V), 1.0, 1e-12);
  EXPECT_NEAR(box_hexahedra(concrete, {5e-3, 6e-3, 7e-3}, 1e-3).total_mass() / (concrete.rho_kg_m3 * 210e-9), 1.0,
              1e-12);
}

TEST(FemModel, StableStepBoundsTheHighestFrequencyTightly) {
  // The bound must not exceed the true stable step 2 / omega_max (power iteration
  // converges to omega_max from below, so 2 / estimate is an upper limit of it only
  // once converged: use many iterations on small meshes), and should be close to it.
  const FemModel models[] = {rod_axisymmetric(steel, kR, 15e-3, 1e-3), rod_hexahedra(steel, kR, 8e-3, 1e-3),
                             box_hexahedra(concrete, {6e-3, 6e-3, 6e-3}, 1e-3),
                             box_hexahedra(concrete, {5e-3, 4e-3, 7e-3}, 1e-3)};
  for (const auto& m : models) {
    const double dt_true = 2 / global_max_omega(m, 4000);
    EXPECT_LE(m.stable_dt(), dt_true * (1 + 1e-6)) << m.description;
    EXPECT_GT(m.stable_dt(), 0.9 * dt_true) << m.description << " (" << m.stable_dt_method << ")";
  }
}

TEST(FemSolver, CentralDifferencesAreStableAtTheBoundAndDivergeAboveTheTrueLimit) {
  const auto model = box_hexahedra(concrete, {4e-3, 4e-3, 8e-3}, 1e-3);
  const auto load = make_load(model, 2, 0.0, {2e-3, 2e-3, 0}, 0.0, 2, 1.0, signal::HannBurst(200e3, 2, 1.0));
  const std::vector<Probe> probes{{"P", model.nearest_node({2e-3, 2e-3, 8e-3}) * 3 + 2, MotionQuantity::velocity, "z"}};
  ExplicitOptions opt;
  opt.steps = 3000;
  opt.dt_s = model.stable_dt();
  const auto stable = run_explicit(model, load, probes, opt);
  // Undamped, after the burst (10 us, ~60 steps): the energy stays bounded.
  EXPECT_LT(stable.final_kinetic_energy_J, 1.01 * stable.max_kinetic_energy_J);
  opt.dt_s = 1.02 * model.stable_dt();
  EXPECT_THROW(run_explicit(model, load, probes, opt), InputError);
  // 3 % above the true limit 2 / omega_max the highest mode grows without bound.
  opt.dt_s = 1.03 * 2 / global_max_omega(model, 4000);
  opt.allow_unstable = true;
  const auto unstable = run_explicit(model, load, probes, opt);
  EXPECT_TRUE(!std::isfinite(unstable.final_kinetic_energy_J) ||
              unstable.final_kinetic_energy_J > 1e6 * stable.max_kinetic_energy_J);
}

TEST(FemSolver, BarPulseFollowsTheOneDimensionalImpedanceSolution) {
  // nu = 0 prism under a uniform end traction: exactly a 1D bar. Particle velocity
  // v(z, t) = F(t - z / c0) / (rho c0 A) until the far-end reflection returns.
  const IsotropicMaterial m{210e9, 0.0, 7800.0};
  const double a = 2e-3, L = 300e-3, z = 100e-3, c0 = std::sqrt(m.E_Pa / m.rho_kg_m3);
  const auto model = box_hexahedra(m, {a, a, L}, 1e-3);
  const signal::HannBurst burst(100e3, 3, 50.0);
  const auto load = make_load(model, 2, 0.0, {a / 2, a / 2, 0}, 1.0, 2, 1.0, burst);
  const std::vector<Probe> probes{{"V", model.nearest_node({a / 2, a / 2, z}) * 3 + 2, MotionQuantity::velocity, "z"}};
  const auto st = choose_stepping(model, 90e-6, 0.1e-6);
  ExplicitOptions opt;
  opt.dt_s = st.dt_s;
  opt.steps = st.steps;
  opt.sample_stride = st.stride;
  const auto res = run_explicit(model, load, probes, opt);
  const auto& v = res.signals[0];
  double peak = 0, err = 0;
  std::size_t i_peak = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const double exact = burst(v.time(i) - z / c0) / (m.rho_kg_m3 * c0 * a * a);
    peak = std::max(peak, std::abs(exact));
    err = std::max(err, std::abs(v.samples[i] - exact));
    if (std::abs(v.samples[i]) > std::abs(v.samples[i_peak])) i_peak = i;
  }
  EXPECT_LT(err / peak, 0.01);
  // The largest excursion of the burst (its 2nd peak for 3 cycles) arrives z / c0 late.
  double t_burst_peak = 0, fmax = 0;
  for (double t = 0; t < burst.duration_s(); t += 1e-9)
    if (std::abs(burst(t)) > fmax) {
      fmax = std::abs(burst(t));
      t_burst_peak = t;
    }
  EXPECT_NEAR(v.time(i_peak), t_burst_peak + z / c0, 0.2e-6);
}

TEST(FemSolver, AxisymmetricAndHexahedralRodsAgree) {
  const double L = 60e-3, h = kR / 4;
  const signal::HannBurst burst(100e3, 5, 1.0);
  std::vector<double> sig[2][2];  // [model][load: point, face]
  for (int k = 0; k < 2; ++k) {
    const auto model = k == 0 ? rod_axisymmetric(steel, kR, L, h) : rod_hexahedra(steel, kR, L, h);
    const auto probes = make_probes(model, {{"S", {0, 0, L}, ""}}, MotionQuantity::acceleration, "z");
    const auto st = choose_stepping(model, 60e-6, 0.1e-6);
    ExplicitOptions opt;
    opt.dt_s = st.dt_s;
    opt.steps = st.steps;
    opt.sample_stride = st.stride;
    for (int l = 0; l < 2; ++l) {
      const auto load = make_load(model, 2, 0.0, {0, 0, 0}, l == 0 ? 0.0 : 1.0, 2, 1.0, burst);
      sig[k][l] = run_explicit(model, load, probes, opt).signals[0].samples;
    }
  }
  std::printf("PCC axisymmetric vs 3D: face load %.6f, point load %.6f\n", signal::pearson(sig[0][1], sig[1][1]),
              signal::pearson(sig[0][0], sig[1][0]));
  EXPECT_GT(signal::pearson(sig[0][1], sig[1][1]), 0.9999);  // uniform end traction
  EXPECT_GT(signal::pearson(sig[0][0], sig[1][0]), 0.9995);  // point force on the axis
}

TEST(FemSolver, GroupVelocityConvergesToPochhammerChree) {
  // 10-cycle burst at 150 kHz in an axisymmetric rod, axial velocity at two axis
  // stations. Reference: the FEM record at z1 carried to z2 by the exact L(0,1)
  // propagator exp(-i k(omega) dz) of Pochhammer-Chree theory; the group velocity
  // is dz over the shift of the energy centroid. The FEM's own dispersion error
  // should fall as h^2.
  const double L = 500e-3, z1 = 100e-3, z2 = 250e-3, f0 = 150e3;
  const signal::HannBurst burst(f0, 10, 1.0);
  const PochhammerChree pc(steel, kR);
  TraceOptions topt;
  topt.f_max_Hz = 320e3;
  const auto trace = trace_longitudinal_modes(pc, topt);
  double errors[3], arrival_errors[3];
  double c_ref_last = 0;
  const int rings[3] = {2, 4, 8};
  for (int r = 0; r < 3; ++r) {
    const auto model = rod_axisymmetric(steel, kR, L, kR / rings[r]);
    const auto probes = make_probes(model, {{"A", {0, 0, z1}, ""}, {"B", {0, 0, z2}, ""}}, MotionQuantity::velocity, "z");
    const auto load = make_load(model, 2, 0.0, {0, 0, 0}, 0.0, 2, 1.0, burst);
    const auto st = choose_stepping(model, 140e-6, 0.1e-6);
    ExplicitOptions opt;
    opt.dt_s = st.dt_s;
    opt.steps = st.steps;
    opt.sample_stride = st.stride;
    const auto res = run_explicit(model, load, probes, opt);
    const auto& a = res.signals[0];
    const auto& b = res.signals[1];
    const double dz = model.position(probes[1].dof / 2)[2] - model.position(probes[0].dof / 2)[2];
    // Propagate a by theory.
    const std::size_t n = 4 * a.size();
    auto X = signal::rfft(a.samples, n);
    std::vector<double> freqs;
    for (std::size_t j = 1; j < X.size(); ++j) freqs.push_back(double(j) / (double(n) * a.dt_s));
    std::vector<double> fbelow;
    for (double f : freqs)
      if (f < 300e3) fbelow.push_back(f);
    const auto pts = sample_at_frequencies(pc, trace, fbelow);
    X[0] = 0;
    std::size_t used = 0;
    for (std::size_t j = 1; j < X.size(); ++j) {
      if (freqs[j - 1] >= 300e3) {
        X[j] = 0;
        continue;
      }
      const auto& p = pts.at(used++);
      ASSERT_EQ(p.mode, 1);
      X[j] *= std::polar(1.0, -p.k_rad_m * dz);
    }
    signal::Signal prop = a;
    prop.samples = signal::irfft(X, n);
    prop.samples.resize(a.size());
    const double c_fem = dz / (energy_centroid(b) - energy_centroid(a));
    const double c_ref = dz / (energy_centroid(prop) - energy_centroid(a));
    errors[r] = c_fem - c_ref;
    arrival_errors[r] = energy_centroid(b) - energy_centroid(prop);  // arrival at z2, FEM against theory
    c_ref_last = c_ref;
  }
  // The reference is near the theory's group velocity at the centre frequency.
  std::vector<double> f{f0};
  const double cg = sample_at_frequencies(pc, trace, f).at(0).c_group_m_s;
  EXPECT_NEAR(c_ref_last / cg, 1.0, 0.01);
  // Converging, second order (observed orders printed for the record).
  const double p1 = std::log2(errors[0] / errors[1]), p2 = std::log2(errors[1] / errors[2]);
  std::printf("group velocity error at h = R/2, R/4, R/8: %.2f, %.2f, %.2f m/s; observed orders %.2f, %.2f\n",
              errors[0], errors[1], errors[2], p1, p2);
  EXPECT_LT(std::abs(errors[2]) / cg, 0.005);
  EXPECT_NEAR(p2, 2.0, 0.4);
  EXPECT_NEAR(p1, 2.0, 0.6);
  const double q1 = std::log2(arrival_errors[0] / arrival_errors[1]), q2 = std::log2(arrival_errors[1] / arrival_errors[2]);
  std::printf("arrival-time error at z2: %.3f, %.3f, %.3f us; observed orders %.2f, %.2f\n", arrival_errors[0] * 1e6,
              arrival_errors[1] * 1e6, arrival_errors[2] * 1e6, q1, q2);
  EXPECT_GT(arrival_errors[2], 0);  // the discrete rod is slow: the packet arrives late
  EXPECT_NEAR(q2, 2.0, 0.4);
}

TEST(FemSolver, SameBitsForOneAndTwoThreads) {
  const auto model = rod_hexahedra(steel, kR, 30e-3, 1.5e-3);
  const auto probes = make_probes(model, {{"S", {0, 0, 30e-3}, ""}, {"T", {kR, 0, 15e-3}, "x"}},
                                  MotionQuantity::acceleration, "z");
  const auto load = make_load(model, 2, 0.0, {0, 0, 0}, 0.0, 2, 1.0, signal::HannBurst(150e3, 5, 1.0));
  ExplicitOptions opt;
  opt.dt_s = 0.9 * model.stable_dt();
  opt.steps = 150;
  opt.alpha_damping_per_s = 2000;
  opt.min_elements_per_thread = 0;  // threads even for this small mesh
  const int before = omp_get_max_threads();
  omp_set_num_threads(1);
  const auto one = run_explicit(model, load, probes, opt);
  omp_set_num_threads(2);
  const auto two = run_explicit(model, load, probes, opt);
  omp_set_num_threads(before);
  EXPECT_EQ(one.threads, 1);
  EXPECT_EQ(two.threads, 2);
  for (std::size_t p = 0; p < probes.size(); ++p) {
    ASSERT_EQ(one.signals[p].size(), two.signals[p].size());
    EXPECT_EQ(std::memcmp(one.signals[p].samples.data(), two.signals[p].samples.data(),
                          one.signals[p].size() * sizeof(double)),
              0);
  }
}

TEST(FemCase, SteppingAndInputErrors) {
  const auto model = rod_axisymmetric(steel, kR, 50e-3, 1e-3);
  const auto s = choose_stepping(model, 10e-6, 0.1e-6);
  EXPECT_LE(s.dt_s, model.stable_dt());
  EXPECT_NEAR(s.dt_s * double(s.stride), 0.1e-6, 1e-18);
  EXPECT_EQ(s.steps, std::llround(10e-6 / s.dt_s));
  EXPECT_THROW(choose_stepping(model, 10e-6, 0.1e-6, 1.01 * model.stable_dt()), InputError);
  EXPECT_THROW(choose_stepping(model, 10e-6, 0.1e-6, 0.03e-6), InputError);  // 0.1 us is not 3.33 steps
  EXPECT_NO_THROW(choose_stepping(model, 10e-6, 0.1e-6, 0.05e-6));
  EXPECT_THROW(make_probes(model, {{"far", {20e-3, 0, 10e-3}, ""}}, MotionQuantity::velocity, "z"), InputError);
  EXPECT_THROW(parse_probe_point("S=1,2"), InputError);
  EXPECT_THROW(parse_probe_point("=1,2,3"), InputError);
  EXPECT_THROW(parse_probe_point("S=1,2,3/q"), InputError);
  EXPECT_THROW(rod_axisymmetric({steel.E_Pa, 0.5, steel.rho_kg_m3}, kR, 1, 1e-3), InputError);
  EXPECT_THROW(rod_hexahedra(steel, kR, 1, -1e-3), InputError);
}

TEST(FemSolver, CubePulseArrivesAtTheLongitudinalSpeed) {
  // The cube paper's concrete (E_d, nu_d, rho): a burst pushed into the centre of one face of
  // a 20 mm cube. On the axis through the cube the first arrival travels with the P wave:
  // from a station 5 mm in to the opposite face it takes 15 mm / cP (same picker on both).
  const double L = 20e-3;
  const auto model = box_hexahedra(concrete, {L, L, L}, 1e-3);
  const auto load = make_load(model, 2, 0.0, {L / 2, L / 2, 0}, 1.5e-3, 2, 1.0, signal::HannBurst(200e3, 5, 1.0));
  const auto probes =
      make_probes(model,
                  {{"B", {L / 2, L / 2, L}, ""}, {"C", {0, L / 2, L / 2}, ""}, {"A", {L / 2, L / 2, 5e-3}, "z"},
                   {"D", {L, L / 2, L / 2}, ""}},
                  MotionQuantity::acceleration, "normal", std::array<double, 3>{L, L, L});
  // "normal" is the outward normal, as mw-dem records it: +z on the face z = L, -x on x = 0.
  EXPECT_EQ(probes[0].component, "z");
  EXPECT_EQ(probes[1].component, "-x");
  EXPECT_EQ(probes[3].component, "x");
  const auto st = choose_stepping(model, 12e-6, 0.05e-6);
  ExplicitOptions opt;
  opt.dt_s = st.dt_s;
  opt.steps = st.steps;
  opt.sample_stride = st.stride;
  const auto res = run_explicit(model, load, probes, opt);
  signal::ThresholdOptions to;
  to.noise_begin_s = 0;
  to.noise_end_s = 1e-6;  // before anything can arrive
  to.relative = 0.02;
  to.noise_end_s = 0.5e-6;  // before anything can arrive at A
  const double dt = signal::threshold_pick(res.signals[0], to).time_s - signal::threshold_pick(res.signals[2], to).time_s;
  const double cP = wave_speeds(concrete).cP;
  std::printf("P travel A -> B %.3f us, 15 mm / cP = %.3f us\n", dt * 1e6, 15e-3 / cP * 1e6);
  EXPECT_NEAR(dt, 15e-3 / cP, 0.03 * 15e-3 / cP);
  // C (x = 0) and D (x = L) are mirror images across x = L / 2: the outward normals see the same
  // signal (the x components are opposite), as for the paper's D/F and E/G pairs of an ideal cube.
  double peak = 0, worst = 0;
  for (std::size_t i = 0; i < res.signals[1].size(); ++i) {
    peak = std::max(peak, std::abs(res.signals[3].samples[i]));
    worst = std::max(worst, std::abs(res.signals[1].samples[i] - res.signals[3].samples[i]));
  }
  EXPECT_GT(peak, 0.0);
  EXPECT_LT(worst, 1e-9 * peak);
}

TEST(FemCase, AssembledBarPulseFollowsTheImpedanceSolution) {
  // The bar of BarPulseFollowsTheOneDimensionalImpedanceSolution described as a
  // case (the patch covers the whole end face): v(z, t) = F(t - z / c0) / (rho c0 A).
  FemCase c;
  c.body = FemCase::Body::box;
  c.material = {210e9, 0.0, 7800.0};
  const double a = 2e-3, L = 300e-3, z = 100e-3, c0 = std::sqrt(c.material.E_Pa / c.material.rho_kg_m3);
  c.size_m = {a, a, L};
  c.source_m = {a / 2, a / 2, 0};
  c.patch_radius_m = 1.0;
  c.frequency_hz = 100e3;
  c.cycles = 3;
  c.force_N = 50;
  c.duration_s = 90e-6;
  c.quantity = MotionQuantity::velocity;
  c.probe_points = {{"V", {a / 2, a / 2, z}, "z"}};
  c.threads = 2;
  const FemSetup setup = assemble_fem_case(c);
  const FemRun run = run_fem_case(setup);
  ASSERT_EQ(run.result.signals.size(), 2u);  // V, then the excitation
  const auto& v = run.result.signals[0];
  const signal::HannBurst burst(100e3, 3, 50.0);
  double peak = 0, err = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const double exact = burst(v.time(i) - z / c0) / (c.material.rho_kg_m3 * c0 * a * a);
    peak = std::max(peak, std::abs(exact));
    err = std::max(err, std::abs(v.samples[i] - exact));
  }
  EXPECT_LT(err / peak, 0.01);
  const auto& f = run.result.signals[1];
  EXPECT_EQ(f.name, "excitation");
  ASSERT_EQ(f.size(), v.size());
  for (std::size_t i = 0; i < f.size(); i += 37) EXPECT_NEAR(f.samples[i], burst(f.time(i)), 1e-9);
  // 2 x 2 x 300 elements: fewer than two threads' worth (4000 each).
  EXPECT_EQ(run.result.threads, 1);
  EXPECT_EQ(run.threads.reason, "requested (--threads 2), 1 for 1200 elements (at least 4000 per thread)");
  EXPECT_EQ(run.attributes.at("burst_cycles"), "3");

  // The far face pushes the other way (into the body); a point inside is no face.
  FemCase far = c;
  far.source_m = {a / 2, a / 2, L};
  far.patch_radius_m = 0;
  const FemSetup far_setup = assemble_fem_case(far);
  ASSERT_EQ(far_setup.load.dof_weights.size(), 1u);
  EXPECT_EQ(far_setup.load.dof_weights[0].second, -1.0);
  far.source_m = {a / 2, a / 2, L / 2};
  EXPECT_THROW(assemble_fem_case(far), InputError);
  FemCase blind = c;
  blind.probe_points.clear();
  EXPECT_THROW(assemble_fem_case(blind), InputError);
}

TEST(FemCase, RodDefaultsToTheFarEndSensor) {
  FemCase c;
  c.material = steel;
  c.radius_m = kR;
  c.length_m = 50e-3;
  c.duration_s = 1e-6;
  c.spacetime_step_m = 0.0;  // every mesh size along the axis
  const FemSetup setup = assemble_fem_case(c);
  ASSERT_EQ(setup.probes.size(), 1u);
  EXPECT_EQ(setup.probes[0].name, "S");
  const auto x = setup.model.position(setup.probes[0].dof / std::size_t(setup.model.dim));
  EXPECT_NEAR(x[2], 50e-3, 1e-12);
  ASSERT_TRUE(setup.spacetime);
  EXPECT_EQ(setup.spacetime->coordinate_m.size(), 51u);  // z = 0, 1, ..., 50 mm
  c.rod_model = "2d";
  EXPECT_THROW(assemble_fem_case(c), InputError);
}
