// The crater measure (efg/crater) on hand-made states whose crater is known: a crushed block under the loaded
// face, a crushed spot deep inside (not joined to the face: not crater), a piece cut loose at the loaded face by
// open segments (crater), a piece cut loose at the far face (spall), a cut that does not close (no piece). The
// expected depths, widths and areas are the 2 x 2 Gauss rule's own coordinates and weights; and which crack
// faces DynamicCracks reports open (every face point past w_max; traction-free faces).
#include <gtest/gtest.h>

#include <cmath>

#include "mesowave/efg/crater.hpp"
#include "mesowave/efg/discretisation.hpp"
#include "mesowave/efg/dynamic_cracks.hpp"
#include "support/input_error.hpp"

using namespace mesowave;
using namespace mesowave::efg;
using mesowave::test::input_error_of;

namespace {

constexpr double h = 0.01;  // 200 x 60 mm, 10 mm cells
const Rect kBody{0, 0, 0.2, 0.06};
// the 2 x 2 rule in a cell [c, c + h]: its points at c + h/2 (1 -+ 1/sqrt 3)
const double kInset = 0.5 * h * (1 - 1 / std::sqrt(3.0));

bool inside(const Vec2& x, double x0, double x1, double y0, double y1) {
  return x.x() > x0 && x.x() < x1 && x.y() > y0 && x.y() < y1;
}

CraterInput hand_made_state() {
  const Discretisation d = rectangular_grid(kBody, 20, 6, 2);
  CraterInput in;
  in.body = kBody;
  in.link_radius_m = h;
  in.crushing_eps_v = 0.0475;
  for (const GaussPoint& g : d.points) {
    in.x.push_back(g.x);
    in.area_m2.push_back(g.weight_m2);
    double e = -0.01;  // compacted (past e_v,th = 0.008), not crushed
    if (inside(g.x, 0.08, 0.12, 0.04, 0.06)) e = -0.06;   // crushed block under the charge, 40 x 20 mm
    if (inside(g.x, 0.02, 0.03, 0.02, 0.03)) e = -0.08;   // crushed deep inside: not joined to the face
    if (inside(g.x, 0.12, 0.13, 0.05, 0.06)) e = -0.047;  // just below eps_crush, beside the block
    in.min_eps_v.push_back(e);
  }
  // a piece 30 x 30 mm cut loose at the loaded face (the cut runs past the face, as a crack's run-on does)
  in.open_segments.push_back({Vec2(0.14, 0.0605), Vec2(0.14, 0.03)});
  in.open_segments.push_back({Vec2(0.14, 0.03), Vec2(0.17, 0.03)});
  in.open_segments.push_back({Vec2(0.17, 0.03), Vec2(0.17, 0.0605)});
  // a piece 30 x 10 mm cut loose at the far face: spall
  in.open_segments.push_back({Vec2(0.02, -0.0005), Vec2(0.02, 0.01)});
  in.open_segments.push_back({Vec2(0.02, 0.01), Vec2(0.05, 0.01)});
  in.open_segments.push_back({Vec2(0.05, 0.01), Vec2(0.05, -0.0005)});
  // a cut from the loaded face that ends inside (its tip): it frees nothing
  in.open_segments.push_back({Vec2(0.06, 0.0605), Vec2(0.06, 0.02)});
  in.open_segments.push_back({Vec2(0.06, 0.02), Vec2(0.09, 0.02)});
  return in;
}

}  // namespace

TEST(Crater, AHandMadeStateGivesItsCrushedBlockAndItsCutLoosePieceAsTheCrater) {
  const CraterInput in = hand_made_state();
  const CraterMeasure m = measure_crater(in);
  EXPECT_EQ(m.pieces, 3u);  // the slab, the crater's piece, the spall; the open-ended cut frees nothing
  EXPECT_EQ(m.crushed_points, 4u * 2 * 4);         // 4 x 2 cells of 4 points
  EXPECT_EQ(m.crater_fragments, 1u);
  EXPECT_EQ(m.crater_fragment_points, 3u * 3 * 4);  // 3 x 3 cells
  EXPECT_NEAR(m.crushed_area_m2, 0.04 * 0.02, 1e-15);
  EXPECT_NEAR(m.fragment_area_m2, 0.03 * 0.03, 1e-15);
  EXPECT_NEAR(m.area_m2, 0.04 * 0.02 + 0.03 * 0.03, 1e-15);
  // the deepest crater point: the piece's lowest row, 30 mm + the rule's inset above y = 0
  EXPECT_NEAR(m.depth_m, 0.06 - (0.03 + kInset), 1e-14);
  EXPECT_NEAR(m.x_min_m, 0.08 + kInset, 1e-14);
  EXPECT_NEAR(m.x_max_m, 0.17 - kInset, 1e-14);
  EXPECT_NEAR(m.width_m, 0.09 - 2 * kInset, 1e-14);
  EXPECT_EQ(m.spall_fragments, 1u);
  EXPECT_EQ(m.spall_points, 3u * 1 * 4);
  EXPECT_NEAR(m.spall_area_m2, 0.03 * 0.01, 1e-15);
  EXPECT_NEAR(m.spall_depth_m, 0.01 - kInset, 1e-14);
  EXPECT_EQ(m.loose_inside_points, 0u);
  // the deep crushed spot and the point just below eps_crush are intact
  for (std::size_t i = 0; i < in.x.size(); ++i) {
    if (inside(in.x[i], 0.02, 0.03, 0.02, 0.03) || inside(in.x[i], 0.12, 0.13, 0.05, 0.06)) {
      EXPECT_EQ(m.label[i], CraterLabel::intact) << i;
    }
  }
}

TEST(Crater, WithoutOpenCutsTheCraterIsTheCrushedBlockAlone) {
  CraterInput in = hand_made_state();
  in.open_segments.clear();
  const CraterMeasure m = measure_crater(in);
  EXPECT_EQ(m.pieces, 1u);
  EXPECT_EQ(m.crater_fragments + m.spall_fragments, 0u);
  EXPECT_NEAR(m.area_m2, 0.04 * 0.02, 1e-15);
  EXPECT_NEAR(m.depth_m, 0.06 - (0.04 + kInset), 1e-14);
  EXPECT_NEAR(m.width_m, 0.04 - 2 * kInset, 1e-14);
  // a lower crushing strain takes the neighbour at 0.047 in: the block grows by one cell
  in.crushing_eps_v = 0.046;
  EXPECT_NEAR(measure_crater(in).area_m2, 0.04 * 0.02 + 0.01 * 0.01, 1e-15);
}

TEST(Crater, TheDefaultCrushingStrainIsTheYFunctionsMinimum) {
  const HugoniotParameters p;  // Eq. (26)
  const double e = default_crushing_eps_v(p);
  EXPECT_NEAR(e, 0.0475, 5e-5);  // efg/hugoniot.hpp's value for Eq. (26)
  // a minimum of Eq. (25): Y is larger a little to either side
  EXPECT_LT(hugoniot_Y(-e, p), hugoniot_Y(-(e - 1e-3), p));
  EXPECT_LT(hugoniot_Y(-e, p), hugoniot_Y(-(e + 1e-3), p));
}

TEST(Crater, BadInputIsRefusedInOneLine) {
  CraterInput in = hand_made_state();
  in.link_radius_m = 0;
  EXPECT_NE(input_error_of([&] { measure_crater(in); }).find("crater link radius"), std::string::npos);
  in = hand_made_state();
  in.crushing_eps_v = -0.01;
  EXPECT_NE(input_error_of([&] { measure_crater(in); }).find("crushing volumetric strain"), std::string::npos);
  in = hand_made_state();
  in.area_m2.pop_back();
  EXPECT_NE(input_error_of([&] { measure_crater(in); }).find("areas"), std::string::npos);
}

TEST(Crater, DynamicCracksReportTractionFreeFacesOpenAndFreshCohesiveFacesClosed) {
  const Rect body{0, 0, 0.1, 0.05};
  const Discretisation disc = rectangular_grid(body, 10, 5);
  CrackSet cracks;
  const MlsApproximation mls(disc.nodes, support_radii_by_spacing(disc.nodes, disc.spacing_m, 2.5), {}, &cracks);
  const ElasticMaterial2D concrete{20e9, 0.2, 1.0, 2400, PlaneState::plane_strain};
  ElasticModel model(disc, concrete, mls);
  DynamicCrackOptions o;
  o.cohesive.f_t_Pa = 2.4e6;
  o.cohesive.G_f_J_m2 = 113;
  o.strain_rate.f_cm_Pa = 30.4e6;
  DynamicCracks dc(model, cracks, o);
  dc.add_crack({Vec2(0.0251, 0.0505), Vec2(0.0251, 0.0303)}, false, false);  // cohesive: w_hist = w_initial < w_max
  EXPECT_TRUE(dc.open_segments().empty());
  EXPECT_GT(dc.face_w_max_m(0), dc.face_points()[0].w_hist_m);
  dc.add_crack({Vec2(0.0751, 0.0505), Vec2(0.0751, 0.0303)}, true, false);  // traction-free: open from the start
  const std::vector<Segment> open = dc.open_segments();
  ASSERT_FALSE(open.empty());
  for (const Segment& s : open) {
    EXPECT_DOUBLE_EQ(s.a.x(), 0.0751);
    EXPECT_DOUBLE_EQ(s.b.x(), 0.0751);
  }
  EXPECT_EQ(dc.face_w_max_m(dc.face_points().size() - 1), 0.0);
}
