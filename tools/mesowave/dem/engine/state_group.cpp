#include "mesowave/dem/engine/state_group.hpp"

#include <algorithm>
#include <stdexcept>
#include <type_traits>

#include "mesowave/core/error.hpp"
#include "mesowave/io/hdf5.hpp"

namespace mesowave::dem {
namespace {

static_assert(std::is_same_v<hid_t, std::int64_t>, "StateGroup keeps an hid_t as int64");

std::vector<double> flat(const std::vector<Vec3>& values) {
  std::vector<double> d(3 * values.size());
  for (std::size_t k = 0; k < values.size(); ++k)
    for (int c = 0; c < 3; ++c) d[3 * k + std::size_t(c)] = values[k][c];
  return d;
}

std::string child_path(const std::string& where, const std::string& name) {
  return where + (!where.empty() && where.back() == '/' ? "" : "/") + name;
}

// The path of `name` in the group at `where`; InputError if the group has no such link.
std::string existing(std::int64_t id, const std::string& where, const std::string& name) {
  std::string at = child_path(where, name);
  if (!io::h5::has_link(id, name)) throw InputError("checkpoint " + at + " is missing: the checkpoint is not from this run");
  return at;
}

InputError not_an_index_at(const std::string& where, std::int64_t v) {
  return InputError("checkpoint " + where + " holds " + std::to_string(v) + ", not an index");
}

std::uint32_t as_index(std::int64_t v, const std::string& where) {
  if (!StateGroup::is_index(v)) throw not_an_index_at(where, v);
  return std::uint32_t(v);
}

// The rows at ascending `at` of a dataset of `rows` rows of `cols` values (0: 1-D), from pieces read by
// read_rows(first, count, &shape); keep(out, piece, offset) appends the row at `offset` of the piece.
template <class T, class Piece, class ReadRows, class Keep>
std::vector<T> rows_at(const std::string& where, std::size_t rows, std::size_t cols, const std::vector<std::uint32_t>& at,
                       const ReadRows& read_rows, const Keep& keep) {
  std::vector<hsize_t> shape;
  read_rows(0, 0, &shape);
  const bool fits = !shape.empty() && shape[0] == rows && (cols == 0 ? shape.size() == 1 : shape.size() == 2 && shape[1] == cols);
  if (!fits)
    throw InputError("checkpoint " + where + " holds " + std::to_string(shape.empty() ? 0 : shape[0]) + " rows, this run " +
                     std::to_string(rows) + ": the checkpoint is not from this run");
  for (std::size_t i = 0; i < at.size(); ++i)
    if (at[i] >= rows || (i > 0 && at[i] <= at[i - 1])) throw std::logic_error("StateGroup: rows not ascending within the array");
  std::vector<T> out;
  out.reserve(at.size());
  for (std::size_t i = 0; i < at.size();) {
    // One piece: from this row up to kPieceRows on, and the wanted rows in it.
    const std::size_t first = at[i];
    const std::size_t end = std::min(rows, first + StateGroup::kPieceRows);
    std::size_t last = i;
    while (last + 1 < at.size() && at[last + 1] < end) ++last;
    const Piece piece = read_rows(first, at[last] + 1 - first, nullptr);
    for (; i <= last; ++i) keep(out, piece, std::size_t(at[i]) - first);
  }
  return out;
}

}  // namespace

StateGroup::~StateGroup() {
  if (id_ >= 0) io::h5::Handle close(id_);
}

StateGroup StateGroup::create(const std::string& name) {
  if (id_ < 0) return nowhere();
  io::h5::Handle g = io::h5::create_group(id_, name);
  H5Iinc_ref(g.id());  // the StateGroup holds one reference, the Handle drops its own
  return StateGroup(g.id(), child_path(where_, name));
}

StateGroup StateGroup::open(const std::string& name) const {
  const std::string at = existing(id_, where_, name);
  io::h5::Handle g = io::h5::open_group(id_, name, "checkpoint " + at);
  H5Iinc_ref(g.id());  // as in create()
  return StateGroup(g.id(), at);
}

void StateGroup::write(const std::string& name, double value) {
  if (id_ >= 0) io::h5::write_doubles(id_, name, {value});
}
void StateGroup::write(const std::string& name, std::int64_t value) {
  if (id_ >= 0) io::h5::write_int64s(id_, name, {value});
}
void StateGroup::write(const std::string& name, const std::vector<double>& values) {
  if (id_ >= 0) io::h5::write_doubles(id_, name, values);
}
void StateGroup::write(const std::string& name, const std::vector<Vec3>& values) {
  if (id_ >= 0) io::h5::write_doubles(id_, name, flat(values), 3);
}
void StateGroup::write(const std::string& name, const std::vector<std::uint32_t>& values) {
  if (id_ >= 0) io::h5::write_int64s(id_, name, std::vector<std::int64_t>(values.begin(), values.end()));
}

StateGroup::Rows::Rows(std::unique_ptr<io::h5::RowWriter> writer, bool indices) : writer_(std::move(writer)), indices_(indices) {}
StateGroup::Rows::Rows(Rows&&) noexcept = default;
StateGroup::Rows::~Rows() = default;

void StateGroup::Rows::write(std::size_t first, const std::vector<double>& values) {
  if (!writer_) return;
  if (indices_) writer_->write_rows(first, std::vector<std::int64_t>(values.begin(), values.end()));
  else writer_->write_rows(first, values);
}

StateGroup::Rows StateGroup::write_rows(const std::string& name, std::size_t rows, std::size_t cols, bool indices) const {
  if (id_ < 0) return Rows(nullptr, indices);
  return Rows(std::make_unique<io::h5::RowWriter>(id_, name, rows, cols, indices), indices);
}

std::vector<double> StateGroup::read_doubles(const std::string& name) const {
  existing(id_, where_, name);
  return io::h5::read_doubles(id_, name);
}

std::vector<std::uint32_t> StateGroup::read_uint32s(const std::string& name) const {
  existing(id_, where_, name);
  const std::vector<std::int64_t> v = io::h5::read_int64s(id_, name);
  std::vector<std::uint32_t> out(v.size());
  for (std::size_t k = 0; k < v.size(); ++k) out[k] = as_index(v[k], child_path(where_, name));
  return out;
}

std::vector<std::uint32_t> StateGroup::read_uint32s(const std::string& name, std::size_t first, std::size_t count,
                                                    std::size_t* rows) const {
  const std::vector<std::int64_t> v = read_int64s(name, first, count, rows);
  const std::string at = child_path(where_, name);
  std::vector<std::uint32_t> out(v.size());
  for (std::size_t k = 0; k < v.size(); ++k) out[k] = as_index(v[k], at);
  return out;
}

std::vector<std::int64_t> StateGroup::read_int64s(const std::string& name, std::size_t first, std::size_t count,
                                                  std::size_t* rows) const {
  existing(id_, where_, name);
  std::vector<hsize_t> shape;
  std::vector<std::int64_t> v = io::h5::read_int64_rows(id_, name, first, count, &shape);
  if (rows) *rows = std::size_t(shape[0]);
  return v;
}

InputError StateGroup::not_an_index(const std::string& name, std::int64_t value) const {
  return not_an_index_at(child_path(where_, name), value);
}

std::vector<double> StateGroup::read_at(const std::string& name, std::size_t rows, const std::vector<std::uint32_t>& at) const {
  const std::string where = existing(id_, where_, name);
  return rows_at<double, std::vector<double>>(
      where, rows, 0, at, [&](std::size_t first, std::size_t count, std::vector<hsize_t>* shape) {
        return io::h5::read_double_rows(id_, name, first, count, shape);
      },
      [](std::vector<double>& out, const std::vector<double>& piece, std::size_t r) { out.push_back(piece[r]); });
}

std::vector<Vec3> StateGroup::read_vec3s_at(const std::string& name, std::size_t rows, const std::vector<std::uint32_t>& at) const {
  const std::string where = existing(id_, where_, name);
  return rows_at<Vec3, std::vector<double>>(
      where, rows, 3, at, [&](std::size_t first, std::size_t count, std::vector<hsize_t>* shape) {
        return io::h5::read_double_rows(id_, name, first, count, shape);
      },
      [](std::vector<Vec3>& out, const std::vector<double>& piece, std::size_t r) {
        out.push_back({piece[3 * r], piece[3 * r + 1], piece[3 * r + 2]});
      });
}

std::vector<std::uint32_t> StateGroup::read_uint32s_at(const std::string& name, std::size_t rows,
                                                       const std::vector<std::uint32_t>& at) const {
  const std::string where = existing(id_, where_, name);
  return rows_at<std::uint32_t, std::vector<std::int64_t>>(
      where, rows, 0, at, [&](std::size_t first, std::size_t count, std::vector<hsize_t>* shape) {
        return io::h5::read_int64_rows(id_, name, first, count, shape);
      },
      [&](std::vector<std::uint32_t>& out, const std::vector<std::int64_t>& piece, std::size_t r) {
        out.push_back(as_index(piece[r], where));
      });
}

void StateGroup::write_text(const std::string& key, const std::string& text) {
  if (id_ >= 0) io::h5::set_attribute(id_, key, text);
}

void StateGroup::expect_text(const std::string& key, const std::string& text) const {
  const std::string held = io::h5::has_attribute(id_, key) ? io::h5::string_attribute(id_, key) : "";
  if (held != text)
    throw InputError("checkpoint " + where_ + " holds " + key + " \"" + held + "\" where this run has \"" + text +
                     "\": the checkpoint is not from this run");
}

double StateGroup::read_double(const std::string& name) const {
  const std::vector<double> v = read_doubles(name);
  if (v.size() != 1)
    throw InputError("checkpoint " + child_path(where_, name) + " holds " + std::to_string(v.size()) + " values where one is expected");
  return v[0];
}

std::int64_t StateGroup::read_int64(const std::string& name) const {
  existing(id_, where_, name);
  const std::vector<std::int64_t> v = io::h5::read_int64s(id_, name);
  if (v.size() != 1)
    throw InputError("checkpoint " + child_path(where_, name) + " holds " + std::to_string(v.size()) + " values where one is expected");
  return v[0];
}

void StateGroup::read_into(const std::string& name, std::vector<double>& values) const {
  std::vector<double> v = read_doubles(name);
  if (v.size() != values.size())
    throw InputError("checkpoint " + child_path(where_, name) + " holds " + std::to_string(v.size()) + " values, this run " +
                     std::to_string(values.size()) + ": the checkpoint is not from this run");
  values = std::move(v);
}

void StateGroup::read_into(const std::string& name, std::vector<Vec3>& values) const {
  const std::vector<double> v = read_doubles(name);
  if (v.size() != 3 * values.size())
    throw InputError("checkpoint " + child_path(where_, name) + " holds " + std::to_string(v.size() / 3) + " vectors, this run " +
                     std::to_string(values.size()) + ": the checkpoint is not from this run");
  for (std::size_t k = 0; k < values.size(); ++k) values[k] = {v[3 * k], v[3 * k + 1], v[3 * k + 2]};
}

}  // namespace mesowave::dem
