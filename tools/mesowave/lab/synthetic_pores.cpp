#include "mesowave/lab/synthetic_pores.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

#include "mesowave/core/error.hpp"
#include "mesowave/core/random.hpp"

namespace mesowave::lab {

namespace {

struct Ball {
  double x, y, z, r;
};

// Log-uniform radius: many small voids, few large ones.
double log_uniform(XoshiroRandom& rng, double lo, double hi) { return lo * std::pow(hi / lo, rng.uniform01()); }

// One pore: a sphere, or an irregular cluster of 2-4 overlapping spheres.
std::vector<Ball> pore_balls(XoshiroRandom& rng, double x, double y, double z, double r, PoreShape shape, bool planar) {
  std::vector<Ball> balls = {{x, y, z, r}};
  if (shape == PoreShape::irregular) {
    const int extra = 1 + int(rng.uniform01() * 3.0);
    for (int k = 0; k < extra; ++k) {
      double dx = rng.normal(), dy = rng.normal(), dz = planar ? 0.0 : rng.normal();
      const double n = std::sqrt(dx * dx + dy * dy + dz * dz);
      if (n == 0) continue;
      const double d = 0.8 * r;
      balls.push_back({x + d * dx / n, y + d * dy / n, z + d * dz / n, r * rng.uniform(0.5, 0.9)});
    }
  }
  return balls;
}

std::uint16_t to_gray(double v, double max) { return std::uint16_t(std::lround(std::clamp(v, 0.0, max))); }

void check_fraction(const char* what, double f) {
  if (!(f > 0 && f < 0.6)) throw InputError(std::string(what) + " must lie in (0, 0.6)");
}

}  // namespace

SyntheticCtStack synthetic_ct_stack(const SyntheticCtSpec& spec) {
  check_fraction("porosity", spec.porosity);
  if (spec.specimen_px < 4 || spec.slices < 1 || spec.margin_px < 0)
    throw InputError("CT stack needs a specimen of at least 4 px and one slice");
  if (!(spec.pore_radius_min_px > 0 && spec.pore_radius_max_px >= spec.pore_radius_min_px))
    throw InputError("pore radii must satisfy 0 < min <= max");
  XoshiroRandom rng(spec.seed);
  const int n = spec.specimen_px, nz = spec.slices, m = spec.margin_px, side = n + 2 * m;
  const std::size_t voxels = std::size_t(n) * n * nz;
  constexpr int kSub = 3, kSubN = kSub * kSub * kSub;
  auto vindex = [&](int x, int y, int z) { return (std::size_t(z) * n + y) * n + x; };

  // Sand grains: which specimen voxels are quartz (by voxel centre).
  std::vector<std::uint8_t> grain(voxels, 0);
  std::size_t grain_voxels = 0;
  while (double(grain_voxels) < spec.grain_fraction * double(voxels)) {
    const double r = log_uniform(rng, spec.grain_radius_min_px, spec.grain_radius_max_px);
    const double cx = rng.uniform(0, n), cy = rng.uniform(0, n), cz = rng.uniform(0, nz);
    for (int z = std::max(0, int(cz - r)); z <= std::min(nz - 1, int(cz + r)); ++z)
      for (int y = std::max(0, int(cy - r)); y <= std::min(n - 1, int(cy + r)); ++y)
        for (int x = std::max(0, int(cx - r)); x <= std::min(n - 1, int(cx + r)); ++x) {
          const double dx = x + 0.5 - cx, dy = y + 0.5 - cy, dz = z + 0.5 - cz;
          if (dx * dx + dy * dy + dz * dz <= r * r && !grain[vindex(x, y, z)]) {
            grain[vindex(x, y, z)] = 1;
            ++grain_voxels;
          }
        }
  }

  // Voids: 27 subsample bits per voxel, unions by OR.
  std::vector<std::uint32_t> cover(voxels, 0);
  std::size_t covered = 0;
  const double target = spec.porosity * double(voxels) * kSubN;
  SyntheticCtStack out;
  while (double(covered) < target) {
    // Near the target, smaller pores: the last one must not overshoot it by much.
    const double deficit = (target - double(covered)) / kSubN;  // voxels
    const double cluster = spec.shape == PoreShape::irregular ? 3.2 : 1.0;
    const double r_fit = std::cbrt(3.0 * deficit / (4.0 * M_PI * cluster));
    const double r = log_uniform(rng, spec.pore_radius_min_px,
                                 std::clamp(r_fit, spec.pore_radius_min_px, spec.pore_radius_max_px));
    const double cx = rng.uniform(0, n), cy = rng.uniform(0, n), cz = rng.uniform(0, nz);
    for (const Ball& b : pore_balls(rng, cx, cy, cz, r, spec.shape, false))
      for (int z = std::max(0, int(std::floor(b.z - b.r))); z <= std::min(nz - 1, int(b.z + b.r)); ++z)
        for (int y = std::max(0, int(std::floor(b.y - b.r))); y <= std::min(n - 1, int(b.y + b.r)); ++y)
          for (int x = std::max(0, int(std::floor(b.x - b.r))); x <= std::min(n - 1, int(b.x + b.r)); ++x) {
            std::uint32_t bits = 0;
            for (int s = 0; s < kSubN; ++s) {
              const double dx = x + (s % kSub + 0.5) / kSub - b.x, dy = y + (s / kSub % kSub + 0.5) / kSub - b.y,
                           dz = z + (s / (kSub * kSub) + 0.5) / kSub - b.z;
              if (dx * dx + dy * dy + dz * dz <= b.r * b.r) bits |= 1u << s;
            }
            std::uint32_t& c = cover[vindex(x, y, z)];
            covered += std::size_t(std::popcount(bits & ~c));
            c |= bits;
          }
    ++out.pores;
  }

  out.true_porosity = double(covered) / (double(voxels) * kSubN);
  out.specimen_roi = {m, m, n, n};
  for (int z = 0; z < nz; ++z) {
    io::GrayImage slice;
    slice.width = slice.height = side;
    slice.bit_depth = 16;
    slice.origin = "slice " + std::to_string(z + 1);
    slice.pixels.resize(std::size_t(side) * side);
    std::size_t slice_cover = 0;
    for (int y = 0; y < side; ++y)
      for (int x = 0; x < side; ++x) {
        double v = spec.air_level;
        const int sx = x - m, sy = y - m;
        if (sx >= 0 && sy >= 0 && sx < n && sy < n) {
          const std::size_t i = vindex(sx, sy, z);
          const int bits = std::popcount(cover[i]);
          slice_cover += std::size_t(bits);
          const double c = double(bits) / kSubN;
          const double solid = grain[i] ? spec.grain_level : spec.paste_level;
          v = c * spec.air_level + (1 - c) * solid;
        }
        slice.pixels[std::size_t(y) * side + x] = to_gray(v + spec.noise_sd * rng.normal(), 65535.0);
      }
    out.slice_porosity.push_back(double(slice_cover) / (double(n) * n * kSubN));
    out.slices.push_back(std::move(slice));
  }
  return out;
}

SyntheticFace synthetic_face(const SyntheticFaceSpec& spec) {
  check_fraction("porosity", spec.porosity);
  if (spec.width_px < 4 || spec.height_px < 4) throw InputError("face image must be at least 4 x 4 px");
  if (!(spec.pore_radius_min_px > 0 && spec.pore_radius_max_px >= spec.pore_radius_min_px))
    throw InputError("pore radii must satisfy 0 < min <= max");
  XoshiroRandom rng(spec.seed);
  const int w = spec.width_px, h = spec.height_px;
  const std::size_t pixels = std::size_t(w) * h;
  constexpr int kSub = 4, kSubN = kSub * kSub;

  // Matrix: cement paste with sand grains of varied tone.
  std::vector<double> solid(pixels, spec.paste_level);
  std::vector<std::uint8_t> is_grain(pixels, 0);
  std::size_t grain_px = 0;
  while (double(grain_px) < spec.grain_fraction * double(pixels)) {
    const double r = log_uniform(rng, spec.grain_radius_min_px, spec.grain_radius_max_px);
    const double cx = rng.uniform(0, w), cy = rng.uniform(0, h), tone = rng.uniform(spec.grain_level_min, spec.grain_level_max);
    const double ax = rng.uniform(0.7, 1.3);  // elongated grains
    for (int y = std::max(0, int(cy - r * 1.4)); y <= std::min(h - 1, int(cy + r * 1.4)); ++y)
      for (int x = std::max(0, int(cx - r * 1.4)); x <= std::min(w - 1, int(cx + r * 1.4)); ++x) {
        const double dx = (x + 0.5 - cx) / ax, dy = (y + 0.5 - cy) * ax;
        if (dx * dx + dy * dy <= r * r) {
          const std::size_t i = std::size_t(y) * w + x;
          if (!is_grain[i]) ++grain_px;
          is_grain[i] = 1;
          solid[i] = tone;
        }
      }
  }

  // Plaster-filled voids: 16 subsample bits per pixel.
  std::vector<std::uint16_t> cover(pixels, 0);
  std::vector<double> plaster(pixels, spec.plaster_level);
  std::size_t covered = 0;
  const double target = spec.porosity * double(pixels) * kSubN;
  SyntheticFace out;
  while (double(covered) < target) {
    const double deficit = (target - double(covered)) / kSubN;  // pixels
    const double cluster = spec.shape == PoreShape::irregular ? 2.5 : 1.0;
    const double r_fit = std::sqrt(deficit / (M_PI * cluster));
    const double r = log_uniform(rng, spec.pore_radius_min_px,
                                 std::clamp(r_fit, spec.pore_radius_min_px, spec.pore_radius_max_px));
    const double cx = rng.uniform(0, w), cy = rng.uniform(0, h);
    const double tone = spec.plaster_level + rng.uniform(-6, 6);
    for (const Ball& b : pore_balls(rng, cx, cy, 0, r, spec.shape, true))
      for (int y = std::max(0, int(std::floor(b.y - b.r))); y <= std::min(h - 1, int(b.y + b.r)); ++y)
        for (int x = std::max(0, int(std::floor(b.x - b.r))); x <= std::min(w - 1, int(b.x + b.r)); ++x) {
          std::uint16_t bits = 0;
          for (int s = 0; s < kSubN; ++s) {
            const double dx = x + (s % kSub + 0.5) / kSub - b.x, dy = y + (s / kSub + 0.5) / kSub - b.y;
            if (dx * dx + dy * dy <= b.r * b.r) bits = std::uint16_t(bits | (1u << s));
          }
          const std::size_t i = std::size_t(y) * w + x;
          covered += std::size_t(std::popcount(std::uint16_t(bits & ~cover[i])));
          cover[i] = std::uint16_t(cover[i] | bits);
          if (bits) plaster[i] = tone;
        }
    ++out.pores;
  }
  out.true_porosity = double(covered) / (double(pixels) * kSubN);

  io::GrayImage& image = out.image;
  image.width = w;
  image.height = h;
  image.bit_depth = 8;
  image.origin = "synthetic face";
  image.pixels.resize(pixels);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = std::size_t(y) * w + x;
      const double c = double(std::popcount(cover[i])) / kSubN;
      // Illumination falls off linearly from the top-left to the bottom-right corner.
      const double light = spec.illumination_gradient * (1.0 - (double(x) / w + double(y) / h));
      const double v = c * plaster[i] + (1 - c) * solid[i] + light + spec.noise_sd * rng.normal();
      image.pixels[i] = to_gray(v, 255.0);
    }
  return out;
}

}  // namespace mesowave::lab
