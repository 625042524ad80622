#include "mesowave/dem/packing/packing_generator.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "mesowave/core/check.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"

namespace mesowave::dem {
namespace {

using Vec3 = std::array<double, 3>;
constexpr double pi = std::numbers::pi;

std::string mm(double metres) { return format_quantity(metres / 1e-3, "mm"); }

// ---- where a centre may lie ------------------------------------------------

// Centres kept at least their radius from every wall. Lengths here are in the
// generator's internal unit (see Scale).
struct Region {
  bool cylinder = false;
  Vec3 lo{}, hi{};         // box corners (cylinder: bounding box)
  double cx = 0, cy = 0, R = 0;

  void project(Vec3& x, double r) const {
    if (!cylinder) {
      for (int d = 0; d < 3; ++d) x[d] = std::clamp(x[d], lo[d] + r, hi[d] - r);
      return;
    }
    x[2] = std::clamp(x[2], lo[2] + r, hi[2] - r);
    const double ex = x[0] - cx, ey = x[1] - cy, reach = R - r;
    const double rho2 = ex * ex + ey * ey;
    if (rho2 > reach * reach) {
      const double s = reach / std::sqrt(rho2);
      x[0] = cx + ex * s;
      x[1] = cy + ey * s;
    }
  }

  // Removes from `f` (and `v`) the components that push through a wall the
  // centre rests on: the wall carries them, so they are not out of balance.
  void constrain(const Vec3& x, double r, Vec3& f, Vec3& v) const {
    constexpr double eps = 1e-12;
    auto axis = [&](int d) {
      if (x[d] <= lo[d] + r + eps && f[d] < 0) f[d] = 0, v[d] = std::max(v[d], 0.0);
      if (x[d] >= hi[d] - r - eps && f[d] > 0) f[d] = 0, v[d] = std::min(v[d], 0.0);
    };
    axis(2);
    if (!cylinder) {
      axis(0);
      axis(1);
      return;
    }
    const double ex = x[0] - cx, ey = x[1] - cy, reach = R - r;
    const double rho = std::sqrt(ex * ex + ey * ey);
    if (rho >= reach - eps && rho > 0) {
      const double nx = ex / rho, ny = ey / rho;
      const double fn = f[0] * nx + f[1] * ny;
      if (fn > 0) f[0] -= fn * nx, f[1] -= fn * ny;
      const double vn = v[0] * nx + v[1] * ny;
      if (vn > 0) v[0] -= vn * nx, v[1] -= vn * ny;
    }
  }

  Vec3 random_point(double r, Mt64Random& random) const {
    if (!cylinder) return {random.uniform(lo[0] + r, hi[0] - r), random.uniform(lo[1] + r, hi[1] - r),
                           random.uniform(lo[2] + r, hi[2] - r)};
    const double reach = R - r;
    for (;;) {  // rejection from the square around the disc
      const double ex = random.uniform(-reach, reach), ey = random.uniform(-reach, reach);
      if (ex * ex + ey * ey <= reach * reach) return {cx + ex, cy + ey, random.uniform(lo[2] + r, hi[2] - r)};
    }
  }
};

// ---- sums that give the same bits for any thread count --------------------

// Fixed blocks summed in a fixed order: the partition does not depend on the
// number of threads, so neither does the rounding.
constexpr std::size_t kBlock = 256;

// Loops hand out work in chunks as threads come free (dynamic schedule): on a
// shared machine a thread that loses its core does not hold up the other.
// Each sphere's (or block's) result is stored by index, so which thread
// computes it changes no bit.
constexpr int kChunk = 256;

// ---- Verlet neighbour lists ------------------------------------------------

// For each sphere, every other sphere within r_i + r_j + skin (both
// directions, CSR). Rebuilt when a centre has moved more than skin/2 since
// the last build, so no overlapping pair is ever missing.
struct NeighbourList {
  std::uint32_t slots = 32;
  std::vector<std::uint32_t> count, index;  // sphere i: index[i * slots + k], k < count[i]
  std::vector<Vec3> reference;  // centres at the last build
};

void build_neighbours(const std::vector<Vec3>& x, const std::vector<double>& r, double r_max, double skin,
                      const Region& region, bool parallel, NeighbourList& list) {
  const std::size_t n = x.size();
  const double cell = 2 * r_max + skin;
  std::array<std::int64_t, 3> dims{};
  for (int d = 0; d < 3; ++d) dims[d] = std::max<std::int64_t>(1, std::int64_t((region.hi[d] - region.lo[d]) / cell));
  std::array<double, 3> inv{};
  for (int d = 0; d < 3; ++d) inv[d] = double(dims[d]) / (region.hi[d] - region.lo[d]);  // cells >= `cell` wide
  auto cell_of = [&](const Vec3& p) {
    std::array<std::int64_t, 3> c;
    for (int d = 0; d < 3; ++d) c[d] = std::clamp<std::int64_t>(std::int64_t((p[d] - region.lo[d]) * inv[d]), 0, dims[d] - 1);
    return c;
  };
  const std::size_t cells = std::size_t(dims[0] * dims[1] * dims[2]);
  std::vector<std::uint32_t> cell_start(cells + 1, 0), order(n), home(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto c = cell_of(x[i]);
    home[i] = std::uint32_t((c[2] * dims[1] + c[1]) * dims[0] + c[0]);
    ++cell_start[home[i] + 1];
  }
  for (std::size_t c = 0; c < cells; ++c) cell_start[c + 1] += cell_start[c];
  {
    std::vector<std::uint32_t> fill(cell_start.begin(), cell_start.end() - 1);
    for (std::size_t i = 0; i < n; ++i) order[fill[home[i]]++] = std::uint32_t(i);
  }

  auto visit = [&](std::size_t i, auto&& emit) {
    const auto c = cell_of(x[i]);
    for (std::int64_t z = std::max<std::int64_t>(c[2] - 1, 0); z <= std::min(c[2] + 1, dims[2] - 1); ++z)
      for (std::int64_t y = std::max<std::int64_t>(c[1] - 1, 0); y <= std::min(c[1] + 1, dims[1] - 1); ++y) {
        // The three cells along x are contiguous in the cell order.
        const std::int64_t x0 = std::max<std::int64_t>(c[0] - 1, 0), x1 = std::min(c[0] + 1, dims[0] - 1);
        const auto row = std::size_t((z * dims[1] + y) * dims[0]);
        for (std::uint32_t s = cell_start[row + std::size_t(x0)]; s < cell_start[row + std::size_t(x1) + 1]; ++s) {
          const std::uint32_t j = order[s];
          if (j == i) continue;
          const double ax = x[j][0] - x[i][0], ay = x[j][1] - x[i][1], az = x[j][2] - x[i][2];
          const double reach = r[i] + r[j] + skin;
          if (ax * ax + ay * ay + az * az < reach * reach) emit(j);
        }
      }
  };

  // One pass into fixed-size slots per sphere (each list written by one
  // thread, in a fixed order); a sphere with more partners than slots
  // widens the slots and the pass runs again.
  for (;;) {
    const std::uint32_t slots = list.slots;
    list.count.assign(n, 0);
    list.index.resize(n * slots);
    bool overflow = false;
#pragma omp parallel for schedule(dynamic, kChunk) reduction(|| : overflow) if (parallel)
    for (std::size_t i = 0; i < n; ++i) {
      std::uint32_t at = 0;
      std::uint32_t* out = list.index.data() + i * slots;
      visit(i, [&](std::uint32_t j) {
        if (at < slots) out[at] = j;
        ++at;
      });
      list.count[i] = std::min(at, slots);
      if (at > slots) overflow = true;
    }
    if (!overflow) break;
    list.slots *= 2;
  }
  list.reference = x;
}

// A direction for two coincident centres: fixed by the pair, opposite for the
// two partners, so the pair separates deterministically.
Vec3 fallback_direction(std::size_t i, std::size_t j) {
  const std::size_t a = std::min(i, j), b = std::max(i, j);
  std::uint64_t h = (std::uint64_t(a) * 0x9E3779B97F4A7C15ull) ^ (std::uint64_t(b) + 0x632BE59BD9B4E019ull);
  h ^= h >> 31;
  h *= 0xBF58476D1CE4E5B9ull;
  h ^= h >> 29;
  const double u = double(h >> 11) * 0x1.0p-53, w = double((h * 0x94D049BB133111EBull) >> 11) * 0x1.0p-53;
  const double z = 2 * u - 1, phi = 2 * pi * w, s = std::sqrt(std::max(0.0, 1 - z * z));
  const double sign = (i < j) ? 1.0 : -1.0;
  return {sign * s * std::cos(phi), sign * s * std::sin(phi), sign * z};
}

// What one force pass gathers, summed block by block (see kBlock).
struct ForceSums {
  double power = 0;         // sum F . v
  double v2 = 0, f2 = 0;    // sum |v|^2, sum |F|^2
  double max_f2 = 0;        // largest |F|^2 on one sphere
  double contact_force = 0; // sum over contacts of |f_ij| (each counted from both sides)
  double contacts = 0;      // number of contacts, counted from both sides
};

// Net force F_i = -dE/dx_i of E = sum 1/2 xi^2 + Q/4 xi^4, xi = delta/r_min, on every sphere,
// less the components the walls carry (Region::constrain), with the sums
// FIRE needs. One pass, so one synchronisation per iteration.
ForceSums overlap_forces(const std::vector<Vec3>& x, const std::vector<double>& r, const std::vector<double>& inv_r2,
                         double stiffening, const NeighbourList& list, const Region& region, bool parallel,
                         std::vector<Vec3>& force, std::vector<Vec3>& v) {
  const std::size_t n = x.size();
  const std::size_t blocks = (n + kBlock - 1) / kBlock;
  std::vector<ForceSums> partial(blocks);
#pragma omp parallel for schedule(dynamic, 1) if (parallel)
  for (std::size_t b = 0; b < blocks; ++b) {
    ForceSums sums;
    const std::size_t end = std::min(n, (b + 1) * kBlock);
    for (std::size_t i = b * kBlock; i < end; ++i) {
      Vec3 f{0, 0, 0};
      const std::uint32_t* partners = list.index.data() + i * list.slots;
      for (std::uint32_t s = 0; s < list.count[i]; ++s) {
        const std::uint32_t j = partners[s];
        const double ax = x[i][0] - x[j][0], ay = x[i][1] - x[j][1], az = x[i][2] - x[j][2];
        const double reach = r[i] + r[j];
        const double d2 = ax * ax + ay * ay + az * az;
        if (d2 >= reach * reach) continue;
        const double dist = std::sqrt(d2);
        const double ir2 = std::max(inv_r2[i], inv_r2[j]);
        const double xi2 = (reach - dist) * (reach - dist) * ir2;
        const double magnitude = (reach - dist) * ir2 * (1 + stiffening * xi2);  // dE/d(delta)
        if (dist > 0) {
          const double k = magnitude / dist;
          f[0] += k * ax, f[1] += k * ay, f[2] += k * az;
        } else {
          const Vec3 e = fallback_direction(i, j);
          f[0] += magnitude * e[0], f[1] += magnitude * e[1], f[2] += magnitude * e[2];
        }
        sums.contact_force += magnitude;
        sums.contacts += 1;
      }
      region.constrain(x[i], r[i], f, v[i]);
      force[i] = f;
      const double ff = f[0] * f[0] + f[1] * f[1] + f[2] * f[2];
      sums.power += f[0] * v[i][0] + f[1] * v[i][1] + f[2] * v[i][2];
      sums.v2 += v[i][0] * v[i][0] + v[i][1] * v[i][1] + v[i][2] * v[i][2];
      sums.f2 += ff;
      sums.max_f2 = std::max(sums.max_f2, ff);
    }
    partial[b] = sums;
  }
  ForceSums total;
  for (const auto& p : partial) {
    total.power += p.power;
    total.v2 += p.v2;
    total.f2 += p.f2;
    total.max_f2 = std::max(total.max_f2, p.max_f2);
    total.contact_force += p.contact_force;
    total.contacts += p.contacts;
  }
  return total;
}

// ---- containers -------------------------------------------------------------

bool nearly(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b)); }

}  // namespace

Container box_container(const std::array<double, 3>& lower, const std::array<double, 3>& upper) {
  Container c;
  c.shape = "box";
  c.lower_m = lower;
  c.upper_m = upper;
  check_container(c);
  return c;
}

Container cylinder_container(double radius, double z0, double z1, double axis_x, double axis_y) {
  Container c;
  c.shape = "cylinder";
  c.radius_m = radius;
  c.lower_m = {axis_x - radius, axis_y - radius, z0};
  c.upper_m = {axis_x + radius, axis_y + radius, z1};
  check_container(c);
  return c;
}

Container rod_container(double rod_radius, double z0, double z1) {
  Container c = cylinder_container(rod_radius, z0, z1);
  c.shape = "line";
  return c;
}

void check_container(const Container& c) {
  for (int d = 0; d < 3; ++d) {
    require_finite("container corner", c.lower_m[d] / 1e-3, "mm");
    require_finite("container corner", c.upper_m[d] / 1e-3, "mm");
    const double side = c.upper_m[d] - c.lower_m[d];
    if (!(side > 0))
      throw InputError(std::string("container size along ") + "xyz"[d] + " (" + mm(side) + ") must be positive");
  }
  if (c.shape == "box") return;
  if (c.shape != "cylinder" && c.shape != "line")
    throw InputError("container shape '" + c.shape + "' is not box, cylinder or line");
  require_positive(c.shape + " radius", c.radius_m / 1e-3, "mm");
  if (!nearly(c.upper_m[0] - c.lower_m[0], 2 * c.radius_m) || !nearly(c.upper_m[1] - c.lower_m[1], 2 * c.radius_m))
    throw InputError("a " + c.shape + " container's x-y extent must be 2 R square (R = " + mm(c.radius_m) + ")");
}

double container_volume(const Container& c) {
  check_container(c);
  const double h = c.upper_m[2] - c.lower_m[2];
  if (c.shape == "box") return (c.upper_m[0] - c.lower_m[0]) * (c.upper_m[1] - c.lower_m[1]) * h;
  return pi * c.radius_m * c.radius_m * h;
}

Packing generate_packing(const Container& container, const PackingOptions& o, PackingRun* run_out) {
  check_container(container);
  if (container.shape == "line") throw InputError("a line of spheres is made by line_of_spheres, not packed");
  if (!std::isfinite(o.porosity) || o.porosity <= 0 || o.porosity >= 1)
    throw InputError("porosity (" + format_number(o.porosity) + ") must lie strictly between 0 and 1");
  require_positive("force tolerance", o.force_tolerance);
  const bool cylinder = container.shape == "cylinder";
  const double d_max = o.sizes.d_max();
  {
    const double h = container.upper_m[2] - container.lower_m[2];
    const double w = cylinder ? 2 * container.radius_m
                              : std::min(container.upper_m[0] - container.lower_m[0], container.upper_m[1] - container.lower_m[1]);
    if (std::min(w, h) < d_max)
      throw InputError("the container (smallest size " + mm(std::min(w, h)) + ") cannot hold a sphere of d_max = " +
                       mm(d_max));
  }
  const double volume = container_volume(container);
  const double solid = (1 - o.porosity) * volume;
  const double expected = solid / o.sizes.mean_sphere_volume();
  if (expected > 5e7)
    throw InputError("the packing would hold about " + format_number(std::round(expected)) +
                     " spheres; mw-pack stops at 50 million");

  Mt64Random random(o.seed);
  std::vector<double> diameters = draw_diameters_for_volume(o.sizes, solid, random);
  if (diameters.empty())
    throw InputError("porosity " + format_number(o.porosity) + " leaves less solid than one sphere of d_min = " +
                     mm(o.sizes.d_min()) + " in this container");
  const std::size_t n = diameters.size();

  // Internal unit: the largest radius, so forces and steps are O(1).
  const double unit = d_max / 2;
  Region region;
  region.cylinder = cylinder;
  for (int d = 0; d < 3; ++d) region.lo[d] = container.lower_m[d] / unit, region.hi[d] = container.upper_m[d] / unit;
  region.R = container.radius_m / unit;
  region.cx = (region.lo[0] + region.hi[0]) / 2;
  region.cy = (region.lo[1] + region.hi[1]) / 2;

  std::vector<double> r(n);
  std::vector<Vec3> x(n);
  for (std::size_t i = 0; i < n; ++i) r[i] = diameters[i] / 2 / unit;
  for (std::size_t i = 0; i < n; ++i) x[i] = region.random_point(r[i], random);

  // Spheres numbered cell by cell (z, y, x) so neighbours sit close in memory.
  {
    const double cell = 2.0;
    std::array<std::int64_t, 3> dims{};
    for (int d = 0; d < 3; ++d) dims[d] = std::max<std::int64_t>(1, std::int64_t((region.hi[d] - region.lo[d]) / cell));
    std::vector<std::int64_t> key(n);
    for (std::size_t i = 0; i < n; ++i) {
      std::array<std::int64_t, 3> c;
      for (int d = 0; d < 3; ++d)
        c[d] = std::clamp<std::int64_t>(std::int64_t((x[i][d] - region.lo[d]) / (region.hi[d] - region.lo[d]) * dims[d]), 0,
                                        dims[d] - 1);
      // Serpentine order in y and x keeps consecutive cells adjacent.
      if (c[2] % 2) c[1] = dims[1] - 1 - c[1];
      if ((c[2] * dims[1] + c[1]) % 2) c[0] = dims[0] - 1 - c[0];
      key[i] = (c[2] * dims[1] + c[1]) * dims[0] + c[0];
    }
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key[a] < key[b]; });
    std::vector<double> r2(n);
    std::vector<Vec3> x2(n);
    for (std::size_t k = 0; k < n; ++k) r2[k] = r[order[k]], x2[k] = x[order[k]];
    r.swap(r2);
    x.swap(x2);
  }

  // FIRE minimisation of the overlap energy (unit masses).
  // The stiffest contact, 1/r_min^2 in internal units, sets the stable step:
  // the steps scale with the smallest radius (tuned on d = 1.6-2.0 mm, where
  // r_min/r_max = 0.8 and dt_max = 0.3). The list skin is 0.4 of the largest
  // radius (the fastest of 0.3-0.7).
  const double r_small = *std::min_element(r.begin(), r.end());
  const double skin = 0.4, max_step = 0.1;
  const double dt_max = 0.375 * r_small, dt_start = dt_max / 6, dt_min = dt_max / 150;
  const double alpha_start = 0.25, f_alpha = 0.99, f_inc = 1.1, f_dec = 0.5;
  const std::size_t n_delay = 20;

  // Threads only pay off for large packings; small ones run serially and skip
  // the per-loop synchronisation. Either way each sphere's result is computed
  // the same way, so the bits agree.
  const bool parallel = n >= o.parallel_from;
  NeighbourList list;
  PackingRun run;
  std::vector<Vec3> v(n), f(n);
  std::vector<double> radius(n), inv_r2(n);

  // Largest net force on a sphere over the mean contact force.
  auto residual_of = [](const ForceSums& sums) {
    return sums.contacts > 0 && sums.contact_force > 0 ? std::sqrt(sums.max_f2) / (sums.contact_force / sums.contacts)
                                                        : 0.0;
  };
  std::size_t it = 0;
  double residual = 0;

  // Relaxes at radii r * scale until the relative residual is below
  // `tolerance`, the largest net force below `force_floor` (a loose stage
  // with no contacts left), or `budget` iterations have run.
  auto relax = [&](double scale, double tolerance, double force_floor, std::size_t budget) {
    for (std::size_t i = 0; i < n; ++i) {
      radius[i] = r[i] * scale;
      inv_r2[i] = 1 / (radius[i] * radius[i]);
      region.project(x[i], radius[i]);
      v[i] = {0, 0, 0};
    }
    double dt = dt_start, alpha = alpha_start;
    std::size_t positive_steps = 0;
    build_neighbours(x, radius, 1.0, skin, region, parallel, list);
    ++run.neighbour_rebuilds;
    ForceSums sums = overlap_forces(x, radius, inv_r2, o.overlap_stiffening, list, region, parallel, f, v);
    residual = residual_of(sums);
    for (std::size_t local = 0; it < o.max_iterations && local < budget && residual > tolerance &&
                                sums.max_f2 > force_floor * force_floor;
         ++it, ++local) {
      const bool downhill = sums.power > 0;
      if (downhill) {
        if (++positive_steps > n_delay) {
          dt = std::min(dt * f_inc, dt_max);
          alpha *= f_alpha;
        }
      } else {
        positive_steps = 0;
        if (local >= n_delay) dt = std::max(dt * f_dec, dt_min);
        alpha = alpha_start;
      }
      // Semi-implicit Euler with the FIRE velocity mixing (FIRE 2.0 order): on
      // an uphill step, back up half a step and stop. |v + dt F|^2 follows from
      // the sums of the force pass, so the update needs no further reduction.
      const double v2_new = downhill ? sums.v2 + 2 * dt * sums.power + dt * dt * sums.f2 : dt * dt * sums.f2;
      const double f_norm = std::sqrt(sums.f2);
      const double mix = (downhill && f_norm > 0) ? alpha * std::sqrt(std::max(v2_new, 0.0)) / f_norm : 0.0;
      const double keep = downhill ? 1 - alpha : 1.0;
      double moved2 = 0;
#pragma omp parallel for schedule(dynamic, kChunk) reduction(max : moved2) if (parallel)
      for (std::size_t i = 0; i < n; ++i) {
        if (!downhill)
          for (int d = 0; d < 3; ++d) x[i][d] -= 0.5 * dt * v[i][d], v[i][d] = 0;
        Vec3 step;
        for (int d = 0; d < 3; ++d) {
          v[i][d] = keep * (v[i][d] + dt * f[i][d]) + mix * f[i][d];
          step[d] = dt * v[i][d];
        }
        const double len2 = step[0] * step[0] + step[1] * step[1] + step[2] * step[2];
        if (len2 > max_step * max_step) {
          const double shrink = max_step / std::sqrt(len2);
          for (int d = 0; d < 3; ++d) step[d] *= shrink;
        }
        for (int d = 0; d < 3; ++d) x[i][d] += step[d];
        region.project(x[i], radius[i]);
        const double mx = x[i][0] - list.reference[i][0], my = x[i][1] - list.reference[i][1],
                     mz = x[i][2] - list.reference[i][2];
        moved2 = std::max(moved2, mx * mx + my * my + mz * mz);
      }
      if (moved2 > 0.25 * skin * skin) {
        build_neighbours(x, radius, 1.0, skin, region, parallel, list);
        ++run.neighbour_rebuilds;
      }
      sums = overlap_forces(x, radius, inv_r2, o.overlap_stiffening, list, region, parallel, f, v);
      residual = residual_of(sums);
      if (o.progress && it % 50 == 0) o.progress(it, residual);
    }
  };

  // Radius growth (Lubachevsky-Stillinger style, by relaxation): from a
  // solid fraction where the random centres leave room, grow every radius by
  // the same factor in steps, relaxing a little at each, so that small
  // spheres settle in the gaps between large ones instead of inside them.
  // Needed for wide size ranges only: for d_max/d_min <= 1.5 (the concrete
  // paper's 1.25) the quench from full size gives the same structure (same
  // coordination and overlaps) in half the iterations.
  const double phi = 1 - o.porosity;
  const double phi_start = std::min(phi, 0.5);
  const int stages = o.growth_stages >= 0 ? o.growth_stages : (o.sizes.d_max() > 1.5 * o.sizes.d_min() ? 10 : 0);
  for (int k = 0; phi > phi_start && k < stages; ++k) {
    const double phi_k = phi_start + (phi - phi_start) * double(k) / double(stages);
    relax(std::cbrt(phi_k / phi), 0.1, 1e-4, o.growth_stage_iterations);
  }
  relax(1.0, o.force_tolerance, 1e-9, o.max_iterations);
  run.iterations = it;
  run.residual = residual;
  run.converged = residual <= o.force_tolerance;
  if (o.progress) o.progress(it, residual);

  // A sphere whose centre lies inside its partner is buried: the target
  // asks for more solid than overlapping spheres can hold evenly.
  double worst = 0;
#pragma omp parallel for schedule(dynamic, kChunk) reduction(max : worst) if (parallel)
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t* partners = list.index.data() + i * list.slots;
    for (std::uint32_t k = 0; k < list.count[i]; ++k) {
      const std::uint32_t j = partners[k];
      const double ax = x[i][0] - x[j][0], ay = x[i][1] - x[j][1], az = x[i][2] - x[j][2];
      const double overlap = r[i] + r[j] - std::sqrt(ax * ax + ay * ay + az * az);
      worst = std::max(worst, overlap / std::min(r[i], r[j]));
    }
  }
  if (worst >= 1)
    throw InputError("porosity " + format_number(o.porosity) + " is unreachable here: after relaxation a sphere lies " +
                     format_number(worst) + " of its radius deep in another (buried); choose a larger porosity");

  Packing p;
  p.container = container;
  p.centres_m.resize(n);
  p.radii_m.resize(n);
  p.ids.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    p.radii_m[i] = diameters.empty() ? 0 : r[i] * unit;
    for (int d = 0; d < 3; ++d) p.centres_m[i][d] = x[i][d] * unit;
    p.ids[i] = std::int64_t(i);
  }
  if (run_out) *run_out = run;
  return p;
}

std::size_t rod_sphere_count(double length, double spacing) {
  require_positive("rod length", length / 1e-3, "mm");
  require_positive("sphere spacing", spacing / 1e-3, "mm");
  const double ratio = length / spacing;
  if (ratio > 1e8) throw InputError("the line would hold more than 1e8 spheres");
  const double nearest = std::round(ratio);
  return std::size_t(std::abs(ratio - nearest) <= 1e-9 * nearest ? nearest : std::ceil(ratio));
}

Packing line_of_spheres(const RodLine& line) {
  require_positive("sphere radius", line.sphere_radius_m / 1e-3, "mm");
  require_positive("rod radius", line.rod_radius_m / 1e-3, "mm");
  const std::size_t n = rod_sphere_count(line.length_m, line.spacing_m);
  Packing p;
  p.container = rod_container(line.rod_radius_m, 0, line.length_m);
  const double first = (line.length_m - double(n - 1) * line.spacing_m) / 2;
  for (std::size_t k = 0; k < n; ++k) {
    p.centres_m.push_back({0, 0, first + double(k) * line.spacing_m});
    p.radii_m.push_back(line.sphere_radius_m);
    p.ids.push_back(std::int64_t(k));
  }
  return p;
}

}  // namespace mesowave::dem
