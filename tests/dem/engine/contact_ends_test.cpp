// A chunk's contact ends (dem/engine/contact_ends.hpp) against the spheres' arrays indexed directly:
// every component of every source at both ends, bit for bit (-0, a subnormal and distinct values
// in each lane, so that a transposed lane or component shows), for whole chunks, chunks shorter
// than the vector width and tails, with the arrays' last sphere among the ends (the masked loads
// must not read past it); the same for sphere records. And the requests for lines ahead
// (SphereSystem::set_prefetch_ahead) change no bit of a step.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

#include "mesowave/dem/contact/cohesive_frictional_contact.hpp"
#include "mesowave/dem/contact/linear_bonded_network.hpp"
#include "mesowave/dem/engine/contact_ends.hpp"
#include "mesowave/dem/engine/sphere_system.hpp"
#include "dem/test_packings.hpp"
#include "dem/test_systems.hpp"

using namespace mesowave::dem;
using namespace mesowave::dem::testing;

namespace {

bool same_bits(const Vec3& a, const Vec3& b) { return std::memcmp(&a, &b, sizeof(Vec3)) == 0; }

// 200 pairs first < second of `spheres`, from a fixed pseudo-random walk, with sphere 0 and the last
// one among them (contact 5), and the last one again at contact 199.
void random_pairs(std::size_t spheres, std::uint32_t state, std::vector<std::uint32_t>& first, std::vector<std::uint32_t>& second) {
  for (std::size_t c = 0; c < 200; ++c) {
    state = state * 1664525u + 1013904223u;
    const std::uint32_t i = (state >> 8) % (spheres - 1);
    const std::uint32_t j = i + 1 + (state >> 20) % std::uint32_t(spheres - 1 - i);
    first.push_back(i), second.push_back(j);
  }
  first[5] = 0, second[5] = std::uint32_t(spheres - 1);
  first[199] = 3, second[199] = std::uint32_t(spheres - 1);
}

// Chunks (first contact, size): whole, shorter than a chunk, one vector, shorter than one, a tail.
constexpr std::pair<std::size_t, std::size_t> kChunks[] = {{0, 32}, {32, 31}, {64, 8}, {100, 7}, {168, 32}, {199, 1}};

}  // namespace

TEST(ContactEnds, EachEndIsItsSpheresValuesBitForBit) {
  constexpr std::size_t spheres = 301;
  std::vector<Vec3> x(spheres), v(spheres), w(spheres);  // exactly `spheres` long: nothing after the last
  for (std::size_t k = 0; k < spheres; ++k) {
    const double s = double(k);
    x[k] = {s + 0.25, -s, 1e-3 * s};
    v[k] = {-0.5 * s, s * s, 7.0 - s};
    w[k] = {1.0 / (s + 1.0), -2.0 * s, s + 1e6};
  }
  x[3] = {-0.0, std::numeric_limits<double>::denorm_min(), 0.0};
  std::vector<std::uint32_t> first, second;
  random_pairs(spheres, 12345, first, second);
  for (const auto& [begin, m] : kChunks) {
    ContactEnds<3> ends;
    ends.fill({x.data(), v.data(), w.data()}, first.data(), second.data(), begin, m);
    const std::vector<Vec3>* sources[3] = {&x, &v, &w};
    for (std::size_t b = begin; b < begin + m; ++b)
      for (std::size_t s = 0; s < 3; ++s) {
        EXPECT_TRUE(same_bits(ends.at(s, 0, b), (*sources[s])[first[b]])) << "chunk at " << begin << ", contact " << b << ", source " << s;
        EXPECT_TRUE(same_bits(ends.at(s, 1, b), (*sources[s])[second[b]])) << "chunk at " << begin << ", contact " << b << ", source " << s;
      }
  }
}

// The same for sphere records (the linearised network's d, theta and r as one line a sphere):
// packed from three arrays and staged by transposes of eight records, every component at both
// ends, the last record among the ends.
TEST(ContactEnds, EachRecordEndIsItsSpheresValuesBitForBit) {
  constexpr std::size_t spheres = 301;
  std::vector<Vec3> d(spheres), theta(spheres);
  std::vector<double> r(spheres);
  for (std::size_t k = 0; k < spheres; ++k) {
    const double s = double(k);
    d[k] = {s + 0.25, -s, 1e-3 * s};
    theta[k] = {1.0 / (s + 1.0), -2.0 * s, s + 1e6};
    r[k] = 1e-3 * (s + 0.5);
  }
  d[3] = {-0.0, std::numeric_limits<double>::denorm_min(), 0.0};
  std::vector<SphereRecord> records(spheres);  // exactly `spheres` long
  pack_sphere_records(d.data(), theta.data(), r.data(), 0, 150, records.data());
  pack_sphere_records(d.data(), theta.data(), r.data(), 150, spheres, records.data());
  std::vector<std::uint32_t> first, second;
  random_pairs(spheres, 54321, first, second);
  for (const auto& [begin, m] : kChunks) {
    RecordEnds ends;
    ends.fill(records.data(), first.data(), second.data(), begin, m);
    for (std::size_t b = begin; b < begin + m; ++b)
      for (int end = 0; end < 2; ++end) {
        const std::uint32_t k = end == 0 ? first[b] : second[b];
        EXPECT_TRUE(same_bits(ends.at(0, end, b), d[k])) << "chunk at " << begin << ", contact " << b << ", end " << end;
        EXPECT_TRUE(same_bits(ends.at(1, end, b), theta[k])) << "chunk at " << begin << ", contact " << b << ", end " << end;
        EXPECT_EQ(ends.scalar(end, b), r[k]) << "chunk at " << begin << ", contact " << b << ", end " << end;
      }
  }
}

// No lines asked for, one contact ahead, 33 (not a chunk's multiple) and more than a task holds
// (the clamps to the task's end): positions, velocities, angular velocities and energies the same
// to the bit, for both laws. 8,788 spheres: two partitions and the contacts between them.
TEST(ContactEnds, AskingForLinesAheadChangesNoBit) {
  const Packing p = fcc_packing(13, 2.5e-3, 0.8e-3, 1.0e-3, 0.03, 9, 2290);
  const CohesiveFrictionalMaterial material = concrete_material();
  for (const bool full : {false, true}) {
    std::unique_ptr<SphereSystem> reference;
    for (const std::size_t ahead : {0, 1, 33, 5000}) {
      auto system = bonded_system(p, material, full);
      system->set_prefetch_ahead(ahead);
      ASSERT_EQ(system->prefetch_ahead(), ahead);
      for (int i = 0; i < 150; ++i) {
        for (std::size_t k = 0; k < 40; ++k) system->add_external_force(k, {1e-3 * std::sin(0.1 * i), 2e-4, 0});
        system->step(5e-8, i % 50 == 49);
      }
      if (!reference) {
        reference = std::move(system);
        continue;
      }
      expect_same_motion(*system, *reference, std::string(full ? "full" : "linear") + ", " + std::to_string(ahead) + " ahead");
    }
  }
}
