#include "mesowave/signal/signal_file.hpp"

#include <cmath>

#include "mesowave/core/error.hpp"
#include "mesowave/io/hdf5.hpp"

namespace mesowave::signal {

void write_signal_file(const std::filesystem::path& path, const std::vector<Signal>& signals,
                       const std::map<std::string, std::string>& file_attributes) {
  auto file = io::h5::create_file(path);
  io::h5::set_attribute(file.id(), "format", std::string("mesowave-signals"));
  io::h5::set_attribute(file.id(), "format_version", std::int64_t(1));
  for (const auto& [key, value] : file_attributes) io::h5::set_attribute(file.id(), key, value);
  auto group = io::h5::create_group(file.id(), "signals");
  for (const auto& s : signals) {
    if (s.name.empty() || s.name.find('/') != std::string::npos)
      throw InputError("signal name '" + s.name + "' must be non-empty and contain no '/'");
    if (!(s.dt_s > 0) || !std::isfinite(s.dt_s))
      throw std::logic_error("signal " + s.name + " has a non-positive sampling interval");
    auto g = io::h5::create_group(group.id(), s.name);
    io::h5::write_doubles(g.id(), "samples", s.samples, 0, true);
    io::h5::set_attribute(g.id(), "t0_s", s.t0_s);
    io::h5::set_attribute(g.id(), "dt_s", s.dt_s);
    io::h5::set_attribute(g.id(), "quantity", s.quantity);
    io::h5::set_attribute(g.id(), "unit", s.unit);
    io::h5::set_attribute(g.id(), "component", s.component);
    if (s.position_m)
      io::h5::set_attribute(g.id(), "position_m", std::vector<double>(s.position_m->begin(), s.position_m->end()));
  }
}

std::vector<Signal> read_signal_file(const std::filesystem::path& path) {
  auto file = io::h5::open_file(path);
  if (!io::h5::has_attribute(file.id(), "format") || io::h5::string_attribute(file.id(), "format") != "mesowave-signals")
    throw InputError(path.string() + " is an HDF5 file but not a mesowave signal file (no format = mesowave-signals)");
  auto group = io::h5::open_group(file.id(), "signals", path.string());
  std::vector<Signal> signals;
  for (const auto& name : io::h5::list_links(group.id())) {
    auto g = io::h5::open_group(group.id(), name, path.string());
    Signal s;
    s.name = name;
    try {
      s.samples = io::h5::read_doubles(g.id(), "samples");
      s.t0_s = io::h5::double_attribute(g.id(), "t0_s");
      s.dt_s = io::h5::double_attribute(g.id(), "dt_s");
      s.quantity = io::h5::string_attribute(g.id(), "quantity");
      s.unit = io::h5::string_attribute(g.id(), "unit");
      s.component = io::h5::has_attribute(g.id(), "component") ? io::h5::string_attribute(g.id(), "component") : "";
      if (io::h5::has_attribute(g.id(), "position_m")) {
        const auto p = io::h5::doubles_attribute(g.id(), "position_m");
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

}  // namespace mesowave::signal
