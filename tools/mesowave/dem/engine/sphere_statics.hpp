#pragma once
// What a sphere is at step 0, by the model's index (Morton order): all that the actuators and
// sensors read when they are made (their spheres' places, sizes and masses), so that they can be
// made from the packing's sphere set before any model exists (SpherePart), and read a
// running Model the same way (Model derives from it).
#include <cstddef>
#include <cstdint>

#include "mesowave/dem/engine/vec3.hpp"

namespace mesowave::dem {

class SphereStatics {
public:
  virtual ~SphereStatics() = default;
  virtual std::size_t sphere_count() const = 0;
  virtual Vec3 reference_position(std::size_t k) const = 0;
  virtual double radius(std::size_t k) const = 0;
  virtual double mass(std::size_t k) const = 0;
  virtual std::uint32_t packing_index(std::size_t k) const = 0;  ///< where sphere k sits in the packing file
};

}  // namespace mesowave::dem
