#include "mesowave/signal/signal_csv.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/io/csv.hpp"
#include "mesowave/signal/signal_file.hpp"

namespace mesowave::signal {
namespace {

// Seconds per unit of a time column, from "t_us", "time_ms", "t [us]", "time [s]".
double time_column_factor(const std::string& header) {
  std::string unit;
  const auto bracket = header.find('[');
  if (bracket != std::string::npos && header.back() == ']') {
    const std::string name = io::trim_blanks(header.substr(0, bracket));
    if (name != "t" && name != "time") return 0;
    unit = io::trim_blanks(header.substr(bracket + 1, header.size() - bracket - 2));
  } else {
    for (const char* prefix : {"t_", "time_"})
      if (header.rfind(prefix, 0) == 0) unit = header.substr(std::string(prefix).size());
  }
  if (unit == "s") return 1.0;
  if (unit == "ms") return 1e-3;
  if (unit == "us") return 1e-6;
  if (unit == "ns") return 1e-9;
  return 0;
}

void check_csv_name(const std::string& name) {
  if (name.empty() || name.find_first_of(",\"[]:\n\r") != std::string::npos || io::trim_blanks(name) != name)
    throw InputError("signal name '" + name +
                     "' cannot be a CSV column (no commas, quotes, brackets, colons or outer spaces)");
}

struct Metadata {
  std::string quantity, component;
  std::optional<std::array<double, 3>> position_m;
};

// "# signal B: quantity=acceleration; component=z; position_m=0.025 0 0.05"
void parse_metadata_line(std::string_view line, const std::string& origin, std::size_t line_no,
                         std::map<std::string, Metadata>& out) {
  const std::string_view prefix = "# signal ";
  if (line.substr(0, prefix.size()) != prefix) return;
  const auto colon = line.find(':', prefix.size());
  if (colon == std::string_view::npos) return;
  const std::string name = io::trim_blanks(line.substr(prefix.size(), colon - prefix.size()));
  Metadata m;
  std::stringstream fields{std::string(line.substr(colon + 1))};
  std::string field;
  while (std::getline(fields, field, ';')) {
    const auto eq = field.find('=');
    if (eq == std::string::npos) continue;
    const std::string key = io::trim_blanks(field.substr(0, eq)), value = io::trim_blanks(field.substr(eq + 1));
    if (key == "quantity") m.quantity = value;
    else if (key == "component") m.component = value;
    else if (key == "position_m") {
      std::stringstream numbers(value);
      std::array<double, 3> p{};
      if (!(numbers >> p[0] >> p[1] >> p[2]) || !std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
        throw InputError(origin + ":" + std::to_string(line_no) + ": position_m of signal " + name +
                         " must be three numbers");
      m.position_m = p;
    }
  }
  out[name] = m;
}

}  // namespace

std::string signals_to_csv(const std::vector<Signal>& signals,
                           const std::map<std::string, std::string>& file_attributes) {
  if (signals.empty()) throw InputError("no signals to write");
  const auto& first = signals.front();
  std::set<std::string> names;
  for (const auto& s : signals) {
    check_csv_name(s.name);
    if (!names.insert(s.name).second) throw InputError("signal name '" + s.name + "' appears twice");
    if (s.unit.find_first_of("[]\n\r,\"") != std::string::npos)
      throw InputError("unit '" + s.unit + "' of signal " + s.name + " cannot go in a CSV header");
    const bool same = s.samples.size() == first.samples.size() && std::abs(s.dt_s - first.dt_s) <= 1e-9 * first.dt_s &&
                      std::abs(s.t0_s - first.t0_s) <= 1e-6 * first.dt_s;
    if (!same)
      throw InputError("signals " + first.name + " and " + s.name +
                       " are sampled differently; a CSV file holds one time column (write HDF5, or resample first)");
    for (std::size_t i = 0; i < s.samples.size(); ++i)
      if (!std::isfinite(s.samples[i]))
        throw InputError("signal " + s.name + ": sample " + std::to_string(i) + " is not finite");
  }
  if (!(first.dt_s > 0) || !std::isfinite(first.dt_s) || !std::isfinite(first.t0_s))
    throw InputError("signal " + first.name + " has no valid time base (dt_s must be positive)");

  std::string out = "# mesowave signals (CSV): time in the first column, one column per signal, \"name [unit]\"\n";
  for (const auto& [key, value] : file_attributes) {
    std::string v = value;
    std::replace(v.begin(), v.end(), '\n', ' ');
    out += "# " + key + ": " + v + "\n";
  }
  for (const auto& s : signals) {
    out += "# signal " + s.name + ": quantity=" + s.quantity + "; component=" + s.component;
    if (s.position_m)
      out += "; position_m=" + format_exact((*s.position_m)[0]) + " " + format_exact((*s.position_m)[1]) + " " +
             format_exact((*s.position_m)[2]);
    out += "\n";
  }
  out += "t_s";
  for (const auto& s : signals) out += "," + s.name + " [" + s.unit + "]";
  out += "\n";
  for (std::size_t i = 0; i < first.samples.size(); ++i) {
    out += format_exact(first.time(i));
    for (const auto& s : signals) {
      out += ',';
      out += format_exact(s.samples[i]);
    }
    out += '\n';
  }
  return out;
}

std::vector<Signal> parse_signal_csv(std::string_view text, const std::string& origin,
                                             const SignalCsvDefaults& defaults) {
  std::map<std::string, Metadata> metadata;
  {
    std::size_t pos = 0, line_no = 1;
    while (pos < text.size()) {
      const auto eol = text.find('\n', pos);
      const auto line = text.substr(pos, eol == std::string_view::npos ? std::string_view::npos : eol - pos);
      parse_metadata_line(line, origin, line_no, metadata);
      if (eol == std::string_view::npos) break;
      pos = eol + 1;
      ++line_no;
    }
  }
  const io::CsvTable table = io::parse_csv(text, origin);
  if (table.header.size() < 2)
    throw InputError(origin + ": needs a time column and at least one signal column, has " +
                     std::to_string(table.header.size()) + " column(s)");
  const double factor = time_column_factor(table.header[0]);
  if (factor == 0)
    throw InputError(origin + ": the first column '" + table.header[0] +
                     "' must be the time with its unit: t_s, t_ms, t_us or t_ns (or \"t [us]\")");
  const std::size_t rows = table.rows.size();
  if (rows < 2) throw InputError(origin + ": needs at least 2 rows to know the sampling interval, has " + std::to_string(rows));

  const double t0 = table.number(0, 0) * factor;
  const double t_last = table.number(rows - 1, 0) * factor;
  const double dt = (t_last - t0) / double(rows - 1);
  if (!(dt > 0))
    throw InputError(origin + ": times must increase (first " + format_number(t0) + " s, last " + format_number(t_last) + " s)");
  for (std::size_t r = 0; r < rows; ++r) {
    const double t = table.number(r, 0) * factor;
    if (std::abs(t - (t0 + double(r) * dt)) > 0.1 * dt)
      throw InputError(origin + ":" + std::to_string(table.row_lines[r]) + ": time " + table.text(r, 0) +
                       " is off the uniform grid t0 + i dt (dt " + format_number(dt / factor) + " " +
                       table.header[0] + ") by more than 0.1 dt; resample the file onto a uniform grid first");
  }

  std::vector<Signal> signals;
  std::set<std::string> names;
  for (std::size_t c = 1; c < table.header.size(); ++c) {
    const std::string& header = table.header[c];
    Signal s;
    const auto bracket = header.rfind('[');
    if (bracket != std::string::npos && header.back() == ']') {
      s.name = io::trim_blanks(header.substr(0, bracket));
      s.unit = io::trim_blanks(header.substr(bracket + 1, header.size() - bracket - 2));
    } else {
      s.name = header;
      s.unit = defaults.unit;
    }
    if (s.name.empty()) throw InputError(origin + ": column " + std::to_string(c + 1) + " has no name");
    if (!names.insert(s.name).second) throw InputError(origin + ": column '" + s.name + "' appears twice");
    if (auto m = metadata.find(s.name); m != metadata.end()) {
      s.quantity = m->second.quantity;
      s.component = m->second.component;
      s.position_m = m->second.position_m;
    } else {
      s.quantity = defaults.quantity;
    }
    s.t0_s = t0;
    s.dt_s = dt;
    s.samples.resize(rows);
    for (std::size_t r = 0; r < rows; ++r) s.samples[r] = table.number(r, c);
    signals.push_back(std::move(s));
  }
  return signals;
}

std::vector<Signal> read_signal_csv(const std::filesystem::path& path, const SignalCsvDefaults& defaults) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read " + path.string());
  std::ostringstream content;
  content << in.rdbuf();
  return parse_signal_csv(content.str(), path.string(), defaults);
}

SignalFormat signal_format_of(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext == ".h5" || ext == ".hdf5" || ext == ".hdf") return SignalFormat::hdf5;
  if (ext == ".csv") return SignalFormat::csv;
  throw InputError(path.string() + ": signal files end in .h5 (HDF5) or .csv, not '" + ext + "'");
}

std::vector<Signal> read_signals(const std::filesystem::path& path, const SignalCsvDefaults& defaults) {
  return signal_format_of(path) == SignalFormat::hdf5 ? read_signal_file(path) : read_signal_csv(path, defaults);
}

void write_signals(const std::filesystem::path& path, SignalFormat format, const std::vector<Signal>& signals,
                   const std::map<std::string, std::string>& file_attributes) {
  if (format == SignalFormat::hdf5) return write_signal_file(path, signals, file_attributes);
  const std::string text = signals_to_csv(signals, file_attributes);
  std::ofstream out(path, std::ios::binary);
  out.write(text.data(), std::streamsize(text.size()));
  out.close();
  if (!out) throw InputError("cannot write " + path.string());
}

}  // namespace mesowave::signal
