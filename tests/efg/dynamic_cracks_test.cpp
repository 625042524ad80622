// Cracks in explicit EFG dynamics (efg/dynamic_cracks, issue 16) against closed forms:
//  - SPALL of a free strip: a compressive pulse with a short rise and a linear fall reflects from the
//    free end as tension; the first crack forms where the net tension first reaches f_t, at the
//    distance d = lambda_f f_t / (2 sigma_0) from the free end (derived below), at the time the
//    reflected peak gets there;
//  - the crack-speed limit: with it no tip moves faster than v_max; without it the same spall's tip
//    runs faster than 500 m/s;
//  - the minimum spacing between cracks;
//  - the energy balance: kinetic + strain + dissipated + stored in the faces = work of the load;
//  - the same bits for 1 and 2 threads;
//  - the contact penalty: a compressive pulse crosses a traction-free crack whose faces touch;
//  - the crack radius limit on a prescribed turn.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <memory>

#include "mesowave/efg/dynamic_cracks.hpp"
#include "support/input_error.hpp"

using namespace mesowave;
using namespace mesowave::efg;
using mesowave::test::input_error_of;

namespace {

// Concrete as the strip of docs/efg.md, here in plane stress with free long sides: the state of a
// slender bar (sigma_yy = 0), whose long waves travel at the bar speed c = sqrt(E / rho).
const ElasticMaterial2D kConcrete{30e9, 0.2, 1.0, 2400, PlaneState::plane_stress};
const double kBarSpeed = std::sqrt(30e9 / 2400.0);  // 3535.5 m/s

struct SpallSetup {
  double L = 0.2, W = 0.01, h = 2.5e-3;
  double sigma0 = 10e6, rise = 15e-6, fall = 60e-6, f_t = 3e6;
  double duration = 90e-6;
  double speed_limit = 500;
  double min_spacing = 0;
  int threads_min_points = 2000;
  FieldProjection project_fields = DynamicCrackOptions{}.project_fields;  // the library default
};

struct SpallRun {
  DynamicsResult run;
  std::vector<CrackEvent> events;
  double dissipated = 0, stored_faces = 0, strain = 0, kinetic = 0, jump = 0, kinetic_jump = 0, faces_jump = 0;
  std::vector<DynamicCracks::Projection> projections;
  double balance() const { return kinetic + strain + dissipated + stored_faces - jump - run.energy.back().external_work_J; }
  std::size_t cracks = 0;
  std::vector<Vec2> first_crack;
};

SpallRun run_spall(const SpallSetup& s) {
  const int nx = int(std::lround(s.L / s.h)), ny = int(std::lround(s.W / s.h));
  const Discretisation disc = rectangular_grid({0, 0, s.L, s.W}, nx, ny);
  CrackSet cracks;
  const MlsApproximation mls(disc.nodes, support_radii_by_spacing(disc.nodes, disc.spacing_m, 2.5), {}, &cracks);
  ElasticModel model(disc, kConcrete, mls);
  const LinearElasticPoint linear(kConcrete);
  const ExplicitDynamics dyn(model, linear, nullptr,
                             {{{Vec2(0, s.W), Vec2(0, 0)}, TriangularPulse{s.sigma0, s.rise, s.fall, 0}, "end"}});
  DynamicCrackOptions co;
  co.cohesive.f_t_Pa = s.f_t;
  co.cohesive.G_f_J_m2 = 100;  // assumed, a normal concrete's (fib Model Code 2010 gives 100-150 N/m)
  co.strain_rate_effect = false;  // the closed form is for a fixed strength
  co.crack_speed_limit_m_s = s.speed_limit;
  co.min_crack_spacing_m = s.min_spacing;
  co.project_fields = s.project_fields;
  DynamicCracks dc(model, cracks, co);
  DynamicsOptions o;
  o.duration_s = s.duration;
  o.cracks = &dc;
  o.sample_stride = 1000000;
  o.min_points_per_thread = std::size_t(s.threads_min_points);
  SpallRun out;
  out.run = dyn.run(o);
  out.events = dc.events();
  out.dissipated = dc.dissipated_J();
  out.stored_faces = dc.stored_J(out.run.u);
  out.cracks = dc.cracks().cracks().size();
  out.jump = dc.energy_jump_J();
  out.kinetic_jump = dc.kinetic_jump_J();
  out.faces_jump = dc.faces_jump_J();
  out.projections = dc.projections();
  if (!dc.cracks().cracks().empty()) out.first_crack = dc.cracks().cracks().front().points;
  // strain energy of the linear law at the last step: W_int^{n+1/2} = 1/2 u^n . K u^{n+1} (the central
  // difference's shadow energy, docs/efg.md), with K of the cracked shape functions
  std::vector<PointState> states;
  const Eigen::VectorXd Ku = dyn.internal_force(out.run.u, states);
  out.strain = 0.5 * out.run.u_previous.dot(Ku);
  out.kinetic = out.run.energy.back().kinetic_J;
  return out;
}

}  // namespace

// The closed form. A pulse p(t) on x = 0 (rise t_r, then a linear fall over t_f from sigma_0 to 0)
// travels as the compression -P(s), s the distance behind its front, P rising over lambda_r = c t_r
// and falling linearly over lambda_f = c t_f. The free end x = L reflects it as the tension +P(s');
// at the distance d from the end the two meet with s - s' = 2 d, so the net stress there is
// P(s') - P(s' + 2 d). Once the reflected peak has passed (s' >= lambda_r, with s' + 2 d on the fall)
// it is sigma_0 (s' + 2d - s') / lambda_f = 2 sigma_0 d / lambda_f, the same for as long as both lie
// on the fall, and below it before (s' < lambda_r: P(s') < sigma_0). So the net tension at d never
// exceeds 2 sigma_0 d / lambda_f, which reaches f_t first at d = lambda_f f_t / (2 sigma_0), when the
// reflected peak gets there: t = t_r + (L + d) / c. (Points deeper in reach f_t earlier in the
// reflected rise only if lambda_r > lambda_f: d + s*(d) grows with d at the rate 1 - 2 lambda_r /
// (lambda_r + lambda_f) > 0 here.) Here sigma_0 = 10 MPa, t_r = 15 us, t_f = 60 us, f_t = 3 MPa:
// d = 31.8 mm, x = 168.2 mm, t = 80.57 us.
TEST(DynamicCracks, SpallFormsWhereTheNetTensionFirstReachesTheStrength) {
  const SpallSetup s;
  const SpallRun r = run_spall(s);
  ASSERT_FALSE(r.events.empty());
  const CrackEvent& first = r.events.front();
  ASSERT_TRUE(first.initiation);
  const double lambda_f = kBarSpeed * s.fall, d = lambda_f * s.f_t / (2 * s.sigma0);
  const double t_expected = s.rise + (s.L + d) / kBarSpeed;
  // Position within 2 h (5 mm; measured 170.8 mm against 168.2 mm, +2.6 mm). Why 2 h: the crack-free
  // strip's largest net tension exceeds 2 sigma_0 d / lambda_f by 0.4-0.6 MPa between 150 and 190 mm
  // at h = 2.5 mm AND at 1.25 mm (sensors on the centre line; not a discretisation error that falls
  // with h, not explained yet), which moves the first point d by delta lambda_f / (2 sigma_0) = 4-6 mm
  // toward the end; the criterion is read at Gauss points (about h / 2 apart in x) and the crack is
  // shifted off the Gauss line by 0.1 a.
  EXPECT_NEAR(first.from.x(), s.L - d, 2 * s.h);
  // Time within 3 us (measured 82.92 us against 80.57 us, +2.35 us): the criterion reads the stress of
  // the step before (dt = 1.04 us), and the same excess reaches f_t where the closed form's level
  // stays below it for a while (t grows along d at 0.6 / c = 0.17 us/mm).
  EXPECT_NEAR(first.t_s, t_expected, 3e-6);
  EXPECT_GT(first.t_s, t_expected - 1e-6);  // never before the reflected peak can get there
  // Normal to the largest principal stress (sigma_xx): a crack across the strip, i.e. vertical.
  ASSERT_GE(r.first_crack.size(), 2u);
  const Vec2 along = (r.first_crack.back() - r.first_crack.front()).normalized();
  EXPECT_LT(std::abs(along.x()), 0.1);  // within 6 degrees of vertical (the tips follow the local principal directions)
  // Minimum spacing (2 a = 5 mm by default) holds between a critical Gauss point and the cracks; the
  // crack's centre is then moved off the Gauss line by at most 0.4 a along its normal, so two centres
  // lie at least 2 a - 2 x 0.4 a apart.
  const double spacing = 2 * s.h - 0.8 * s.h;
  for (std::size_t i = 0; i < r.events.size(); ++i)
    for (std::size_t j = i + 1; j < r.events.size(); ++j)
      if (r.events[i].initiation && r.events[j].initiation) {
        EXPECT_GE((r.events[i].from - r.events[j].from).norm(), spacing * (1 - 1e-9)) << i << " " << j;
      }
  EXPECT_GT(r.cracks, 1u);  // the tension keeps growing inward: more spall planes (cohesive faces carry f_t)
}

// The speed limit: the same spall run on to 92 us, tips growing. With v_max = 500 m/s no tip moves
// faster; without a limit (v_max = 1e12 m/s) the tips of the same run move a segment (2.5 mm) in a few
// steps, faster than 500 m/s.
TEST(DynamicCracks, NoTipIsFasterThanTheSpeedLimitWhichTheUnlimitedRunExceeds) {
  SpallSetup s;
  s.duration = 92e-6;  // tips wait a / v_max = 5 us after the first crack (82.9 us) with the limit
  double fastest_limited = 0, fastest_free = 0;
  std::size_t grown_limited = 0;
  {
    const SpallRun r = run_spall(s);
    for (const auto& e : r.events)
      if (!e.initiation) fastest_limited = std::max(fastest_limited, e.speed_m_s), ++grown_limited;
  }
  s.speed_limit = 1e12;
  {
    const SpallRun r = run_spall(s);
    for (const auto& e : r.events)
      if (!e.initiation) fastest_free = std::max(fastest_free, e.speed_m_s);
  }
  std::printf("grown %zu, fastest with the limit %.1f m/s, without %.1f m/s\n", grown_limited, fastest_limited, fastest_free);
  ASSERT_GT(grown_limited, 0u);
  EXPECT_LE(fastest_limited, 500.0 * (1 + 1e-12));  // length / elapsed, the elapsed time held >= a / v_max
  EXPECT_GT(fastest_free, 500.0);
}

// Energy balance and threads, on the spall run with one crack (min spacing 1 m): the crack starts, its
// two tips grow to the faces. kinetic + strain + dissipated + stored in the faces = W_ext + the energy
// the cuts add at fixed u (energy_jump_J; dynamic_cracks.hpp: measured +0.8 % of W_ext here).
// Tolerance 2e-3 of W_ext (measured 3.4e-4): the faces' work in the run is the trapezoid sum
// f^n (dt/2)(v + v') over steps across the softening law, their energy the law's integral; and the
// strain energy is the central difference's shadow energy 1/2 u^n K u^{n+1} while the jumps are read
// at u^{n+1}.
TEST(DynamicCracks, EnergyBalanceAndTheSameBitsForOneAndTwoThreads) {
  SpallSetup s;
  s.min_spacing = 1.0;
  s.threads_min_points = 1;
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const SpallRun r1 = run_spall(s);
  omp_set_num_threads(2);
  const SpallRun r2 = run_spall(s);
  omp_set_num_threads(threads);
  EXPECT_EQ(r1.run.threads, 1);
  EXPECT_EQ(r2.run.threads, 2);
  ASSERT_EQ(r1.events.size(), r2.events.size());
  ASSERT_GE(r1.events.size(), 3u);  // started, and grew
  EXPECT_EQ(r1.cracks, 1u);
  for (std::size_t i = 0; i < r1.events.size(); ++i) {
    EXPECT_EQ(r1.events[i].t_s, r2.events[i].t_s);
    EXPECT_EQ(r1.events[i].to, r2.events[i].to);
  }
  ASSERT_EQ(r1.run.u.size(), r2.run.u.size());
  EXPECT_EQ(0, std::memcmp(r1.run.u.data(), r2.run.u.data(), sizeof(double) * std::size_t(r1.run.u.size())));
  const double W_ext = r1.run.energy.back().external_work_J;
  const double balance = r1.kinetic + r1.strain + r1.dissipated + r1.stored_faces - r1.jump - W_ext;
  std::printf("W_ext %.6g KE %.6g strain %.6g dissipated %.6g stored %.6g jump %.6g balance %.3g\n", W_ext, r1.kinetic,
              r1.strain, r1.dissipated, r1.stored_faces, r1.jump, balance / W_ext);
  EXPECT_LT(std::abs(balance), 2e-3 * W_ext);
  EXPECT_GT(r1.dissipated, 0.0);
  EXPECT_LT(r1.run.energy_drift, 1e-12);  // the scheme's own identity, faces' forces included
}

// Contact: a traction-free crack across the strip at x = 101.25 mm (between node and Gauss columns),
// a 10 MPa compressive pulse (15 / 60 us) through it. Closed faces push back with k = E / a; a spring
// interface of stiffness k between two equal bars transmits |T| = 1 / sqrt(1 + (omega Z / (2 k))^2),
// Z = rho c: omega Z / (2 k) = omega a / (2 c) = 0.03 at the pulse's 13 kHz (1 / 75 us), |T| = 0.9996,
// so the peak beyond the crack is the crack-free strip's. With the penalty a million times softer the
// faces pass through each other and almost nothing crosses (visibility: no node couples the sides).
TEST(DynamicCracks, ClosedFacesTransmitACompressivePulseThroughThePenalty) {
  const double L = 0.2, W = 0.01, h = 2.5e-3, x_c = 0.10125;
  const auto peak_beyond = [&](bool crack, double penalty_factor) {
    const Discretisation disc = rectangular_grid({0, 0, L, W}, 80, 4);
    CrackSet cracks;
    const MlsApproximation mls(disc.nodes, support_radii_by_spacing(disc.nodes, disc.spacing_m, 2.5), {}, &cracks);
    ElasticModel model(disc, kConcrete, mls);
    const LinearElasticPoint linear(kConcrete);
    const ExplicitDynamics dyn(model, linear, nullptr,
                               {{{Vec2(0, W), Vec2(0, 0)}, TriangularPulse{10e6, 15e-6, 60e-6, 0}, "end"}});
    DynamicCrackOptions co;
    co.cohesive.f_t_Pa = 1e9;  // no new cracks: only the placed one
    co.cohesive.G_f_J_m2 = 100;
    co.strain_rate_effect = false;
    co.penalty_factor = penalty_factor;
    DynamicCracks dc(model, cracks, co);
    if (crack) dc.add_crack({Vec2(x_c, -0.5 * h), Vec2(x_c, 0.25 * W), Vec2(x_c, 0.75 * W), Vec2(x_c, W + 0.5 * h)}, true, false);
    DynamicsOptions o;
    o.duration_s = 70e-6;  // the peak reaches 150 mm at 57.4 us; the reflection from x = L not before 71 us
    o.cracks = &dc;
    const auto r = dyn.run(o, {{"beyond", Vec2(0.15, 0.5 * W)}});
    double peak = 0;
    for (const auto& smp : r.sensors[0]) peak = std::max(peak, -smp.stress_Pa[0]);
    return peak;
  };
  const double free = peak_beyond(false, 1), contact = peak_beyond(true, 1), none = peak_beyond(true, 1e-6);
  std::printf("-sigma_xx at 150 mm by 70 us (peak): no crack %.4f MPa, contact %.4f MPa, no contact %.4f MPa\n", free * 1e-6,
              contact * 1e-6, none * 1e-6);
  // 2 % (measured 0.9942): |T| = 0.9996 for the spring; the rest is the cut's own change of the
  // approximation near the line (the energy jump of dynamic_cracks.hpp), not bounded in closed form
  EXPECT_NEAR(contact / free, 1.0, 0.02);
  EXPECT_LT(none, 0.05 * free);
}

// The projection of the parameters onto the cut space at each change (project_fields, efg/field_projection)
// on the same spall strip: the energy the changes add (energy_jump_J, kinetic energy included) falls, the
// balance with it still closes, and the first crack is the same (it starts before any projection).
// Measured (this machine, docs/efg.md "Energy across crack growth"), energy_jump_J / W_ext:
//   one crack (min spacing 1 m):  none 7.85e-3, u 3.05e-3, u-v 2.95e-3   (held: < 4e-3 and < 0.5 x none)
//   24 cracks (default spacing):  none 0.152,  u 0.042 (24 cracks)          (held: < 0.06 and < 0.5 x none)
// and the balance kinetic + strain + faces - jump - W_ext: one crack 3.5e-4 / 5.5e-4 / 5.6e-4 of W_ext
// (held to the 2e-3 of the test above), 24 cracks 3.4e-2 / 7.3e-3 (held < 1e-2 with u: the balance the
// projection closes; without it 0.10 J stayed unaccounted, dynamic_cracks.hpp).
TEST(DynamicCracks, ProjectingTheFieldsCutsTheEnergyTheChangesAdd) {
  SpallSetup s;
  s.min_spacing = 1.0;
  const auto run = [&](FieldProjection p) {
    s.project_fields = p;
    return run_spall(s);
  };
  const SpallRun none = run(FieldProjection::none), u = run(FieldProjection::displacement),
                 uv = run(FieldProjection::displacement_and_velocity);
  const double W = none.run.energy.back().external_work_J;
  std::printf("one crack: jump / W_ext none %.3e u %.3e u-v %.3e (kinetic %.2e J); balance / W_ext %.2e %.2e %.2e\n", none.jump / W,
              u.jump / u.run.energy.back().external_work_J, uv.jump / uv.run.energy.back().external_work_J, uv.kinetic_jump,
              none.balance() / W, u.balance() / W, uv.balance() / W);
  for (const SpallRun* r : {&u, &uv}) {
    const double Wr = r->run.energy.back().external_work_J;
    ASSERT_EQ(r->cracks, 1u);
    ASSERT_FALSE(r->projections.empty());
    EXPECT_EQ(r->events.front().t_s, none.events.front().t_s);  // the first crack: before any projection
    EXPECT_EQ(r->events.front().from, none.events.front().from);
    EXPECT_LT(r->jump, 4e-3 * Wr);
    EXPECT_LT(r->jump, 0.5 * none.jump);
    EXPECT_LT(std::abs(r->balance()), 2e-3 * Wr);
    EXPECT_LT(r->run.energy_drift, 1e-12);  // the run's identity, the projection's kinetic change booked
    for (const auto& p : r->projections) EXPECT_TRUE(p.ok);
  }
  EXPECT_EQ(u.kinetic_jump, 0.0);  // v is kept: the lumped kinetic energy cannot change
  // many cracks: u only (u-v measured 0.033, but see docs/efg.md: on a coarse slab it changed KE by 49 % of W_ext)
  s.min_spacing = 0;
  const SpallRun many_none = run(FieldProjection::none), many_u = run(FieldProjection::displacement);
  const double Wm = many_u.run.energy.back().external_work_J;
  std::printf("%zu / %zu cracks: jump / W_ext none %.3f u %.3f; balance / W_ext %.2e %.2e\n", many_none.cracks, many_u.cracks,
              many_none.jump / many_none.run.energy.back().external_work_J, many_u.jump / Wm,
              many_none.balance() / many_none.run.energy.back().external_work_J, many_u.balance() / Wm);
  EXPECT_GT(many_u.cracks, 10u);
  EXPECT_LT(many_u.jump, 0.06 * Wm);
  EXPECT_LT(many_u.jump, 0.5 * many_none.jump);
  EXPECT_LT(std::abs(many_u.balance()), 1e-2 * Wm);
}

// The projection keeps the run's bits for any thread count: its points, nodes and sums are in a fixed
// order and serial (one crack, u and v projected, 1 and 2 threads).
TEST(DynamicCracks, ProjectionGivesTheSameBitsForOneAndTwoThreads) {
  SpallSetup s;
  s.min_spacing = 1.0;
  s.threads_min_points = 1;
  s.project_fields = FieldProjection::displacement_and_velocity;
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const SpallRun r1 = run_spall(s);
  omp_set_num_threads(2);
  const SpallRun r2 = run_spall(s);
  omp_set_num_threads(threads);
  EXPECT_EQ(r1.run.threads, 1);
  EXPECT_EQ(r2.run.threads, 2);
  ASSERT_GE(r1.projections.size(), 3u);
  ASSERT_EQ(r1.events.size(), r2.events.size());
  for (std::size_t i = 0; i < r1.events.size(); ++i) {
    EXPECT_EQ(r1.events[i].t_s, r2.events[i].t_s);
    EXPECT_EQ(r1.events[i].to, r2.events[i].to);
  }
  ASSERT_EQ(r1.run.u.size(), r2.run.u.size());
  const auto bytes = sizeof(double) * std::size_t(r1.run.u.size());
  EXPECT_EQ(0, std::memcmp(r1.run.u.data(), r2.run.u.data(), bytes));
  EXPECT_EQ(0, std::memcmp(r1.run.v.data(), r2.run.v.data(), bytes));
  EXPECT_EQ(r1.jump, r2.jump);
  EXPECT_EQ(r1.kinetic_jump, r2.kinetic_jump);
}
