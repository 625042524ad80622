#include "mesowave/lab/compression_record.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/io/csv.hpp"
#include "mesowave/io/mts_export.hpp"

namespace mesowave::lab {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Columns of numbers as read, with their units and the source line of each row.
struct RawTable {
  std::vector<std::string> names, units;
  std::vector<std::vector<double>> columns;
  std::vector<std::size_t> lines;

  std::optional<std::size_t> find(const std::string& name) const {
    for (std::size_t i = 0; i < names.size(); ++i)
      if (names[i] == name) return i;
    return std::nullopt;
  }
};

std::string unit_suffix(const std::string& name) {
  const auto us = name.rfind('_');
  return us == std::string::npos ? "" : name.substr(us + 1);
}

RawTable raw_from_csv(const std::filesystem::path& path) {
  const auto csv = io::read_csv(path);
  RawTable t;
  t.names = csv.header;
  for (const auto& n : csv.header) t.units.push_back(unit_suffix(n));
  t.columns.assign(csv.header.size(), {});
  t.lines = csv.row_lines;
  for (std::size_t r = 0; r < csv.rows.size(); ++r) {
    if (csv.rows[r].size() != csv.header.size())
      throw InputError(csv.origin + ":" + std::to_string(csv.row_lines[r]) + ": " + std::to_string(csv.rows[r].size()) +
                       " fields for " + std::to_string(csv.header.size()) + " columns");
    for (std::size_t c = 0; c < csv.header.size(); ++c) {
      const std::string& field = csv.rows[r][c];
      if (field.empty()) {
        t.columns[c].push_back(kNaN);
        continue;
      }
      char* end = nullptr;
      const double v = std::strtod(field.c_str(), &end);
      if (end != field.c_str() + field.size() || !std::isfinite(v))
        throw InputError(csv.origin + ":" + std::to_string(csv.row_lines[r]) + ": column '" + csv.header[c] + "': '" +
                         field + "' is not a number");
      t.columns[c].push_back(v);
    }
  }
  return t;
}

RawTable raw_from_mts(const io::MtsExport& mts, const std::string& time_name, std::vector<std::string>& notes) {
  RawTable t;
  for (const auto& block : mts.blocks) {
    if (block.rows() <= 2 || !block.find(time_name)) {
      notes.push_back("skipped the " + std::to_string(block.rows()) + "-row block at line " +
                      std::to_string(block.first_line) + " (peak/valley summary, not a time series)");
      continue;
    }
    if (t.names.empty()) {
      t.names = block.names;
      t.units = block.units;
      t.columns.assign(block.names.size(), {});
    } else if (block.names != t.names) {
      notes.push_back("skipped the block at line " + std::to_string(block.first_line) + ": other columns");
      continue;
    } else {
      notes.push_back("joined the time-series block at line " + std::to_string(block.first_line));
    }
    for (std::size_t c = 0; c < block.names.size(); ++c)
      t.columns[c].insert(t.columns[c].end(), block.columns[c].begin(), block.columns[c].end());
    for (std::size_t r = 0; r < block.rows(); ++r) t.lines.push_back(block.first_line + 2 + r);
  }
  if (t.names.empty()) throw InputError(mts.origin + ": no time-series block with a '" + time_name + "' column");
  return t;
}

std::size_t need_column(const RawTable& t, const std::string& name, const std::string& origin, const std::string& role) {
  if (auto i = t.find(name)) return *i;
  std::string have;
  for (const auto& n : t.names) have += (have.empty() ? "" : ", ") + n;
  throw InputError(origin + ": no " + role + " column '" + name + "' (columns: " + have + ")");
}

std::vector<double> scaled(const std::vector<double>& v, double factor) {
  std::vector<double> out(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) out[i] = v[i] * factor;
  return out;
}

// Whether channel `x` rises with the load `y`: a vote of the signs of their
// increments over the samples where the load clearly moves (ramps). Offsets,
// zeroing jumps and the removal of a sensor after the test are single steps or
// stretches without load change, so they cannot outvote the ramps.
double rises_with_load(const std::vector<double>& x, const std::vector<double>& y) {
  std::vector<double> dy;
  for (std::size_t i = 1; i < y.size(); ++i) dy.push_back(std::abs(y[i] - y[i - 1]));
  if (dy.empty()) return 1;
  std::vector<double> sorted = dy;
  const std::size_t k = std::size_t(0.9 * double(sorted.size() - 1));
  std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(k), sorted.end());
  const double moving = 0.25 * sorted[k];
  long vote = 0;
  for (std::size_t i = 1; i < y.size(); ++i) {
    if (!(dy[i - 1] > moving) || !std::isfinite(x[i]) || !std::isfinite(x[i - 1]) || x[i] == x[i - 1]) continue;
    vote += ((x[i] > x[i - 1]) == (y[i] > y[i - 1])) ? 1 : -1;
  }
  return vote < 0 ? -1.0 : 1.0;
}

}  // namespace

double unit_to_si(const std::string& unit, const std::string& kind, const std::string& where) {
  static const std::map<std::string, std::map<std::string, double>> table = {
      {"time", {{"s", 1.0}, {"ms", 1e-3}, {"us", 1e-6}, {"min", 60.0}}},
      {"force", {{"N", 1.0}, {"kN", 1e3}, {"MN", 1e6}}},
      {"stress", {{"Pa", 1.0}, {"kPa", 1e3}, {"MPa", 1e6}, {"GPa", 1e9}, {"N/mm2", 1e6}}},
      {"length", {{"m", 1.0}, {"mm", 1e-3}, {"um", 1e-6}}}};
  const auto& units = table.at(kind);
  const auto it = units.find(unit);
  if (it == units.end()) {
    std::string known;
    for (const auto& [u, f] : units) known += (known.empty() ? "" : ", ") + u;
    throw InputError(where + ": unit '" + unit + "' is not a " + kind + " unit (" + known + ")");
  }
  return it->second;
}

CompressionRecord read_compression_record(const std::filesystem::path& path, RecordFormat format,
                                          const ColumnSelection& columns) {
  if (format == RecordFormat::automatic) format = io::is_mts_export(path) ? RecordFormat::mts793 : RecordFormat::csv;
  CompressionRecord rec;
  rec.origin = path.string();
  RawTable t;
  std::string time_name = columns.time, force_name = columns.force, cross_name = columns.crosshead;
  if (format == RecordFormat::mts793) {
    rec.format = "mts793";
    const auto mts = io::read_mts_export(path);
    if (time_name.empty()) time_name = "Laufzeit";
    if (force_name.empty() && columns.stress.empty()) force_name = "Ch 1 Kraft";
    if (cross_name.empty()) cross_name = "Ch 1 Weg";
    t = raw_from_mts(mts, time_name, rec.notes);
    if (auto d = mts.header_number("Durchmesser")) rec.header_diameter_m = *d * 1e-3;
    if (auto l = mts.header_number("Länge")) rec.header_length_m = *l * 1e-3;
    else if (auto h = mts.header_number("Höhe")) rec.header_length_m = *h * 1e-3;
  } else {
    rec.format = "csv";
    t = raw_from_csv(path);
    auto first_with = [&](const std::string& prefix) {
      for (const auto& n : t.names)
        if (n.rfind(prefix, 0) == 0) return n;
      return std::string();
    };
    if (time_name.empty()) time_name = first_with("t_").empty() ? first_with("time_") : first_with("t_");
    if (force_name.empty() && columns.stress.empty()) {
      force_name = first_with("force_");
      if (force_name.empty() && !first_with("stress_").empty()) {
        ColumnSelection with_stress = columns;
        with_stress.stress = first_with("stress_");
        return read_compression_record(path, RecordFormat::csv, with_stress);
      }
    }
    if (cross_name.empty()) cross_name = first_with("crosshead_");
    if (time_name.empty()) throw InputError(rec.origin + ": no time column (t_s, t_ms, ...; or --time-column)");
  }
  const std::string& where = rec.origin;

  const std::size_t ti = need_column(t, time_name, where, "time");
  const double t_factor = unit_to_si(t.units[ti], "time", where + " column '" + time_name + "'");
  rec.t_s = scaled(t.columns[ti], t_factor);
  for (std::size_t r = 0; r < rec.t_s.size(); ++r) {
    if (!std::isfinite(rec.t_s[r]))
      throw InputError(where + ":" + std::to_string(t.lines[r]) + ": no time in this row");
    if (r > 0 && rec.t_s[r] <= rec.t_s[r - 1])
      throw InputError(where + ":" + std::to_string(t.lines[r]) + ": time " + format_number(rec.t_s[r]) +
                       " s does not increase (previous row " + format_number(rec.t_s[r - 1]) +
                       " s): the time column must be strictly increasing");
  }
  if (rec.t_s.size() < 3) throw InputError(where + ": fewer than three rows of data");

  auto load_column = [&](const std::string& name, const std::string& kind, const std::string& role) {
    const std::size_t i = need_column(t, name, where, role);
    const auto v = scaled(t.columns[i], unit_to_si(t.units[i], kind, where + " column '" + name + "'"));
    return v;
  };
  std::vector<double> load;
  if (!columns.stress.empty()) {
    rec.stress_Pa = load_column(columns.stress, "stress", "stress");
    load = rec.stress_Pa;
  } else {
    if (force_name.empty()) throw InputError(where + ": no force column (force_kN, ...; or --force-column)");
    rec.force_N = load_column(force_name, "force", "force");
    load = rec.force_N;
  }
  for (std::size_t r = 0; r < load.size(); ++r)
    if (!std::isfinite(load[r]))
      throw InputError(where + ":" + std::to_string(t.lines[r]) + ": no force/stress reading in this row");
  double lo = load.front(), hi = load.front();
  for (double v : load) lo = std::min(lo, v), hi = std::max(hi, v);
  if (-lo > hi) {
    for (double& v : rec.force_N) v = -v;
    for (double& v : rec.stress_Pa) v = -v;
    for (double& v : load) v = -v;
    rec.notes.push_back("load recorded negative in compression: sign turned");
  }

  std::vector<std::string> ext = columns.extensometers;
  if (ext.empty()) {
    for (std::size_t c = 0; c < t.names.size(); ++c) {
      const std::string& n = t.names[c];
      if (rec.format == "csv" ? n.rfind("ext", 0) == 0
                              : (t.units[c] == "mm" && n.rfind("Ch ", 0) != 0 && n != cross_name))
        ext.push_back(n);
    }
  }
  for (const auto& name : ext) {
    auto v = load_column(name, "length", "extensometer");
    if (rises_with_load(v, load) < 0) {
      for (double& x : v) x = -x;
      rec.notes.push_back("extensometer '" + name + "' falls as the load rises: sign turned");
    }
    rec.extensometer_names.push_back(name);
    rec.extensometer_m.push_back(std::move(v));
  }
  if (!columns.no_crosshead && !cross_name.empty()) {
    if (!t.find(cross_name)) {
      if (!columns.crosshead.empty()) need_column(t, cross_name, where, "crosshead");
    } else {
      rec.crosshead_name = cross_name;
      rec.crosshead_m = load_column(cross_name, "length", "crosshead");
      if (rises_with_load(rec.crosshead_m, load) < 0) {
        for (double& x : rec.crosshead_m) x = -x;
        rec.notes.push_back("crosshead '" + cross_name + "' falls as the load rises: sign turned");
      }
    }
  }
  return rec;
}

void set_loaded_area(CompressionRecord& record, double area_m2) {
  if (!(area_m2 > 0)) throw InputError("loaded area must be positive");
  if (record.force_N.empty()) return;  // the file gave stress
  record.stress_Pa.resize(record.force_N.size());
  for (std::size_t i = 0; i < record.force_N.size(); ++i) record.stress_Pa[i] = record.force_N[i] / area_m2;
}

}  // namespace mesowave::lab
