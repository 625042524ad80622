#include "mesowave/dem/packing_file.hpp"

#include "mesowave/core/error.hpp"
#include "mesowave/io/hdf5.hpp"

namespace mesowave::dem {
namespace h5 = io::h5;

void write_packing_file(const std::filesystem::path& path, const Packing& p) {
  if (p.centres_m.size() != p.radii_m.size() || p.ids.size() != p.radii_m.size())
    throw std::logic_error("packing arrays differ in length");
  auto file = h5::create_file(path);
  h5::set_attribute(file.id(), "format", std::string("mesowave-packing"));
  h5::set_attribute(file.id(), "format_version", std::int64_t(1));
  std::vector<double> centres;
  centres.reserve(3 * p.size());
  for (const auto& c : p.centres_m) centres.insert(centres.end(), c.begin(), c.end());
  h5::write_doubles(file.id(), "centres_m", centres, 3, true);
  h5::write_doubles(file.id(), "radii_m", p.radii_m, 0, true);
  h5::write_int64s(file.id(), "ids", p.ids);
  h5::set_attribute(file.id(), "container_shape", p.container.shape);
  h5::set_attribute(file.id(), "container_lower_m", std::vector<double>(p.container.lower_m.begin(), p.container.lower_m.end()));
  h5::set_attribute(file.id(), "container_upper_m", std::vector<double>(p.container.upper_m.begin(), p.container.upper_m.end()));
  h5::set_attribute(file.id(), "container_radius_m", p.container.radius_m);
  h5::set_attribute(file.id(), "particle_density_kg_m3", p.particle_density_kg_m3);
}

Packing read_packing_file(const std::filesystem::path& path) {
  auto file = h5::open_file(path);
  if (!h5::has_attribute(file.id(), "format") || h5::string_attribute(file.id(), "format") != "mesowave-packing")
    throw InputError(path.string() + " is not a mesowave packing file (no format = mesowave-packing)");
  Packing p;
  std::vector<hsize_t> shape;
  const auto centres = h5::read_doubles(file.id(), "centres_m", &shape);
  if (shape.size() != 2 || shape[1] != 3) throw InputError(path.string() + ": centres_m must be an [n, 3] array");
  p.radii_m = h5::read_doubles(file.id(), "radii_m");
  p.ids = h5::read_int64s(file.id(), "ids");
  if (p.radii_m.size() != shape[0] || p.ids.size() != shape[0])
    throw InputError(path.string() + ": centres_m, radii_m and ids differ in length");
  p.centres_m.resize(p.radii_m.size());
  for (std::size_t i = 0; i < p.radii_m.size(); ++i) p.centres_m[i] = {centres[3 * i], centres[3 * i + 1], centres[3 * i + 2]};
  p.container.shape = h5::string_attribute(file.id(), "container_shape");
  const auto lower = h5::doubles_attribute(file.id(), "container_lower_m");
  const auto upper = h5::doubles_attribute(file.id(), "container_upper_m");
  if (lower.size() != 3 || upper.size() != 3) throw InputError(path.string() + ": container corners must have 3 values");
  p.container.lower_m = {lower[0], lower[1], lower[2]};
  p.container.upper_m = {upper[0], upper[1], upper[2]};
  p.container.radius_m = h5::double_attribute(file.id(), "container_radius_m");
  p.particle_density_kg_m3 = h5::double_attribute(file.id(), "particle_density_kg_m3");
  return p;
}

}  // namespace mesowave::dem
