#include "mesowave/dem/loading/sphere_selection.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/dem/parallel/domain.hpp"

namespace mesowave::dem {

Face Face::parse(const std::string& text, bool allow_curved) {
  if (text.size() == 2 && (text[0] == 'x' || text[0] == 'y' || text[0] == 'z') && (text[1] == '-' || text[1] == '+'))
    return Face{text[0] - 'x', text[1] == '+'};
  if (allow_curved && text == "curved") return Face{2, false, true};
  throw InputError("face \"" + text + "\" must be one of x-, x+, y-, y+, z-, z+" + (allow_curved ? " or curved" : ""));
}

std::string Face::name() const { return curved ? "curved" : std::string(1, char('x' + axis)) + (upper ? "+" : "-"); }

Vec3 Face::outward_normal() const {
  if (curved) return {std::cos(azimuth_rad), std::sin(azimuth_rad), 0.0};
  Vec3 n;
  n[axis] = upper ? 1.0 : -1.0;
  return n;
}

Box bounding_box(const SpherePart& part) {
  const SphereSet& s = part.spheres();
  Box b;
  const double inf = std::numeric_limits<double>::infinity();
  b.lower = {inf, inf, inf};
  b.upper = {-inf, -inf, -inf};
  for (std::size_t k = 0; k < part.own_count(); ++k) {
    const Vec3 c = s.centre_m[k];
    const double r = s.radius_m[k];
    for (int d = 0; d < 3; ++d) {
      b.lower[d] = std::min(b.lower[d], c[d] - r);
      b.upper[d] = std::max(b.upper[d], c[d] + r);
    }
  }
  if (Domain* domain = part.domain())
    for (int d = 0; d < 3; ++d) b.lower[d] = -domain->max(-b.lower[d]), b.upper[d] = domain->max(b.upper[d]);  // exact
  return b;
}

Vec3 patch_centre(const Patch& patch, const Box& box) {
  if (!patch.relative) return patch.centre_m;
  Vec3 c;
  for (int d = 0; d < 3; ++d) c[d] = box.lower[d] + patch.centre_rel[d] * (box.upper[d] - box.lower[d]);
  return c;
}

std::vector<std::size_t> spheres_under_patch(const SpherePart& part, const Box& box, const Patch& patch,
                                             const std::string& who, const std::optional<Vec3>& line) {
  const SphereSet& s = part.spheres();
  const Vec3 centre = patch_centre(patch, box);
  const double depth = patch.depth_m < 0 ? part.radius_min() : patch.depth_m;
  const int a = patch.face.axis, p = patch.face.in_plane(0), q = patch.face.in_plane(1);
  const double plane = patch.face.upper ? box.upper[a] : box.lower[a];
  std::function<bool(std::size_t)> under;
  if (patch.face.curved) {
    const double cx = 0.5 * (box.lower.x + box.upper.x), cy = 0.5 * (box.lower.y + box.upper.y);
    const double R = 0.5 * (box.upper.x - box.lower.x);
    const double phi0 = std::atan2(centre.y - cy, centre.x - cx);
    under = [&, cx, cy, R, phi0](std::size_t k) {
      const Vec3 c = s.centre_m[k];
      const double rho = std::hypot(c.x - cx, c.y - cy);
      if (R - (rho + s.radius_m[k]) > depth) return false;
      const double around = std::remainder(std::atan2(c.y - cy, c.x - cx) - phi0, 2 * std::numbers::pi);
      return std::abs(R * around) <= 0.5 * patch.size_m[0] && std::abs(c.z - centre.z) <= 0.5 * patch.size_m[1];
    };
  } else {
    // A line across the face: only its end sphere there is at the surface (header). The line's
    // axis along the face normal to the round-off of its unit vector (model_choice.cpp's test of a
    // line along x, y or z).
    std::optional<std::size_t> end;
    if (patch.depth_m < 0 && line && std::abs((*line)[a]) > 1 - 1e-12)
      end = part.arg_min([&](std::size_t k) { return std::pair{patch.face.upper ? -s.centre_m[k][a] : s.centre_m[k][a], 0.0}; });
    under = [&, end](std::size_t k) {
      if (end && part.whole_index(k) != *end) return false;
      const Vec3 c = s.centre_m[k];
      const double r = s.radius_m[k];
      const double gap = patch.face.upper ? plane - (c[a] + r) : (c[a] - r) - plane;
      return gap <= depth && std::abs(c[p] - centre[p]) <= 0.5 * patch.size_m[0] &&
             std::abs(c[q] - centre[q]) <= 0.5 * patch.size_m[1];
    };
  }
  // Ordered by packing index, so the average is summed the same way whatever the numbering.
  std::vector<std::size_t> chosen = part.select(under, true);
  if (chosen.empty())
    throw InputError(who + ": no sphere under its " + format_number(patch.size_m[0] * 1e3) + " x " +
                     format_number(patch.size_m[1] * 1e3) + " mm patch on face " + patch.face.name() + " at (" +
                     format_number(centre.x * 1e3) + ", " + format_number(centre.y * 1e3) + ", " +
                     format_number(centre.z * 1e3) + ") mm; enlarge the patch or its depth");
  return chosen;
}

std::size_t sphere_nearest(const SpherePart& part, const Vec3& point) {
  const SphereSet& s = part.spheres();
  return part.arg_min([&](std::size_t k) { return std::pair{norm2(s.centre_m[k] - point), double(s.packing_index[k])}; });
}

std::size_t sphere_at_end(const SpherePart& part, bool last) {
  const Box b = bounding_box(part);
  int axis = 0;
  for (int d = 1; d < 3; ++d)
    if (b.upper[d] - b.lower[d] > b.upper[axis] - b.lower[axis]) axis = d;
  const SphereSet& s = part.spheres();
  return part.arg_min([&](std::size_t k) { return std::pair{last ? -s.centre_m[k][axis] : s.centre_m[k][axis], 0.0}; });
}

}  // namespace mesowave::dem
