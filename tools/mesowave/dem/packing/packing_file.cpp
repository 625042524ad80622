#include "mesowave/dem/packing/packing_file.hpp"

#include "mesowave/core/error.hpp"
#include "mesowave/io/hdf5.hpp"

namespace mesowave::dem {
namespace h5 = io::h5;
namespace {

// The h5 layer names the attribute or dataset, not the file: say which file.
template <class Read>
auto naming_file(const std::filesystem::path& path, Read&& read) {
  try {
    return read();
  } catch (const InputError& e) {
    const std::string message = e.what();
    if (message.rfind(path.string(), 0) == 0) throw;
    throw InputError(path.string() + ": " + message);
  }
}

}  // namespace

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

namespace {

// Part `part` of `parts` of the file's spheres (0 of 1: all), with its attributes.
Packing read_rows(const std::filesystem::path& path, int part, int parts) {
  auto file = h5::open_file(path);
  return naming_file(path, [&] {
    if (!h5::has_attribute(file.id(), "format") || h5::string_attribute(file.id(), "format") != "mesowave-packing")
      throw InputError(path.string() + " is not a mesowave packing file (no format = mesowave-packing)");
    Packing p;
    std::vector<hsize_t> shape, radii_shape, ids_shape;  // the shapes first (no rows read)
    (void)h5::read_double_rows(file.id(), "centres_m", 0, 0, &shape);
    (void)h5::read_double_rows(file.id(), "radii_m", 0, 0, &radii_shape);
    (void)h5::read_int64_rows(file.id(), "ids", 0, 0, &ids_shape);
    if (shape.size() != 2 || shape[1] != 3) throw InputError(path.string() + ": centres_m must be an [n, 3] array");
    if (radii_shape[0] != shape[0] || ids_shape[0] != shape[0])
      throw InputError(path.string() + ": centres_m, radii_m and ids differ in length");
    const auto n = std::size_t(shape[0]);
    const std::size_t first = n * std::size_t(part) / std::size_t(parts), end = n * std::size_t(part + 1) / std::size_t(parts);
    const auto centres = h5::read_double_rows(file.id(), "centres_m", first, end - first);
    p.radii_m = h5::read_double_rows(file.id(), "radii_m", first, end - first);
    p.ids = h5::read_int64_rows(file.id(), "ids", first, end - first);
    p.centres_m.resize(p.radii_m.size());
    for (std::size_t i = 0; i < p.radii_m.size(); ++i)
      p.centres_m[i] = {centres[3 * i], centres[3 * i + 1], centres[3 * i + 2]};
    if (parts > 1) p.first_row = first, p.file_rows = n;
    p.container.shape = h5::string_attribute(file.id(), "container_shape");
    const auto lower = h5::doubles_attribute(file.id(), "container_lower_m");
    const auto upper = h5::doubles_attribute(file.id(), "container_upper_m");
    if (lower.size() != 3 || upper.size() != 3)
      throw InputError(path.string() + ": container corners must have 3 values");
    p.container.lower_m = {lower[0], lower[1], lower[2]};
    p.container.upper_m = {upper[0], upper[1], upper[2]};
    p.container.radius_m = h5::double_attribute(file.id(), "container_radius_m");
    p.particle_density_kg_m3 = h5::double_attribute(file.id(), "particle_density_kg_m3");
    return p;
  });
}

}  // namespace

Packing read_packing_file(const std::filesystem::path& path) { return read_rows(path, 0, 1); }

Packing read_packing_file(const std::filesystem::path& path, int part, int parts) {
  if (parts < 1 || part < 0 || part >= parts) throw std::logic_error("read_packing_file: no part " + std::to_string(part) + " of " + std::to_string(parts));
  return read_rows(path, part, parts);
}

// ---- /origin: how the packing was made (additive, format_version 1) --------

void write_packing_file(const std::filesystem::path& path, const Packing& p, const PackingOrigin& origin) {
  write_packing_file(path, p);
  if (origin.empty()) return;
  h5::Handle file(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT));
  if (!file) throw std::runtime_error("HDF5: cannot reopen " + path.string() + " to add /origin");
  auto group = h5::create_group(file.id(), "origin");
  for (const auto& [name, value] : origin.text) h5::set_attribute(group.id(), name, value);
  for (const auto& [name, value] : origin.numbers) h5::set_attribute(group.id(), name, value);
}

PackingOrigin read_packing_origin(const std::filesystem::path& path) {
  auto file = h5::open_file(path);
  return naming_file(path, [&] {
    PackingOrigin origin;
    if (!h5::has_link(file.id(), "origin")) return origin;
    auto group = h5::open_group(file.id(), "origin", "packing origin");
    std::vector<std::string> names;
    H5Aiterate2(
        group.id(), H5_INDEX_NAME, H5_ITER_INC, nullptr,
        [](hid_t, const char* name, const H5A_info_t*, void* data) -> herr_t {
          static_cast<std::vector<std::string>*>(data)->emplace_back(name);
          return 0;
        },
        &names);
    for (const auto& name : names) {
      h5::Handle attr(H5Aopen(group.id(), name.c_str(), H5P_DEFAULT));
      h5::Handle type(H5Aget_type(attr.id()));
      if (H5Tget_class(type.id()) == H5T_STRING) origin.text.emplace_back(name, h5::string_attribute(group.id(), name));
      else origin.numbers.emplace_back(name, h5::double_attribute(group.id(), name));
    }
    return origin;
  });
}

}  // namespace mesowave::dem
