// The contact-detonated slab (efg/blast_slab, the shock paper's Section 4.3) on a small slab (200 x 60 mm,
// h = 10 mm, 30-40 us: the tests' time), every part of the paper's list on at once: the crack-speed limit
// holds and acts, the spacing and direction limits hold on the slab's own events, the compacted zone is
// under the charge and empty below the Y-function's threshold pressure (closed form), the run's energy
// identity with the faces' forces inside, the same bits for 1 and 2 threads, bad input one line each.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "mesowave/efg/blast_slab.hpp"
#include "support/input_error.hpp"

using namespace mesowave;
using namespace mesowave::efg;
using mesowave::test::input_error_of;

namespace {

BlastSlabOptions small_slab() {
  BlastSlabOptions o;
  o.span_m = 0.2;
  o.thickness_m = 0.06;
  o.spacing_m = 0.01;
  o.cracks.cohesive.f_t_Pa = 2.4e6;  // the paper's Section 4.1 concrete
  o.cracks.cohesive.G_f_J_m2 = 113;
  o.cracks.strain_rate.f_cm_Pa = 30.4e6;
  o.cracks.penalty_factor = 1;
  o.charge.peak_Pa = 1e9;
  o.duration_s = 30e-6;
  return o;
}

double turn(const Vec2& a, const Vec2& b) { return std::abs(std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b))); }

/// The largest turn between consecutive segments of the cracks' polylines (an initiation's two halves,
/// then one segment per growth at either end).
double largest_turn(const BlastSlabResult& r) {
  double worst = 0;
  for (const auto& p : r.crack_polylines)
    for (std::size_t i = 0; i + 2 < p.size(); ++i) {
      const Vec2 a = p[i + 1] - p[i], b = p[i + 2] - p[i + 1];
      if (a.norm() > 1e-9 && b.norm() > 1e-9) worst = std::max(worst, turn(a, b));
    }
  return worst;
}

}  // namespace

TEST(BlastSlab, CracksObeyTheSpeedSpacingAndRadiusLimitsAndTheSpeedLimitActs) {
  BlastSlabOptions o = small_slab();
  o.duration_s = 50e-6;  // the tips grow after 30 us
  const BlastSlabResult r = run_blast_slab(o);
  std::size_t grown = 0, started = 0;
  for (const CrackEvent& e : r.events) {
    if (e.initiation) {
      ++started;
      continue;
    }
    ++grown;
    EXPECT_LE(e.speed_m_s, 500.0 * (1 + 1e-12)) << "crack " << e.crack << " at " << e.t_s;
  }
  ASSERT_GT(started, 1u);
  ASSERT_GT(grown, 0u);
  // spacing: a critical point at least 2 a from every crack, then shifted by at most 0.4 a along its
  // normal to clear the nodes (dynamic_cracks.cpp): initiation centres at least 2 a - 0.8 a apart
  for (std::size_t i = 0; i < r.events.size(); ++i)
    for (std::size_t j = i + 1; j < r.events.size(); ++j)
      if (r.events[i].initiation && r.events[j].initiation) {
        EXPECT_GE((r.events[i].from - r.events[j].from).norm(), (r.min_spacing_m - 0.8 * r.segment_length_m) * (1 - 1e-9));
      }
  // direction: no segment turns more than 2 asin(a / (2 R_min)) (60 degrees for R_min = a) from the last
  const double limit = 2 * std::asin(r.segment_length_m / (2 * r.min_radius_m));
  EXPECT_LE(largest_turn(r), limit + 1e-9);
  EXPECT_GT(largest_turn(r), 0.5 * limit);  // the principal directions ask for more: the clamp acts

  BlastSlabOptions free = o;  // the same slab without the speed limit: some tip runs faster than 500 m/s
  free.cracks.crack_speed_limit_m_s = std::numeric_limits<double>::infinity();
  free.duration_s = 34e-6;  // the first cracks start before 30 us; unlimited tips grow every step after (slow to run on)
  const BlastSlabResult f = run_blast_slab(free);
  std::printf("cracks %zu, growths %zu, fastest %.1f m/s; without the limit %.1f m/s; largest turn %.1f deg (limit %.1f)\n",
              r.crack_length_m.size(), grown, r.max_crack_speed_m_s, f.max_crack_speed_m_s, largest_turn(r) * 180 / M_PI,
              limit * 180 / M_PI);
  EXPECT_LE(r.max_crack_speed_m_s, 500.0 * (1 + 1e-12));
  EXPECT_GT(f.max_crack_speed_m_s, 500.0);
}

// The direction limit acting: the slab above turns its cracks by up to the limit (60 degrees for R_min = a:
// the clamp is reached); with R_min = 5 a (11.5 degrees) every turn stays within that smaller limit.
TEST(BlastSlab, ALargerCrackRadiusGivesStraighterCracks) {
  BlastSlabOptions o = small_slab();
  o.duration_s = 50e-6;
  o.cracks.min_crack_radius_m = 0.05;
  const BlastSlabResult s = run_blast_slab(o);
  const double limit = 2 * std::asin(s.segment_length_m / (2 * 0.05));
  std::printf("largest turn with R_min = 5 a: %.2f deg (limit %.2f), %zu cracks\n", largest_turn(s) * 180 / M_PI,
              limit * 180 / M_PI, s.crack_polylines.size());
  EXPECT_GT(largest_turn(s), 0.0);  // the cracks do turn
  EXPECT_LE(largest_turn(s), limit + 1e-9);
}

// p_th = M e_v,th (uniaxial strain: the closed form of the threshold; M = E (1 - nu) / ((1 + nu)(1 - 2 nu))
// = 22.22 GPa for E = 20 GPa, nu = 0.2: 177.8 MPa). A quarter of it compacts nothing; ten times it compacts
// a zone that lies under the charge. Why a quarter, not just below p_th: the undamped explicit solver
// overshoots at the pulse's front (measured here: half of p_th reaches |eps_v| = 0.00809, 2.02 times the
// uniaxial p / M; the shock strip of docs/efg.md rings to 1.8 times its pulse), so p_th is the closed
// form of the continuum, and the discrete slab's threshold lies near p_th / 2.
TEST(BlastSlab, CompactedZoneLiesUnderTheChargeAndIsEmptyBelowTheThresholdPressure) {
  BlastSlabOptions o = small_slab();
  const double M = 20e9 * 0.8 / (1.2 * 0.6);
  EXPECT_NEAR(hugoniot_threshold_pressure_Pa(o.concrete, o.hugoniot), M * 0.008, 1e-6 * M * 0.008);
  o.duration_s = 20e-6;
  o.charge.peak_Pa = 0.25 * M * 0.008;
  const BlastSlabResult below = run_blast_slab(o);
  EXPECT_EQ(below.compacted_points, 0u);
  EXPECT_LT(below.max_compression_eps_v, 0.008);
  EXPECT_GT(below.max_compression_eps_v, 0.25 * 0.008);  // it did load: at least the uniaxial p / M
  o.charge.peak_Pa = 10 * M * 0.008;
  const BlastSlabResult above = run_blast_slab(o);
  std::printf("below: max |eps_v| %.5f; above: %zu points, depth %.1f mm, x %.1f-%.1f mm\n", below.max_compression_eps_v,
              above.compacted_points, above.compacted_depth_m * 1e3, above.compacted_x_min_m * 1e3, above.compacted_x_max_m * 1e3);
  ASSERT_GT(above.compacted_points, 0u);
  // under the charge (x = 100 +- 15 mm), spread by at most the depth on each side (a wave front from the
  // loaded segment), and from the top face down
  EXPECT_GE(above.compacted_x_min_m, 0.085 - above.compacted_depth_m);
  EXPECT_LE(above.compacted_x_max_m, 0.115 + above.compacted_depth_m);
  EXPECT_LT(above.compacted_depth_m, o.thickness_m);
  // the crater (efg/crater): none below the threshold; above, crushed points (past the Y-function's minimum,
  // 0.0475 > e_v,th) under the charge, inside the compacted zone, every one of them past eps_crush
  EXPECT_EQ(below.crater.area_m2, 0.0);
  EXPECT_NEAR(above.crushing_eps_v, 0.0475, 5e-5);
  std::printf("crater: %zu crushed points, depth %.1f mm, width %.1f mm, %zu loose pieces\n", above.crater.crushed_points,
              above.crater.depth_m * 1e3, above.crater.width_m * 1e3, above.crater.pieces - 1);
  ASSERT_GT(above.crater.crushed_points, 0u);
  ASSERT_EQ(above.final_points.crater.size(), above.points);
  for (std::size_t k = 0; k < above.points; ++k) {
    if (above.final_points.crater[k] == CraterLabel::crushed) {
      EXPECT_LE(above.final_points.min_eps_v[k], -above.crushing_eps_v) << k;
    }
  }
  if (above.crater.crater_fragments == 0) {
    EXPECT_LE(above.crater.depth_m, above.compacted_depth_m);
    EXPECT_GE(above.crater.x_min_m, above.compacted_x_min_m);
    EXPECT_LE(above.crater.x_max_m, above.compacted_x_max_m);
  }
}

// Energy: the run's identity KE + W_int + W_damp = W_ext (faces' forces inside W_int) to round-off
// (measured 1e-15 of W_ext; held to 1e-12: the block sums of 10^3-10^4 terms). The faces' law energy
// against their force work and the cut's jump are printed, not asserted: docs/efg.md reports that they do
// not close (the open item of dynamic_cracks.hpp). Threads: 1 and 2 give the same bits.
TEST(BlastSlab, RunEnergyIdentityAndTheSameBitsForOneAndTwoThreads) {
  BlastSlabOptions o = small_slab();
  o.min_points_per_thread = 1;
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const BlastSlabResult a = run_blast_slab(o);
  omp_set_num_threads(2);
  const BlastSlabResult b = run_blast_slab(o);
  omp_set_num_threads(threads);
  EXPECT_EQ(a.run.threads, 1);
  EXPECT_EQ(b.run.threads, 2);
  ASSERT_EQ(a.events.size(), b.events.size());
  for (std::size_t i = 0; i < a.events.size(); ++i) {
    EXPECT_EQ(a.events[i].t_s, b.events[i].t_s);
    EXPECT_EQ(a.events[i].to, b.events[i].to);
  }
  ASSERT_EQ(a.run.u.size(), b.run.u.size());
  EXPECT_EQ(0, std::memcmp(a.run.u.data(), b.run.u.data(), sizeof(double) * std::size_t(a.run.u.size())));
  const BlastEnergySample& e = a.energy.back();
  std::printf("W_ext %.5g KE %.5g W_int %.5g faces' work %.5g dissipated %.5g stored %.5g jump %.5g; balance %.3g of W_ext\n",
              e.external_work_J, e.kinetic_J, e.internal_work_J, e.faces_work_J, e.dissipated_J, e.stored_J, e.energy_jump_J,
              e.balance_J() / e.external_work_J);
  EXPECT_GT(e.external_work_J, 0.0);
  EXPECT_LT(a.max_abs_run_balance_J, 1e-12 * e.external_work_J);
}

TEST(BlastSlab, BadInputIsOneLineNamingTheValue) {
  BlastSlabOptions o = small_slab();
  o.thickness_m = 0.02;
  EXPECT_NE(input_error_of([&] { o.validate(); }).find("slab thickness"), std::string::npos);
  o = small_slab();
  o.charge.width_m = 0.3;
  EXPECT_NE(input_error_of([&] { o.validate(); }).find("charge width"), std::string::npos);
  o = small_slab();
  o.charge.peak_Pa = -1;
  EXPECT_NE(input_error_of([&] { o.validate(); }).find("peak pressure"), std::string::npos);
  o = small_slab();
  o.cracks.crack_speed_limit_m_s = 0;
  EXPECT_NE(input_error_of([&] { o.validate(); }).find("crack speed limit"), std::string::npos);
  for (const std::string& m : {input_error_of([&] { o.validate(); })}) EXPECT_EQ(m.find('\n'), std::string::npos);
  o = small_slab();
  o.crushing_eps_v = -0.05;
  EXPECT_NE(input_error_of([&] { o.validate(); }).find("crushing volumetric strain (-0.05)"), std::string::npos);
  o = small_slab();
  o.dt_s = -1e-6;
  EXPECT_NE(input_error_of([&] { o.validate(); }).find("time step (-1e-06 s)"), std::string::npos);
  o.dt_s = 20e-6;  // the stable step of this slab is about 5 us (10 mm)
  EXPECT_NE(input_error_of([&] { run_blast_slab(o); }).find("exceeds the stable step"), std::string::npos);
}
