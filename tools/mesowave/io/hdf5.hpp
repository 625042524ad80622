#pragma once
// A thin RAII layer over the HDF5 C API: files, groups, 1-D/2-D float64 and
// int64 datasets, and scalar/string/vector attributes. Enough for the signal,
// packing and snapshot files; anything fancier uses the C API directly.
#include <hdf5.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace mesowave::io::h5 {

/// Owns one HDF5 identifier and closes it with the right H5*close.
class Handle {
public:
  Handle() = default;
  explicit Handle(hid_t id) : id_(id) {}
  Handle(Handle&& other) noexcept : id_(other.id_) { other.id_ = H5I_INVALID_HID; }
  Handle& operator=(Handle&& other) noexcept;
  Handle(const Handle&) = delete;
  ~Handle();
  hid_t id() const { return id_; }
  explicit operator bool() const { return id_ >= 0; }

private:
  hid_t id_ = H5I_INVALID_HID;
};

/// Creates (truncating) a file that remembers link creation order, so groups
/// list in the order they were written.
Handle create_file(const std::filesystem::path& path);
/// Opens a file read-only; InputError if it is missing or not HDF5.
Handle open_file(const std::filesystem::path& path);

Handle create_group(hid_t parent, const std::string& name);
/// InputError naming `what` if the group is missing.
Handle open_group(hid_t parent, const std::string& name, const std::string& what);
bool has_link(hid_t parent, const std::string& name);
/// Names of the links in a group, in creation order when tracked.
std::vector<std::string> list_links(hid_t group);

/// Row-major datasets; `cols` = 0 writes a 1-D dataset. Chunked and
/// deflate-compressed when `compress` is set and the dataset is large.
void write_doubles(hid_t parent, const std::string& name, const std::vector<double>& data, std::size_t cols = 0,
                   bool compress = false);
void write_int64s(hid_t parent, const std::string& name, const std::vector<std::int64_t>& data, std::size_t cols = 0);
/// A dataset of `rows` rows (`cols` = 0: 1-D) of float64 or int64, uncompressed, written a piece at
/// a time (write_rows), ascending or not: once every row is written it holds what write_doubles or
/// write_int64s would have written whole (what is too large to hold whole: a distributed
/// checkpoint's rank 0 writes each piece as it arrives from the ranks).
class RowWriter {
public:
  RowWriter(hid_t parent, const std::string& name, std::size_t rows, std::size_t cols, bool int64);
  /// Rows [first, first + values.size() / max(cols, 1)).
  void write_rows(std::size_t first, const std::vector<double>& values);
  void write_rows(std::size_t first, const std::vector<std::int64_t>& values);

private:
  template <typename T>
  void write(std::size_t first, const std::vector<T>& values, hid_t mem_type);
  Handle set_;
  std::string name_;
  std::size_t rows_, cols_;
};
std::vector<double> read_doubles(hid_t parent, const std::string& name, std::vector<hsize_t>* shape = nullptr);
std::vector<std::int64_t> read_int64s(hid_t parent, const std::string& name, std::vector<hsize_t>* shape = nullptr);
/// Rows [first, first + count) of a 1-D or 2-D dataset (row-major, one hyperslab), and `shape`
/// its dimensions: a piece of a dataset too large to hold whole. InputError if the rows are not there.
std::vector<double> read_double_rows(hid_t parent, const std::string& name, std::size_t first, std::size_t count,
                                     std::vector<hsize_t>* shape = nullptr);
std::vector<std::int64_t> read_int64_rows(hid_t parent, const std::string& name, std::size_t first, std::size_t count,
                                          std::vector<hsize_t>* shape = nullptr);

void set_attribute(hid_t object, const std::string& name, const std::string& value);
void set_attribute(hid_t object, const std::string& name, double value);
void set_attribute(hid_t object, const std::string& name, std::int64_t value);
void set_attribute(hid_t object, const std::string& name, const std::vector<double>& value);
bool has_attribute(hid_t object, const std::string& name);
std::string string_attribute(hid_t object, const std::string& name);
double double_attribute(hid_t object, const std::string& name);
std::vector<double> doubles_attribute(hid_t object, const std::string& name);

}  // namespace mesowave::io::h5
