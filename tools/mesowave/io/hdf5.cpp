#include "mesowave/io/hdf5.hpp"

#include <limits>
#include <stdexcept>

#include "mesowave/core/error.hpp"

namespace mesowave::io::h5 {
namespace {

// HDF5 prints its own error stack to stderr by default; mesowave reports
// errors itself, one line each.
struct SilenceHdf5 {
  SilenceHdf5() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }
};
const SilenceHdf5 silence;

hid_t check(hid_t id, const std::string& what) {
  if (id < 0) throw std::runtime_error("HDF5: cannot " + what);
  return id;
}

void check_status(herr_t status, const std::string& what) {
  if (status < 0) throw std::runtime_error("HDF5: cannot " + what);
}

// Reading a file the user handed over: a failure is a damaged or foreign file
// (an InputError), not mesowave's fault as a failed write would be.
hid_t check_read(hid_t id, const std::string& what) {
  if (id < 0) throw InputError("HDF5: cannot " + what + " (damaged file, or a type mesowave does not read)");
  return id;
}
void check_read_status(herr_t status, const std::string& what) { check_read(status < 0 ? -1 : 0, what); }

// H5Aread/H5Dread convert to the memory type and fill as many values as the
// object holds: only numbers convert to numbers, and a scalar read needs
// exactly one value, else HDF5 writes past it (an array where one number was
// expected, as h5py writes for attrs["dt_s"] = [1e-7, ...]).
void require_number(hid_t type, const std::string& what) {
  const H5T_class_t type_class = H5Tget_class(type);
  if (type_class != H5T_INTEGER && type_class != H5T_FLOAT) throw InputError("HDF5 " + what + " is not numeric");
}
void require_one_value(hid_t attr, const std::string& name) {
  Handle space(check_read(H5Aget_space(attr), "get the dataspace of attribute " + name));
  const hssize_t n = H5Sget_simple_extent_npoints(space.id());
  if (n != 1)
    throw InputError("HDF5 attribute '" + name + "' holds " + std::to_string(n) + " values where one is expected");
}

std::vector<hsize_t> dims_for(std::size_t size, std::size_t cols) {
  if (cols == 0) return {hsize_t(size)};
  if (size % cols != 0) throw std::logic_error("dataset size is not a multiple of its column count");
  return {hsize_t(size / cols), hsize_t(cols)};
}

Handle create_dataset(hid_t parent, const std::string& name, const std::vector<hsize_t>& dims, std::size_t cols,
                      hid_t file_type, bool compress) {
  Handle space(check(H5Screate_simple(int(dims.size()), dims.data(), nullptr), "create dataspace for " + name));
  Handle props(check(H5Pcreate(H5P_DATASET_CREATE), "create dataset properties"));
  H5Pset_obj_track_times(props.id(), false);  // same inputs, same bytes: no modification times
  if (compress && dims[0] * (cols ? cols : 1) >= 4096) {
    std::vector<hsize_t> chunk = dims;
    chunk[0] = std::min<hsize_t>(dims[0], std::max<hsize_t>(1, 65536 / (cols ? cols : 1)));
    check_status(H5Pset_chunk(props.id(), int(chunk.size()), chunk.data()), "chunk " + name);
    check_status(H5Pset_shuffle(props.id()), "shuffle " + name);
    check_status(H5Pset_deflate(props.id(), 4), "compress " + name);
  }
  return Handle(check(H5Dcreate2(parent, name.c_str(), file_type, space.id(), H5P_DEFAULT, props.id(), H5P_DEFAULT),
                      "create dataset " + name));
}

template <typename T>
void write_dataset(hid_t parent, const std::string& name, const std::vector<T>& data, std::size_t cols, hid_t mem_type,
                   hid_t file_type, bool compress) {
  const Handle set = create_dataset(parent, name, dims_for(data.size(), cols), cols, file_type, compress);
  if (!data.empty())
    check_status(H5Dwrite(set.id(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), "write dataset " + name);
}

// A numeric dataset opened for reading, its dataspace and dimensions; InputError if it is missing or not numbers.
struct NumericDataset {
  Handle set, space;
  std::vector<hsize_t> dims;
};
NumericDataset open_numeric(hid_t parent, const std::string& name) {
  if (!has_link(parent, name)) throw InputError("HDF5 dataset '" + name + "' is missing");
  Handle set(check_read(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), "open dataset " + name));
  Handle type(check_read(H5Dget_type(set.id()), "get the type of dataset " + name));
  require_number(type.id(), "dataset '" + name + "'");
  Handle space(check_read(H5Dget_space(set.id()), "get dataspace of " + name));
  const int rank = H5Sget_simple_extent_ndims(space.id());
  check_read_status(rank, "get the rank of dataset " + name);
  std::vector<hsize_t> dims(static_cast<std::size_t>(std::max(rank, 0)));
  H5Sget_simple_extent_dims(space.id(), dims.data(), nullptr);
  return {std::move(set), std::move(space), std::move(dims)};
}

template <typename T>
std::vector<T> read_dataset(hid_t parent, const std::string& name, hid_t mem_type, std::vector<hsize_t>* shape) {
  const auto [set, space, dims] = open_numeric(parent, name);
  std::size_t count = 1;
  for (auto d : dims) {
    if (d != 0 && count > std::numeric_limits<std::size_t>::max() / sizeof(T) / std::size_t(d))
      throw InputError("HDF5 dataset '" + name + "' is larger than memory can hold");
    count *= std::size_t(d);
  }
  // The dimensions are a few header bytes and can claim anything (found by
  // libFuzzer: 2^54 values in a 2 kB file); what is stored bounds what is
  // read. deflate expands at most 1032:1; beyond 64 MiB a dataset must hold at
  // least 1/1100 of its size, else it is refused before it is allocated.
  const std::uint64_t bytes = std::uint64_t(count) * sizeof(T), stored = H5Dget_storage_size(set.id());
  if (bytes > (std::uint64_t(64) << 20) && bytes / 1100 > stored)
    throw InputError("HDF5 dataset '" + name + "' claims " + std::to_string(count) + " values but stores " +
                     std::to_string(stored) + " bytes (a damaged file)");
  std::vector<T> data(count);
  if (count > 0)
    check_read_status(H5Dread(set.id(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), "read dataset " + name);
  if (shape) *shape = dims;
  return data;
}

Handle open_attribute(hid_t object, const std::string& name) {
  if (H5Aexists(object, name.c_str()) <= 0) throw InputError("HDF5 attribute '" + name + "' is missing");
  return Handle(check_read(H5Aopen(object, name.c_str(), H5P_DEFAULT), "open attribute " + name));
}

void replace_attribute(hid_t object, const std::string& name) {
  if (H5Aexists(object, name.c_str()) > 0) H5Adelete(object, name.c_str());
}

}  // namespace

Handle& Handle::operator=(Handle&& other) noexcept {
  if (this != &other) {
    Handle old(id_);
    id_ = other.id_;
    other.id_ = H5I_INVALID_HID;
  }
  return *this;
}

Handle::~Handle() {
  if (id_ < 0) return;
  switch (H5Iget_type(id_)) {
    case H5I_FILE: H5Fclose(id_); break;
    case H5I_GROUP: H5Gclose(id_); break;
    case H5I_DATASET: H5Dclose(id_); break;
    case H5I_DATASPACE: H5Sclose(id_); break;
    case H5I_DATATYPE: H5Tclose(id_); break;
    case H5I_ATTR: H5Aclose(id_); break;
    case H5I_GENPROP_LST: H5Pclose(id_); break;
    default: break;
  }
}

Handle create_file(const std::filesystem::path& path) {
  Handle props(check(H5Pcreate(H5P_FILE_CREATE), "create file properties"));
  H5Pset_link_creation_order(props.id(), H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED);
  const hid_t id = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, props.id(), H5P_DEFAULT);
  if (id < 0) throw InputError("cannot create HDF5 file " + path.string());
  return Handle(id);
}

Handle open_file(const std::filesystem::path& path) {
  if (!std::filesystem::is_regular_file(path)) throw InputError("file " + path.string() + " does not exist");
  if (H5Fis_hdf5(path.c_str()) <= 0) throw InputError(path.string() + " is not an HDF5 file");
  const hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (id < 0) throw InputError("cannot open HDF5 file " + path.string());
  return Handle(id);
}

Handle create_group(hid_t parent, const std::string& name) {
  Handle props(check(H5Pcreate(H5P_GROUP_CREATE), "create group properties"));
  H5Pset_obj_track_times(props.id(), false);
  H5Pset_link_creation_order(props.id(), H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED);
  return Handle(check(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, props.id(), H5P_DEFAULT), "create group " + name));
}

Handle open_group(hid_t parent, const std::string& name, const std::string& what) {
  if (!has_link(parent, name)) throw InputError(what + ": HDF5 group '" + name + "' is missing");
  return Handle(check_read(H5Gopen2(parent, name.c_str(), H5P_DEFAULT), "open group " + name));
}

bool has_link(hid_t parent, const std::string& name) { return H5Lexists(parent, name.c_str(), H5P_DEFAULT) > 0; }

std::vector<std::string> list_links(hid_t group) {
  H5G_info_t info{};
  check_read_status(H5Gget_info(group, &info), "list group");
  // Creation order if the group tracks it, else names in alphabetical order.
  Handle props(H5Gget_create_plist(group));
  unsigned flags = 0;
  if (props) H5Pget_link_creation_order(props.id(), &flags);
  const H5_index_t index = (flags & H5P_CRT_ORDER_TRACKED) ? H5_INDEX_CRT_ORDER : H5_INDEX_NAME;
  std::vector<std::string> names;
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t length = H5Lget_name_by_idx(group, ".", index, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
    if (length < 0) check_read_status(-1, "read the name of link " + std::to_string(i));
    std::string name(std::size_t(length), '\0');
    H5Lget_name_by_idx(group, ".", index, H5_ITER_INC, i, name.data(), std::size_t(length) + 1, H5P_DEFAULT);
    names.push_back(name);
  }
  return names;
}

void write_doubles(hid_t parent, const std::string& name, const std::vector<double>& data, std::size_t cols,
                   bool compress) {
  write_dataset(parent, name, data, cols, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, compress);
}

void write_int64s(hid_t parent, const std::string& name, const std::vector<std::int64_t>& data, std::size_t cols) {
  write_dataset(parent, name, data, cols, H5T_NATIVE_INT64, H5T_STD_I64LE, false);
}

RowWriter::RowWriter(hid_t parent, const std::string& name, std::size_t rows, std::size_t cols, bool int64)
    : set_(create_dataset(parent, name, dims_for(rows * (cols ? cols : 1), cols), cols, int64 ? H5T_STD_I64LE : H5T_IEEE_F64LE,
                          false)),
      name_(name), rows_(rows), cols_(cols) {}

template <typename T>
void RowWriter::write(std::size_t first, const std::vector<T>& values, hid_t mem_type) {
  const std::size_t width = cols_ ? cols_ : 1, count = values.size() / width;
  if (values.size() % width != 0 || first > rows_ || count > rows_ - first)
    throw std::logic_error("RowWriter: rows " + std::to_string(first) + " + " + std::to_string(count) + " of " + name_ +
                           " (" + std::to_string(rows_) + " rows)");
  if (count == 0) return;
  const int rank = cols_ ? 2 : 1;
  const hsize_t start[2] = {hsize_t(first), 0}, size[2] = {hsize_t(count), hsize_t(width)};
  Handle space(check(H5Dget_space(set_.id()), "get dataspace of " + name_));
  check_status(H5Sselect_hyperslab(space.id(), H5S_SELECT_SET, start, nullptr, size, nullptr), "select rows of " + name_);
  Handle memory(check(H5Screate_simple(rank, size, nullptr), "create a memory space for " + name_));
  check_status(H5Dwrite(set_.id(), mem_type, memory.id(), space.id(), H5P_DEFAULT, values.data()), "write rows of " + name_);
}

void RowWriter::write_rows(std::size_t first, const std::vector<double>& values) { write(first, values, H5T_NATIVE_DOUBLE); }
void RowWriter::write_rows(std::size_t first, const std::vector<std::int64_t>& values) {
  write(first, values, H5T_NATIVE_INT64);
}

template <typename T>
std::vector<T> read_rows(hid_t parent, const std::string& name, std::size_t first, std::size_t count, hid_t mem_type,
                         std::vector<hsize_t>* shape) {
  const auto [set, space, dims] = open_numeric(parent, name);
  const int rank = int(dims.size());
  if (rank != 1 && rank != 2) throw InputError("HDF5 dataset '" + name + "' is not a list of rows (rank " + std::to_string(rank) + ")");
  if (first > dims[0] || count > dims[0] - first)
    throw InputError("HDF5 dataset '" + name + "' has " + std::to_string(dims[0]) + " rows, not rows " + std::to_string(first) +
                     " to " + std::to_string(first + count));
  const hsize_t cols = rank == 2 ? dims[1] : 1;
  std::vector<T> data(count * std::size_t(cols));
  if (count > 0) {
    const hsize_t start[2] = {hsize_t(first), 0}, size[2] = {hsize_t(count), cols};
    check_read_status(H5Sselect_hyperslab(space.id(), H5S_SELECT_SET, start, nullptr, size, nullptr), "select rows of " + name);
    Handle memory(check_read(H5Screate_simple(rank, size, nullptr), "create a memory space for " + name));
    check_read_status(H5Dread(set.id(), mem_type, memory.id(), space.id(), H5P_DEFAULT, data.data()), "read rows of " + name);
  }
  if (shape) *shape = dims;
  return data;
}

std::vector<double> read_double_rows(hid_t parent, const std::string& name, std::size_t first, std::size_t count,
                                     std::vector<hsize_t>* shape) {
  return read_rows<double>(parent, name, first, count, H5T_NATIVE_DOUBLE, shape);
}

std::vector<std::int64_t> read_int64_rows(hid_t parent, const std::string& name, std::size_t first, std::size_t count,
                                          std::vector<hsize_t>* shape) {
  return read_rows<std::int64_t>(parent, name, first, count, H5T_NATIVE_INT64, shape);
}

std::vector<double> read_doubles(hid_t parent, const std::string& name, std::vector<hsize_t>* shape) {
  return read_dataset<double>(parent, name, H5T_NATIVE_DOUBLE, shape);
}

std::vector<std::int64_t> read_int64s(hid_t parent, const std::string& name, std::vector<hsize_t>* shape) {
  return read_dataset<std::int64_t>(parent, name, H5T_NATIVE_INT64, shape);
}

void set_attribute(hid_t object, const std::string& name, const std::string& value) {
  replace_attribute(object, name);
  // Fixed-length, null-terminated: what h5py, MATLAB and h5dump all read.
  Handle type(check(H5Tcopy(H5T_C_S1), "copy string type"));
  H5Tset_size(type.id(), std::max<std::size_t>(value.size(), 1));
  H5Tset_strpad(type.id(), H5T_STR_NULLTERM);
  H5Tset_cset(type.id(), H5T_CSET_UTF8);
  Handle space(check(H5Screate(H5S_SCALAR), "create scalar space"));
  Handle attr(check(H5Acreate2(object, name.c_str(), type.id(), space.id(), H5P_DEFAULT, H5P_DEFAULT),
                    "create attribute " + name));
  std::string padded = value.empty() ? std::string(1, '\0') : value;
  check_status(H5Awrite(attr.id(), type.id(), padded.data()), "write attribute " + name);
}

void set_attribute(hid_t object, const std::string& name, double value) {
  replace_attribute(object, name);
  Handle space(check(H5Screate(H5S_SCALAR), "create scalar space"));
  Handle attr(check(H5Acreate2(object, name.c_str(), H5T_IEEE_F64LE, space.id(), H5P_DEFAULT, H5P_DEFAULT),
                    "create attribute " + name));
  check_status(H5Awrite(attr.id(), H5T_NATIVE_DOUBLE, &value), "write attribute " + name);
}

void set_attribute(hid_t object, const std::string& name, std::int64_t value) {
  replace_attribute(object, name);
  Handle space(check(H5Screate(H5S_SCALAR), "create scalar space"));
  Handle attr(check(H5Acreate2(object, name.c_str(), H5T_STD_I64LE, space.id(), H5P_DEFAULT, H5P_DEFAULT),
                    "create attribute " + name));
  check_status(H5Awrite(attr.id(), H5T_NATIVE_INT64, &value), "write attribute " + name);
}

void set_attribute(hid_t object, const std::string& name, const std::vector<double>& value) {
  replace_attribute(object, name);
  const hsize_t n = value.size();
  Handle space(check(H5Screate_simple(1, &n, nullptr), "create attribute space"));
  Handle attr(check(H5Acreate2(object, name.c_str(), H5T_IEEE_F64LE, space.id(), H5P_DEFAULT, H5P_DEFAULT),
                    "create attribute " + name));
  check_status(H5Awrite(attr.id(), H5T_NATIVE_DOUBLE, value.data()), "write attribute " + name);
}

bool has_attribute(hid_t object, const std::string& name) { return H5Aexists(object, name.c_str()) > 0; }

std::string string_attribute(hid_t object, const std::string& name) {
  Handle attr = open_attribute(object, name);
  Handle type(check_read(H5Aget_type(attr.id()), "get attribute type"));
  if (H5Tget_class(type.id()) != H5T_STRING) throw InputError("HDF5 attribute '" + name + "' is not a string");
  require_one_value(attr.id(), name);
  if (H5Tis_variable_str(type.id()) > 0) {
    Handle mem(H5Tcopy(H5T_C_S1));
    H5Tset_size(mem.id(), H5T_VARIABLE);
    H5Tset_cset(mem.id(), H5Tget_cset(type.id()));  // h5py writes UTF-8; HDF5 converts no character sets
    char* text = nullptr;
    check_read_status(H5Aread(attr.id(), mem.id(), &text), "read attribute " + name);
    std::string value = text ? text : "";
    H5free_memory(text);
    return value;
  }
  const std::size_t size = H5Tget_size(type.id());
  std::string value(size, '\0');
  check_read_status(H5Aread(attr.id(), type.id(), value.data()), "read attribute " + name);
  value.resize(std::min(value.find('\0'), value.size()));
  return value;
}

// One number of any numeric type, converted to `mem_type`.
template <typename T>
T number_attribute(hid_t object, const std::string& name, hid_t mem_type) {
  Handle attr = open_attribute(object, name);
  Handle type(check_read(H5Aget_type(attr.id()), "get attribute type"));
  require_number(type.id(), "attribute '" + name + "'");
  require_one_value(attr.id(), name);
  T value = 0;
  check_read_status(H5Aread(attr.id(), mem_type, &value), "read attribute " + name);
  return value;
}

double double_attribute(hid_t object, const std::string& name) {
  return number_attribute<double>(object, name, H5T_NATIVE_DOUBLE);
}

std::vector<double> doubles_attribute(hid_t object, const std::string& name) {
  Handle attr = open_attribute(object, name);
  Handle type(check_read(H5Aget_type(attr.id()), "get attribute type"));
  require_number(type.id(), "attribute '" + name + "'");
  Handle space(check_read(H5Aget_space(attr.id()), "get the dataspace of attribute " + name));
  const hssize_t n = H5Sget_simple_extent_npoints(space.id());
  std::vector<double> value(std::size_t(std::max<hssize_t>(n, 0)));
  if (!value.empty())
    check_read_status(H5Aread(attr.id(), H5T_NATIVE_DOUBLE, value.data()), "read attribute " + name);
  return value;
}

}  // namespace mesowave::io::h5
