#include "mesowave/io/signal_file.hpp"

#include <cmath>

#include "mesowave/core/error.hpp"
#include "mesowave/io/hdf5.hpp"

namespace mesowave::io {

void write_signal_file(const std::filesystem::path& path, const std::vector<signal::Signal>& signals,
                       const std::map<std::string, std::string>& file_attributes) {
  auto file = h5::create_file(path);
  h5::set_attribute(file.id(), "format", std::string("mesowave-signals"));
  h5::set_attribute(file.id(), "format_version", std::int64_t(1));
  for (const auto& [key, value] : file_attributes) h5::set_attribute(file.id(), key, value);
  auto group = h5::create_group(file.id(), "signals");
  for (const auto& s : signals) {
    if (s.name.empty() || s.name.find('/') != std::string::npos)
      throw InputError("signal name '" + s.name + "' must be non-empty and contain no '/'");
    if (!(s.dt_s > 0) || !std::isfinite(s.dt_s))
      throw std::logic_error("signal " + s.name + " has a non-positive sampling interval");
    auto g = h5::create_group(group.id(), s.name);
    h5::write_doubles(g.id(), "samples", s.samples, 0, true);
    h5::set_attribute(g.id(), "t0_s", s.t0_s);
    h5::set_attribute(g.id(), "dt_s", s.dt_s);
    h5::set_attribute(g.id(), "quantity", s.quantity);
    h5::set_attribute(g.id(), "unit", s.unit);
    h5::set_attribute(g.id(), "component", s.component);
    if (s.position_m)
      h5::set_attribute(g.id(), "position_m", std::vector<double>(s.position_m->begin(), s.position_m->end()));
  }
}

std::vector<signal::Signal> read_signal_file(const std::filesystem::path& path) {
  auto file = h5::open_file(path);
  if (!h5::has_attribute(file.id(), "format") || h5::string_attribute(file.id(), "format") != "mesowave-signals")
    throw InputError(path.string() + " is an HDF5 file but not a mesowave signal file (no format = mesowave-signals)");
  auto group = h5::open_group(file.id(), "signals", path.string());
  std::vector<signal::Signal> signals;
  for (const auto& name : h5::list_links(group.id())) {
    auto g = h5::open_group(group.id(), name, path.string());
    signal::Signal s;
    s.name = name;
    try {
      s.samples = h5::read_doubles(g.id(), "samples");
      s.t0_s = h5::double_attribute(g.id(), "t0_s");
      s.dt_s = h5::double_attribute(g.id(), "dt_s");
      s.quantity = h5::string_attribute(g.id(), "quantity");
      s.unit = h5::string_attribute(g.id(), "unit");
      s.component = h5::has_attribute(g.id(), "component") ? h5::string_attribute(g.id(), "component") : "";
      if (h5::has_attribute(g.id(), "position_m")) {
        const auto p = h5::doubles_attribute(g.id(), "position_m");
        if (p.size() == 3) s.position_m = std::array<double, 3>{p[0], p[1], p[2]};
      }
    } catch (const InputError& e) {
      throw InputError(path.string() + ": signal '" + name + "': " + e.what());
    }
    if (!(s.dt_s > 0) || !std::isfinite(s.dt_s))
      throw InputError(path.string() + ": signal '" + name + "' has dt_s = " + std::to_string(s.dt_s) + " (must be > 0)");
    signals.push_back(std::move(s));
  }
  return signals;
}

}  // namespace mesowave::io
