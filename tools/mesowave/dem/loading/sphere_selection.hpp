#pragma once
// Which spheres an actuator drives or a sensor reads: those under a
// rectangular patch on a face of the specimen (a PZT glued on the surface),
// the one nearest to a point, or the first/last sphere of a line. A face is
// one of a box's six (a cylinder's flat ends are z- and z+ of its bounding
// box) or a cylinder's curved face (experiment/experiment.hpp's shapes).
// On several ranks the spheres are a rank's part of the set (SpherePart): each call is then
// collective, and every rank gets the same whole indices.
#include <optional>
#include <string>
#include <vector>

#include "mesowave/dem/engine/sphere_part.hpp"
#include "mesowave/dem/engine/vec3.hpp"

namespace mesowave::dem {

/// Faces of an axis-aligned box: "x-" is the plane x = x_min, "x+" x = x_max, ...;
/// or "curved": the lateral face of a cylinder whose axis is parallel to z through the
/// centre of the packing's bounding box (mw-pack's cylinder), radius half its x extent.
struct Face {
  int axis = 0;       ///< 0, 1, 2
  bool upper = false; ///< the + face
  bool curved = false;     ///< the cylinder's curved face (axis and upper unused)
  double azimuth_rad = 0;  ///< curved: where around the axis the patch sits (from +x towards +y)
  /// InputError for anything but x-, x+, y-, y+, z-, z+ (and curved, where the caller places patches on it).
  static Face parse(const std::string& text, bool allow_curved = false);
  std::string name() const;
  Vec3 outward_normal() const;  ///< curved: the radial direction at azimuth_rad
  /// The two in-plane axes in increasing order (for x faces: y, z).
  int in_plane(int which) const { return which == 0 ? (axis == 0 ? 1 : 0) : (axis == 2 ? 1 : 2); }
};

struct Box {
  Vec3 lower, upper;
};

/// The box the sphere surfaces fill: min(x - r) to max(x + r) per axis.
Box bounding_box(const SpherePart& spheres);

struct Patch {
  Face face;
  Vec3 centre_m;               ///< a point on the face (its coordinate along the face normal is ignored) ...
  bool relative = false;       ///< ... or, if set, centre_rel: fractions of the bounding box (0 lower, 1 upper face)
  Vec3 centre_rel;
  double size_m[2] = {0, 0};   ///< extent along the face's two in-plane axes (in_plane(0), in_plane(1));
                               ///< curved: around the circumference (arc length), along the axis
  double depth_m = -1;         ///< spheres whose surface comes within this of the face plane; < 0: the smallest radius
};

/// The patch centre in metres (resolves centre_rel against the box).
Vec3 patch_centre(const Patch& patch, const Box& box);

/// Spheres whose centre projects inside the patch and whose surface lies
/// within the patch depth of the face plane (curved: of the cylinder's surface, the
/// patch measured as arc length around the axis and length along it); InputError
/// naming `who` if none.
///
/// A line of spheres across the face (`line`: the packing's axis when its centres lie on one
/// line, model_choice.hpp's line_axis, along the face's normal): a patch of the default depth
/// takes the end sphere at that face alone, if its centre projects inside the patch. That sphere
/// is the whole of the line's surface there, the others sit behind it on the axis; by depth
/// alone a chain at a spacing below one radius (the rod paper's 0.95 R, Table 1) would also take
/// the next sphere, whose surface lies d < R from the face. An experiment's end transducers (a
/// rod's A and S) so drive and read the first and last sphere, as `sphere = "first"/"last"` does.
/// An explicit depth_m keeps the depth rule.
std::vector<std::size_t> spheres_under_patch(const SpherePart& spheres, const Box& box, const Patch& patch,
                                             const std::string& who, const std::optional<Vec3>& line = std::nullopt);
/// The sphere whose centre is nearest to `point` (ties: lowest packing index).
std::size_t sphere_nearest(const SpherePart& spheres, const Vec3& point);
/// The first or last sphere along the longest extent of the packing (a rod's ends).
std::size_t sphere_at_end(const SpherePart& spheres, bool last);

}  // namespace mesowave::dem
