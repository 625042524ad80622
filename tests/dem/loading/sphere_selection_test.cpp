// Which spheres a patch, a point or a line's end selects (sphere_selection.hpp),
// checked on hand-placed spheres whose answer is known by construction.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mesowave/core/error.hpp"
#include "mesowave/dem/loading/sphere_selection.hpp"
#include "dem/test_packings.hpp"

using namespace mesowave::dem;

namespace {

// A 4 x 4 x 2 grid of 1 mm spheres, centres 2 mm apart from (1, 1, 1) mm, and
// one small sphere (0.5 mm) sunk 0.8 mm below the top layer's surface plane.
SphereSet grid() {
  Packing p;
  std::int64_t id = 0;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i) {
        p.centres_m.push_back({1e-3 + 2e-3 * i, 1e-3 + 2e-3 * j, 1e-3 + 2e-3 * k});
        p.radii_m.push_back(1e-3);
        p.ids.push_back(id++);
      }
  p.centres_m.push_back({4e-3, 4e-3, 4e-3 - 0.8e-3 - 0.5e-3});
  p.radii_m.push_back(0.5e-3);
  p.ids.push_back(id++);
  return make_sphere_set(p, 2000);
}

std::vector<std::int64_t> ids(const SphereSet& s, const std::vector<std::size_t>& chosen) {
  std::vector<std::int64_t> out;
  for (std::size_t k : chosen) out.push_back(std::int64_t(s.packing_index[k]));
  return out;
}

}  // namespace

TEST(SphereSelection, FacesParseNameAndPointOutward) {
  for (const char* text : {"x-", "x+", "y-", "y+", "z-", "z+"}) EXPECT_EQ(Face::parse(text).name(), text);
  const Face f = Face::parse("y+");
  EXPECT_EQ(f.axis, 1);
  EXPECT_TRUE(f.upper);
  EXPECT_EQ(f.outward_normal().y, 1.0);
  EXPECT_EQ(Face::parse("z-").outward_normal().z, -1.0);
  EXPECT_EQ(f.in_plane(0), 0);
  EXPECT_EQ(f.in_plane(1), 2);
  EXPECT_EQ(Face::parse("x-").in_plane(0), 1);
  EXPECT_EQ(Face::parse("x-").in_plane(1), 2);
  for (const char* bad : {"x", "w+", "x+-", "X+", ""}) EXPECT_THROW(Face::parse(bad), mesowave::InputError) << bad;
}

TEST(SphereSelection, BoundingBoxHoldsTheSurfaces) {
  const SphereSet s = grid();
  const Box b = bounding_box(s);
  EXPECT_DOUBLE_EQ(b.lower.x, 0.0);
  EXPECT_DOUBLE_EQ(b.upper.x, 8e-3);
  EXPECT_DOUBLE_EQ(b.upper.y, 8e-3);
  EXPECT_DOUBLE_EQ(b.upper.z, 4e-3);
  EXPECT_DOUBLE_EQ(b.lower.z, 0.0);
}

TEST(SphereSelection, PatchTakesTheSpheresUnderItWithinItsDepth) {
  const SphereSet s = grid();
  const Box box = bounding_box(s);
  Patch p;
  p.face = Face::parse("z+");
  p.centre_m = {4e-3, 4e-3, 0};  // the coordinate along the normal is ignored
  p.size_m[0] = p.size_m[1] = 4.5e-3;  // centres within 2.25 mm: x, y in {3, 5} mm
  // Depth: the smallest radius (0.5 mm) - the sunk sphere (0.8 mm down) is out.
  EXPECT_EQ(ids(s, spheres_under_patch(s, box, p, "t")), (std::vector<std::int64_t>{21, 22, 25, 26}));
  p.depth_m = 0.9e-3;
  EXPECT_EQ(ids(s, spheres_under_patch(s, box, p, "t")), (std::vector<std::int64_t>{21, 22, 25, 26, 32}));
  // The same patch as fractions of the box.
  p.depth_m = -1;
  p.relative = true;
  p.centre_rel = {0.5, 0.5, 1.0};
  EXPECT_EQ(ids(s, spheres_under_patch(s, box, p, "t")), (std::vector<std::int64_t>{21, 22, 25, 26}));
  EXPECT_DOUBLE_EQ(patch_centre(p, box).x, 4e-3);
  // The lower x face: the first column (x = 1 mm), y and z within the patch.
  Patch side;
  side.face = Face::parse("x-");
  side.centre_m = {0, 1e-3, 1e-3};
  side.size_m[0] = side.size_m[1] = 1e-3;
  EXPECT_EQ(ids(s, spheres_under_patch(s, box, side, "t")), (std::vector<std::int64_t>{0}));
  side.centre_m = {0, 20e-3, 1e-3};
  EXPECT_THROW(spheres_under_patch(s, box, side, "actuator a"), mesowave::InputError);
}

TEST(SphereSelection, NearestSphereAndLineEnds) {
  const SphereSet s = grid();
  EXPECT_EQ(s.packing_index[sphere_nearest(s, {5.1e-3, 2.9e-3, 3.2e-3})], 22u);  // (5, 3, 3) mm
  EXPECT_EQ(s.packing_index[sphere_nearest(s, {4e-3, 4e-3, 2.5e-3})], 32u);      // the sunk sphere
  // Equidistant from spheres 0 and 1: the lower packing index.
  EXPECT_EQ(s.packing_index[sphere_nearest(s, {2e-3, 1e-3, 1e-3})], 0u);
  const SphereSet line = make_sphere_set(mesowave::dem::testing::line_packing(7, 1e-3, 2e-3, 2000), 2000);
  EXPECT_EQ(line.packing_index[sphere_at_end(line, false)], 0u);
  EXPECT_EQ(line.packing_index[sphere_at_end(line, true)], 6u);
}

// The curved face of a cylinder: a ring of twelve 1 mm spheres touching the surface of
// radius 10 mm every 30 degrees (at two heights), and one sphere on the axis. A 6 mm
// (arc) x 3 mm patch at azimuth 90 degrees takes the ring sphere there at the patch's
// height only: its neighbours lie 2 pi 10 mm / 12 = 5.2 mm of arc away, beyond the
// patch's 3 mm half-width; the axis sphere lies 8 mm inside, beyond the depth.
TEST(SphereSelection, CurvedFaceTakesTheSpheresUnderTheArc) {
  Packing p;
  std::int64_t id = 0;
  const double R = 10e-3, r = 1e-3;
  for (double z : {1e-3, 5e-3})
    for (int k = 0; k < 12; ++k) {
      const double phi = k * std::numbers::pi / 6;
      p.centres_m.push_back({R + (R - r) * std::cos(phi), R + (R - r) * std::sin(phi), z});
      p.radii_m.push_back(r);
      p.ids.push_back(id++);
    }
  p.centres_m.push_back({R, R, 3e-3});
  p.radii_m.push_back(r);
  p.ids.push_back(id++);
  const SphereSet s = make_sphere_set(p, 2000);
  const Box box = bounding_box(s);
  EXPECT_THROW(Face::parse("curved"), mesowave::InputError);  // only where the caller places patches on it
  Patch patch;
  patch.face = Face::parse("curved", true);
  EXPECT_TRUE(patch.face.curved);
  EXPECT_EQ(patch.face.name(), "curved");
  patch.face.azimuth_rad = std::numbers::pi / 2;
  patch.relative = true;
  patch.centre_rel = {0.5, 1.0, 5e-3 / box.upper.z};
  patch.size_m[0] = 6e-3;
  patch.size_m[1] = 3e-3;
  EXPECT_EQ(ids(s, spheres_under_patch(s, box, patch, "C")), (std::vector<std::int64_t>{15}));  // k = 3 of the upper ring
  const Vec3 n = patch.face.outward_normal();
  EXPECT_NEAR(n.x, 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(n.y, 1.0);
  // An arc wide enough for the neighbours (2 x 5.3 mm) takes them too, in packing order.
  patch.size_m[0] = 10.6e-3;
  EXPECT_EQ(ids(s, spheres_under_patch(s, box, patch, "C")), (std::vector<std::int64_t>{14, 15, 16}));
  // Across the axis (azimuth -90 degrees: y = 0).
  patch.centre_rel = {0.5, 0.0, 1e-3 / box.upper.z};
  patch.size_m[0] = 6e-3;
  EXPECT_EQ(ids(s, spheres_under_patch(s, box, patch, "C")), (std::vector<std::int64_t>{9}));
}

// A line of spheres along z at a spacing below one radius (d = 0.95 R, the rod paper's first
// chain, Table 1): on the end faces z- and z+ a patch takes the end sphere alone once it knows
// the line. By depth alone it takes the next sphere too, whose surface lies d = 0.95 R from the
// face, inside the default depth (the smallest radius, R). Hand-placed: the answer is the first
// and the last sphere by construction.
TEST(SphereSelection, APatchOnAnEndOfALineTakesTheEndSphere) {
  const double r = 1e-3, d = 0.95 * r;
  Packing p;
  for (std::int64_t i = 0; i < 7; ++i) {
    p.centres_m.push_back({r, r, r + double(i) * d});
    p.radii_m.push_back(r);
    p.ids.push_back(i);
  }
  const SphereSet s = make_sphere_set(p, 2000);
  const Box box = bounding_box(s);
  const Vec3 axis{0, 0, 1};
  Patch lower;
  lower.face = Face::parse("z-");
  lower.relative = true;
  lower.centre_rel = {0.5, 0.5, 0.0};
  lower.size_m[0] = lower.size_m[1] = 0.2e-3;
  EXPECT_EQ(ids(s, spheres_under_patch(s, box, lower, "A", axis)), (std::vector<std::int64_t>{0}));
  EXPECT_EQ(ids(s, spheres_under_patch(s, box, lower, "A")), (std::vector<std::int64_t>{0, 1}));  // depth alone
  Patch upper = lower;
  upper.face = Face::parse("z+");
  upper.centre_rel.z = 1.0;
  EXPECT_EQ(ids(s, spheres_under_patch(s, box, upper, "S", axis)), (std::vector<std::int64_t>{6}));
  // The line's axis may point either way: the face says which end.
  EXPECT_EQ(ids(s, spheres_under_patch(s, box, upper, "S", Vec3{0, 0, -1})), (std::vector<std::int64_t>{6}));
  // An explicit depth keeps the depth rule: 2 R reaches the spheres whose surface is within 2 R
  // of the face, centres at r + i d <= 3 r: i = 0, 1, 2.
  Patch deep = lower;
  deep.depth_m = 2 * r;
  EXPECT_EQ(ids(s, spheres_under_patch(s, box, deep, "A", axis)), (std::vector<std::int64_t>{0, 1, 2}));
  // Off the axis the end sphere is not under the patch: refused, as any empty patch.
  Patch off = lower;
  off.centre_rel = {0.9, 0.5, 0.0};  // 0.8 mm from the axis, the patch 0.1 mm across either side
  EXPECT_THROW(spheres_under_patch(s, box, off, "A", axis), mesowave::InputError);
  // A side face runs along the line: every sphere touches it, the rule does not apply.
  Patch side;
  side.face = Face::parse("x-");
  side.relative = true;
  side.centre_rel = {0.0, 0.5, 0.5};
  side.size_m[0] = 0.2e-3;
  side.size_m[1] = 3.5 * d;  // centres within 1.75 d of the middle sphere (i = 3): i = 2, 3, 4
  EXPECT_EQ(ids(s, spheres_under_patch(s, box, side, "B", axis)), (std::vector<std::int64_t>{2, 3, 4}));
}
