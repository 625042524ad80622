// Cracks that cut the MLS weights (efg/crack.hpp, Eq. (13)) against closed forms: the weight
// distances of visibility, diffraction and transparency for a node and point on either side of a
// straight crack, their gradients against central differences; with the MLS approximation: no
// coupling across a crack that cuts the body in two (a field discontinuous across it is reproduced
// on both sides), linear reproduction beside an edge notch with the hidden nodes' phi = 0, and the
// jump of the shape functions across the shadow line beyond the tip: O(1) with visibility, -> 0 as
// the points approach with diffraction and transparency.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <map>

#include "mesowave/efg/crack.hpp"
#include "mesowave/efg/mls.hpp"
#include "support/efg_fixtures.hpp"
#include "support/input_error.hpp"

using namespace mesowave;
using namespace mesowave::efg;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// A straight crack along y = 0 from (-2, 0) to its tip (1, 0).
CrackSet straight_crack() {
  CrackSet cracks;
  cracks.add({{Vec2(-2, 0), Vec2(1, 0)}, false, true});
  return cracks;
}

// The body [0, 0.3] x [0, 0.2] m, 7 x 5 nodes (spacing 0.05 m), irregular inside; supports 2.5 spacings.
constexpr double kLx = 0.30, kLy = 0.20, kSpacing = 0.05;
const std::vector<Vec2> kNodes = test::grid_nodes(6, 4, kLx, kLy, 0.3);

// An edge notch from below the bottom edge up to a tip inside the body, off every node line.
Crack notch() { return {{Vec2(0.1237, -0.01), Vec2(0.1263, 0.1113)}, false, true}; }

MlsApproximation mls_with(const CrackSet& cracks, CrackWeightMethod method) {
  MlsOptions options;
  options.crack_method = method;
  return MlsApproximation(kNodes, support_radii_by_spacing(kNodes, kSpacing, 2.5), options, &cracks);
}

// phi by node index (0 for nodes not in reach).
std::map<std::int32_t, double> phi_by_node(const ShapeFunctions& sf) {
  std::map<std::int32_t, double> out;
  for (std::size_t k = 0; k < sf.nodes.size(); ++k) out[sf.nodes[k]] = sf.phi[k];
  return out;
}
double largest_jump(const ShapeFunctions& a, const ShapeFunctions& b) {
  auto pa = phi_by_node(a), pb = phi_by_node(b);
  double jump = 0;
  for (const auto& [i, v] : pa) jump = std::max(jump, std::abs(v - (pb.count(i) ? pb[i] : 0.0)));
  for (const auto& [i, v] : pb) jump = std::max(jump, std::abs(v - (pa.count(i) ? pa[i] : 0.0)));
  return jump;
}

}  // namespace

TEST(Crack, AddExtendAndVersion) {
  CrackSet cracks;
  EXPECT_EQ(cracks.version(), 0u);
  const auto k = cracks.add({{Vec2(0, 0), Vec2(0, 1)}, false, true});
  EXPECT_EQ(cracks.version(), 1u);
  cracks.extend(k, Vec2(0.1, 1.5));
  EXPECT_EQ(cracks.version(), 2u);
  ASSERT_EQ(cracks.cracks()[k].points.size(), 3u);
  EXPECT_EQ(cracks.cracks()[k].points.back(), Vec2(0.1, 1.5));
  const auto s = cracks.add({{Vec2(1, 0), Vec2(1, 1)}, true, false});  // tip at the start
  cracks.extend(s, Vec2(1, -1));
  EXPECT_EQ(cracks.cracks()[s].points.front(), Vec2(1, -1));
  EXPECT_NE(test::input_error_of([&] { cracks.add({{Vec2(0, 0)}, false, true}); }).find("1 points"), std::string::npos);
  EXPECT_NE(test::input_error_of([&] { cracks.add({{Vec2(0, 0), Vec2(0, 0)}, false, true}); }).find("zero-length"),
            std::string::npos);
  const auto through = cracks.add({{Vec2(2, 0), Vec2(2, 1)}, false, false});
  EXPECT_NE(test::input_error_of([&] { cracks.extend(through, Vec2(2, 2)); }).find("no tip"), std::string::npos);
  EXPECT_NE(test::input_error_of([&] { cracks.extend(9, Vec2(2, 2)); }).find("crack 9"), std::string::npos);
  EXPECT_EQ(cracks.tip(k), Vec2(0.1, 1.5));
  EXPECT_EQ(cracks.tip(s), Vec2(1, -1));
  EXPECT_NEAR(cracks.distance(Vec2(0.5, 0.5)), 0.5, 1e-15);   // to the segment (0, 0)-(0, 1)
  EXPECT_NEAR(cracks.distance(Vec2(1.3, -1.4)), 0.5, 1e-15);  // to the end point (1, -1)
  EXPECT_EQ(CrackSet().distance(Vec2(0, 0)), kInf);
  EXPECT_EQ(parse_crack_weight_method("diffraction"), CrackWeightMethod::diffraction);
  EXPECT_NE(test::input_error_of([] { parse_crack_weight_method("opaque"); }).find("'opaque'"), std::string::npos);
}

// A crack as the user places it must lie in the body; only its mouth may touch the boundary, on the face where it
// opens (an edge notch from the bottom face). The body [0, 0.3] x [0, 0.2] m.
TEST(Crack, APolylineThatLeavesTheBodyOrStartsOutsideIsRefused) {
  const Rect body{0, 0, kLx, kLy};
  auto error = [&](std::vector<Vec2> line, BodyFace mouth) {
    return test::input_error_of([&] { require_crack_inside(line, body, mouth, "notch"); });
  };
  // legal: an edge notch opening on the bottom face, a kinked one, an interior crack
  EXPECT_EQ(error({Vec2(0.15, 0), Vec2(0.15, 0.05)}, BodyFace::bottom), "");
  EXPECT_EQ(error({Vec2(0.15, 0), Vec2(0.15, 0.05), Vec2(0.2, 0.19)}, BodyFace::bottom), "");
  EXPECT_EQ(error({Vec2(0.3, 0.1), Vec2(0.2, 0.1)}, BodyFace::right), "");
  EXPECT_EQ(error({Vec2(0.1, 0.1), Vec2(0.2, 0.1)}, BodyFace::none), "");
  // starts outside (below the bottom face; beyond the right end)
  EXPECT_EQ(error({Vec2(0.15, -0.01), Vec2(0.15, 0.05)}, BodyFace::bottom),
            "notch: point 0 (0.15, -0.01) m lies outside the body [0, 0.3] x [0, 0.2] m");
  EXPECT_EQ(error({Vec2(0.35, 0), Vec2(0.35, 0.05)}, BodyFace::bottom),
            "notch: point 0 (0.35, 0) m lies outside the body [0, 0.3] x [0, 0.2] m");
  // leaves the body: a point beyond the top face or the right end, after a legal start
  EXPECT_EQ(error({Vec2(0.15, 0), Vec2(0.15, 0.05), Vec2(0.15, 0.25)}, BodyFace::bottom),
            "notch: point 2 (0.15, 0.25) m lies outside the body [0, 0.3] x [0, 0.2] m");
  EXPECT_NE(error({Vec2(0.15, 0), Vec2(0.31, 0.1)}, BodyFace::bottom).find("point 1 (0.31, 0.1) m lies outside"),
            std::string::npos);
  // touches the boundary elsewhere: its tip on the top face (a cut through the depth), back on the bottom face, a
  // mouth at a corner or on a face it does not open on, or a mouth when none is allowed
  EXPECT_EQ(error({Vec2(0.15, 0), Vec2(0.15, 0.2)}, BodyFace::bottom),
            "notch: point 1 (0.15, 0.2) m lies on the boundary of the body [0, 0.3] x [0, 0.2] m (only the first "
            "point may, on the bottom face where the crack opens)");
  EXPECT_NE(error({Vec2(0.1, 0), Vec2(0.15, 0.05), Vec2(0.2, 0)}, BodyFace::bottom).find("point 2"), std::string::npos);
  EXPECT_NE(error({Vec2(0, 0), Vec2(0.05, 0.05)}, BodyFace::bottom).find("point 0 (0, 0) m lies on the boundary"),
            std::string::npos);
  EXPECT_NE(error({Vec2(0, 0.1), Vec2(0.05, 0.1)}, BodyFace::bottom).find("point 0 (0, 0.1) m lies on the boundary"),
            std::string::npos);
  EXPECT_EQ(error({Vec2(0.15, 0), Vec2(0.15, 0.05)}, BodyFace::none),
            "notch: point 0 (0.15, 0) m lies on the boundary of the body [0, 0.3] x [0, 0.2] m (the crack must lie inside)");
  // within the tolerance (1e-9 of the larger side) a point on a face counts as on it
  EXPECT_EQ(error({Vec2(0.15, -1e-11), Vec2(0.15, 0.05)}, BodyFace::bottom), "");
  EXPECT_NE(error({Vec2(0.15, 0), Vec2(0.15, std::nan(""))}, BodyFace::bottom).find("not finite"), std::string::npos);
  EXPECT_NE(error({Vec2(0.15, 0)}, BodyFace::bottom).find("1 points"), std::string::npos);
}

TEST(Crack, WeightDistancesMatchTheirClosedForms) {
  const CrackSet cracks = straight_crack();
  const Vec2 node(0, -1), x(0, 1);  // s0 = 2, s1 = s2 = sqrt 2 around the tip (1, 0)
  EXPECT_TRUE(cracks.hides(node, x));
  EXPECT_FALSE(cracks.hides(node, Vec2(2, 0.5)));  // passes beside the tip
  EXPECT_DOUBLE_EQ(cracks.weight_distance(node, Vec2(0, -0.5), CrackWeightMethod::visibility), 0.5);
  EXPECT_EQ(cracks.weight_distance(node, x, CrackWeightMethod::visibility), kInf);
  // Organ et al.: d = ((s1 + s2) / s0)^lambda s0 = (2 sqrt 2 / 2)^2 2 = 4; lambda = 1: the bent path.
  EXPECT_NEAR(cracks.weight_distance(node, x, CrackWeightMethod::diffraction), 4.0, 1e-14);
  EXPECT_NEAR(cracks.weight_distance(node, x, CrackWeightMethod::diffraction, 1.0), 2 * std::sqrt(2.0), 1e-14);
  // Transparency: crossing at (0, 0), s_c = 1; h = 2, s_bar = 2, kappa = 2: d = 2 + 2 (1/2)^2 = 2.5.
  const auto t = cracks.weight_distance_gradient(node, x, CrackWeightMethod::transparency, 2, 2.0, {2.0, 2.0});
  EXPECT_NEAR(t.d, 2.5, 1e-14);
  // ... opaque beyond s_bar from the tip (s_c = 1 >= 0.9).
  EXPECT_TRUE(cracks.weight_distance_gradient(node, x, CrackWeightMethod::transparency, 2, 2.0, {0.9, 2.0}).cut());
  EXPECT_NE(test::input_error_of([&] { cracks.weight_distance_gradient(node, x, CrackWeightMethod::transparency); }).find("h_I"),
            std::string::npos);
}

TEST(Crack, DiffractionIsCutWhenNoTipIsInReach) {
  CrackSet through;  // no tips: a crack that runs through the body
  through.add({{Vec2(-2, 0), Vec2(2, 0)}, false, false});
  EXPECT_EQ(through.weight_distance(Vec2(0, -1), Vec2(0, 1), CrackWeightMethod::diffraction), kInf);
  CrackSet blocked = straight_crack();  // the path around the tip crosses a second crack
  blocked.add({{Vec2(0.5, 0.2), Vec2(1.5, 0.2)}, false, false});
  EXPECT_EQ(blocked.weight_distance(Vec2(0, -1), Vec2(0, 1), CrackWeightMethod::diffraction), kInf);
  CrackSet two = straight_crack();  // two cracks between node and point
  two.add({{Vec2(-1, 0.5), Vec2(0.5, 0.5)}, false, true});
  EXPECT_EQ(two.weight_distance(Vec2(0, -1), Vec2(0, 1), CrackWeightMethod::diffraction), kInf);
  // A polyline crack: the tip (1, 0.5), a segment away from the crossing, still bends the path.
  CrackSet kinked;
  kinked.add({{Vec2(-2, 0), Vec2(0.5, 0), Vec2(1, 0.5)}, false, true});
  EXPECT_NEAR(kinked.weight_distance(Vec2(0, -1), Vec2(0, 1), CrackWeightMethod::diffraction, 1.0),
              std::sqrt(1 + 1.5 * 1.5) + std::sqrt(1 + 0.5 * 0.5), 1e-14);
}

TEST(Crack, WeightDistanceGradientsMatchCentralDifferences) {
  // delta = 1e-6 on distances of order 1: truncation ~ delta^2 d''' ~ 1e-12, rounding ~ 1e-10.
  CrackSet cracks;
  cracks.add({{Vec2(-2, 0.1), Vec2(0.3, 0), Vec2(1, 0.05)}, false, true});
  const Vec2 node(0.2, -0.7);
  for (const auto method : {CrackWeightMethod::visibility, CrackWeightMethod::diffraction, CrackWeightMethod::transparency})
    for (const Vec2& x : {Vec2(0.4, 0.6), Vec2(0.9, 0.3), Vec2(-0.3, 0.8), Vec2(1.3, -0.2)}) {
      const auto at = [&](const Vec2& p) {
        return cracks.weight_distance_gradient(node, p, method, 2.0, 3.0, {1.5, 2.0});
      };
      const auto d = at(x);
      if (d.cut()) {
        EXPECT_EQ(method, CrackWeightMethod::visibility);
        continue;
      }
      const double h = 1e-6;
      EXPECT_NEAR(d.gradient.x(), (at(x + Vec2(h, 0)).d - at(x - Vec2(h, 0)).d) / (2 * h), 1e-8) << to_string(method);
      EXPECT_NEAR(d.gradient.y(), (at(x + Vec2(0, h)).d - at(x - Vec2(0, h)).d) / (2 * h), 1e-8) << to_string(method);
    }
}

TEST(Crack, NoCouplingAcrossACrackThroughTheBody) {
  // A kinked crack from below the body to above it: two bodies. A field linear on each side with a
  // jump across the crack is reproduced exactly on both sides; no node of the other side reaches.
  CrackSet cracks;
  cracks.add({{Vec2(0.1237, -0.01), Vec2(0.14, 0.1), Vec2(0.1337, 0.21)}, false, false});
  const auto left = [&](const Vec2& p) { return !cracks.hides(Vec2(-1, p.y()), p); };
  const auto u = [&](const Vec2& p) { return left(p) ? 1 + 2 * p.x() - p.y() : -3 + p.x() + 4 * p.y(); };
  for (const auto method : {CrackWeightMethod::visibility, CrackWeightMethod::diffraction, CrackWeightMethod::transparency}) {
    const auto mls = mls_with(cracks, method);
    const auto points = test::gauss_points(2, 2, 4, kLx, kLy);
    int on_left = 0;
    for (std::size_t g = 0; g < points.size(); ++g) {
      const Vec2& x = points[g];
      const auto sf = mls.evaluate(x, "Gauss point " + std::to_string(g));
      double value = 0, ux = 0, uy = 0;
      for (std::size_t k = 0; k < sf.nodes.size(); ++k) {
        const Vec2& xi = kNodes[std::size_t(sf.nodes[k])];
        EXPECT_EQ(left(xi), left(x)) << "node " << sf.nodes[k] << " couples across the crack at Gauss point " << g;
        value += sf.phi[k] * u(xi);
        ux += sf.dphi_dx[k] * u(xi);
        uy += sf.dphi_dy[k] * u(xi);
      }
      EXPECT_NEAR(value, u(x), 1e-12) << "Gauss point " << g;
      EXPECT_NEAR(ux, left(x) ? 2.0 : 1.0, 1e-12) << "Gauss point " << g;
      EXPECT_NEAR(uy, left(x) ? -1.0 : 4.0, 1e-12) << "Gauss point " << g;
      on_left += left(x);
    }
    EXPECT_GT(on_left, 10);
    EXPECT_LT(on_left, int(points.size()) - 10);
  }
}

TEST(Crack, LinearFieldsReproducedBesideANotchWithHiddenNodesCut) {
  CrackSet cracks;
  cracks.add(notch());
  for (const auto method : {CrackWeightMethod::visibility, CrackWeightMethod::diffraction, CrackWeightMethod::transparency}) {
    const auto mls = mls_with(cracks, method);
    int hidden_seen = 0;
    for (const Vec2& x : test::gauss_points(2, 2, 4, kLx, kLy)) {
      const auto sf = mls.evaluate(x);
      double sum = 0, sx = 0, sy = 0, dsum = 0, dxx = 0, dyy = 0;
      for (std::size_t k = 0; k < sf.nodes.size(); ++k) {
        const Vec2& xi = kNodes[std::size_t(sf.nodes[k])];
        sum += sf.phi[k];
        sx += sf.phi[k] * xi.x();
        sy += sf.phi[k] * xi.y();
        dsum += sf.dphi_dx[k];
        dxx += sf.dphi_dx[k] * xi.x();
        dyy += sf.dphi_dy[k] * xi.y();
        // Under visibility every node behind the notch has phi = 0 (it is not in reach at all).
        if (method == CrackWeightMethod::visibility) {
          EXPECT_FALSE(cracks.hides(xi, x));
        }
        hidden_seen += cracks.hides(xi, x);
      }
      EXPECT_NEAR(sum, 1.0, 1e-12);
      EXPECT_NEAR(sx, x.x(), 1e-12);
      EXPECT_NEAR(sy, x.y(), 1e-12);
      EXPECT_NEAR(dsum, 0.0, 1e-11);
      EXPECT_NEAR(dxx, 1.0, 1e-11);
      EXPECT_NEAR(dyy, 1.0, 1e-11);
    }
    // Diffraction and transparency let nodes behind the notch reach round its tip; visibility does not.
    if (method == CrackWeightMethod::visibility) EXPECT_EQ(hidden_seen, 0);
    else EXPECT_GT(hidden_seen, 0);
  }
}

TEST(Crack, ShapeFunctionsAcrossTheShadowLineBeyondTheTip) {
  // Node I left of the notch, below its tip; the shadow line runs from I through the tip into the
  // body. Two points either side of it, eps apart: visibility jumps O(1) whatever eps, diffraction
  // and transparency close the jump like eps.
  CrackSet cracks;
  cracks.add(notch());
  const Vec2 tip = notch().points.back();
  const std::size_t node = 7 * 1 + 2;  // grid node (2, 1), near (0.1, 0.05)
  const Vec2 xi = kNodes[node];
  ASSERT_LT(xi.x(), 0.1237);
  const Vec2 along = (tip - xi).normalized(), normal(-along.y(), along.x());
  const Vec2 x0 = tip + 0.02 * along;  // on the shadow line, 0.02 m beyond the tip
  for (const auto method : {CrackWeightMethod::visibility, CrackWeightMethod::diffraction, CrackWeightMethod::transparency}) {
    const auto mls = mls_with(cracks, method);
    std::vector<double> jumps;
    for (const double eps : {1e-3, 1e-5, 1e-7}) {
      const auto a = mls.evaluate(x0 + eps * normal), b = mls.evaluate(x0 - eps * normal);
      jumps.push_back(largest_jump(a, b));
      // The node itself is seen from one side only under visibility.
      const auto pa = phi_by_node(a), pb = phi_by_node(b);
      if (method == CrackWeightMethod::visibility) {
        EXPECT_NE(pa.count(std::int32_t(node)), pb.count(std::int32_t(node)));
      }
    }
    if (method == CrackWeightMethod::visibility) {
      for (const double j : jumps) EXPECT_GT(j, 5e-3);  // phi of node I there, ~0.01: it does not fall with eps
      EXPECT_GT(jumps[2], 0.5 * jumps[0]);
    } else {
      // Continuous phi with bounded derivatives: jump <= 2 eps max |dphi| (max |dphi| ~ 10 / m).
      EXPECT_LT(jumps[0], 1e-3 * 100);
      EXPECT_LT(jumps[1], 1e-5 * 100);
      EXPECT_LT(jumps[2], 1e-7 * 100);
      EXPECT_LT(jumps[2], jumps[0] * 1e-3);  // falls like eps
    }
    std::cout << to_string(method) << ": jump of phi across the shadow line " << jumps[0] << ", " << jumps[1] << ", "
              << jumps[2] << " at eps = 1e-3, 1e-5, 1e-7 m\n";
  }
}

TEST(Crack, ShapeFunctionDerivativesNearTheTipMatchCentralDifferences) {
  // As in the MLS test: delta = 1e-6 m against supports of 0.125 m, tolerance 1e-6 on derivatives
  // of order 10 per metre (the bent distance adds curvature ~ 1/|x - x_c|, so 10x the MLS test's).
  CrackSet cracks;
  cracks.add(notch());
  for (const auto method : {CrackWeightMethod::diffraction, CrackWeightMethod::transparency}) {
    const auto mls = mls_with(cracks, method);
    for (const Vec2& x : {Vec2(0.14, 0.1), Vec2(0.11, 0.09), Vec2(0.15, 0.14)}) {
      const auto check = test::check_derivatives(mls, x, 1e-6);
      EXPECT_LT(check.error, 1e-6) << to_string(method) << " at (" << x.x() << ", " << x.y() << ")";
      EXPECT_GT(check.largest, 1.0);
      int bent = 0;
      for (const auto i : mls.evaluate(x).nodes) bent += cracks.hides(kNodes[std::size_t(i)], x);
      EXPECT_GT(bent, 0);  // some weights are bent round the tip at this point
    }
  }
}

TEST(Crack, TooFewVisibleNodesBesideANotchNamesThePoint) {
  // Supports of 1.2 spacings: beside the notch face, visibility leaves fewer than 3 nodes.
  CrackSet cracks;
  cracks.add(notch());
  MlsOptions options;
  const MlsApproximation mls(kNodes, support_radii_by_spacing(kNodes, kSpacing, 1.2), options, &cracks);
  const std::string message = test::input_error_of([&] { mls.evaluate(Vec2(0.127, 0.03), "Gauss point 2 of cell 9"); });
  EXPECT_NE(message.find("x = (0.127, 0.03) m (Gauss point 2 of cell 9)"), std::string::npos) << message;
  EXPECT_NE(message.find("nodes reach the point, the linear basis needs at least 3"), std::string::npos) << message;
  // The same point on the same nodes without the notch is fine.
  EXPECT_NO_THROW(MlsApproximation(kNodes, support_radii_by_spacing(kNodes, kSpacing, 1.2)).evaluate(Vec2(0.127, 0.03)));
}

TEST(Crack, AGrownCrackTakesEffectAtOnce) {
  CrackSet cracks;
  const auto k = cracks.add({{Vec2(0.1237, -0.01), Vec2(0.1263, 0.06)}, false, true});
  const auto mls = mls_with(cracks, CrackWeightMethod::visibility);
  const Vec2 x(0.14, 0.1);
  const auto before = mls.evaluate(x);
  cracks.extend(k, Vec2(0.127, 0.13));
  const auto after = mls.evaluate(x);
  EXPECT_LT(after.nodes.size(), before.nodes.size());
}
