#include "mesowave/dem/engine/state_group.hpp"

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
  const std::string at = child_path(where_, name);
  if (!io::h5::has_link(id_, name)) throw InputError("checkpoint " + at + " is missing: the checkpoint is not from this run");
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

std::vector<double> StateGroup::read_doubles(const std::string& name) const {
  if (!io::h5::has_link(id_, name))
    throw InputError("checkpoint " + child_path(where_, name) + " is missing: the checkpoint is not from this run");
  return io::h5::read_doubles(id_, name);
}

std::vector<std::uint32_t> StateGroup::read_uint32s(const std::string& name) const {
  if (!io::h5::has_link(id_, name))
    throw InputError("checkpoint " + child_path(where_, name) + " is missing: the checkpoint is not from this run");
  const std::vector<std::int64_t> v = io::h5::read_int64s(id_, name);
  std::vector<std::uint32_t> out(v.size());
  for (std::size_t k = 0; k < v.size(); ++k) {
    if (v[k] < 0 || v[k] > std::int64_t(UINT32_MAX))
      throw InputError("checkpoint " + child_path(where_, name) + " holds " + std::to_string(v[k]) + ", not an index");
    out[k] = std::uint32_t(v[k]);
  }
  return out;
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
  if (!io::h5::has_link(id_, name))
    throw InputError("checkpoint " + child_path(where_, name) + " is missing: the checkpoint is not from this run");
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
