#include "mesowave/io/table_gather.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/io/quantity_file.hpp"

namespace mesowave::io {
namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

std::string trim(std::string s) {
  const auto b = s.find_first_not_of(" \t");
  const auto e = s.find_last_not_of(" \t");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

std::optional<double> as_number(const std::string& s) {
  if (s.empty()) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size()) return std::nullopt;
  return v;
}

bool same_key(const std::string& a, const std::string& b) {
  const auto x = as_number(a), y = as_number(b);
  return (x && y) ? *x == *y : a == b;
}

// One input file, read once: a CSV table, a JSON document, or TOML quantities.
struct Source {
  fs::path path;
  std::optional<CsvTable> csv;
  std::optional<json> doc;
  std::map<std::string, std::string> quantities;

  static Source load(const fs::path& p) {
    Source s;
    s.path = p;
    if (!fs::is_regular_file(p)) throw InputError(p.string() + " does not exist");
    const auto ext = p.extension().string();
    if (ext == ".csv") {
      s.csv = read_csv(p);
    } else if (ext == ".json") {
      std::ifstream in(p);
      try {
        s.doc = json::parse(in);
      } catch (const json::exception& e) {
        throw InputError(p.string() + " is not JSON: " + e.what());
      }
      if (!s.doc->is_object()) throw InputError(p.string() + ": expected a JSON object");
    } else if (ext == ".toml") {
      for (const auto& q : read_quantity_file(p)) s.quantities[q.name] = q.value;
    } else {
      throw InputError(p.string() + ": a gathered file must be .csv, .json or .toml");
    }
    return s;
  }

  // The value of `source`, if this file holds it.
  std::optional<std::string> value(const std::string& source, const std::optional<RowSelector>& where,
                                   std::optional<int> digits) const {
    if (csv) {
      const auto col = csv->find_column(source);
      if (!col) return std::nullopt;
      std::vector<std::size_t> hits;
      if (where) {
        const auto sel = csv->find_column(where->first);
        if (!sel) throw InputError(path.string() + " has no column '" + where->first + "' to pick a row by");
        for (std::size_t r = 0; r < csv->rows.size(); ++r)
          if (csv->text(r, *sel) == where->second) hits.push_back(r);
        if (hits.size() != 1)
          throw InputError(path.string() + " has " + std::to_string(hits.size()) + " rows with " + where->first + " = " +
                           where->second + " (need exactly one)");
      } else {
        if (csv->rows.size() != 1)
          throw InputError(path.string() + " has " + std::to_string(csv->rows.size()) +
                           " rows: say which one (a row selector COLUMN=VALUE)");
        hits.push_back(0);
      }
      return csv->text(hits.front(), *col);
    }
    if (doc) {
      const json* node = &*doc;
      std::istringstream parts(source);
      std::string part;
      while (std::getline(parts, part, '.')) {
        if (!node->is_object() || !node->contains(part)) return std::nullopt;
        node = &(*node)[part];
      }
      if (node->is_number()) return digits ? format_significant(node->get<double>(), *digits) : format_exact(node->get<double>());
      if (node->is_string()) return node->get<std::string>();
      if (node->is_boolean()) return std::string(node->get<bool>() ? "true" : "false");
      if (node->is_null()) return std::string();  // a value the run could not measure: an empty cell, never a zero
      throw InputError(path.string() + ": '" + source + "' is not a number, text or true/false");
    }
    const auto it = quantities.find(source);
    if (it == quantities.end()) return std::nullopt;
    return it->second;
  }
};

}  // namespace

RowSelector parse_row_selector(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("row selector '" + text + "' must read COLUMN=VALUE");
  return {trim(text.substr(0, eq)), trim(text.substr(eq + 1))};
}

ColumnSource parse_column_source(const std::string& text) {
  ColumnSource c;
  std::string rest = text;
  if (const auto at = rest.find('@'); at != std::string::npos) {
    c.where = parse_row_selector(rest.substr(at + 1));
    rest = rest.substr(0, at);
  }
  const auto eq = rest.find('=');
  c.name = trim(rest.substr(0, eq));
  c.source = eq == std::string::npos ? c.name : trim(rest.substr(eq + 1));
  for (const auto& [word, aggregate] : {std::pair{"mean(", ColumnSource::Aggregate::mean},
                                        std::pair{"median(", ColumnSource::Aggregate::median}}) {
    const std::string prefix = word;
    if (c.source.rfind(prefix, 0) == 0 && c.source.size() > prefix.size() + 1 && c.source.back() == ')') {
      c.source = trim(c.source.substr(prefix.size(), c.source.size() - prefix.size() - 1));
      c.aggregate = aggregate;
    }
  }
  if (c.name.empty() || c.source.empty())
    throw InputError("column '" + text + "' must read NAME, NAME=SOURCE or NAME=SOURCE@COLUMN=VALUE");
  return c;
}

GatherRow parse_gather_row(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
    throw InputError("row '" + text + "' must read KEY=FILE[,FILE...]");
  GatherRow r;
  r.key = trim(text.substr(0, eq));
  std::istringstream files(text.substr(eq + 1));
  std::string f;
  while (std::getline(files, f, ','))
    if (!trim(f).empty()) r.files.emplace_back(trim(f));
  if (r.files.empty()) throw InputError("row '" + text + "' names no file");
  return r;
}

TableJoin parse_table_join(const std::string& text) {
  const auto colon = text.rfind(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 == text.size())
    throw InputError("--join '" + text + "' must read FILE:NAME=SOURCE[,NAME=SOURCE...]");
  TableJoin join{text.substr(0, colon), {}};
  const std::string list = text.substr(colon + 1);
  for (std::size_t at = 0; at <= list.size();) {
    const auto comma = std::min(list.find(',', at), list.size());
    if (comma > at) join.columns.push_back(parse_column_source(list.substr(at, comma - at)));
    at = comma + 1;
  }
  return join;
}

std::vector<fs::path> GatherSpec::files() const {
  std::vector<fs::path> all;
  for (const auto& r : rows) all.insert(all.end(), r.files.begin(), r.files.end());
  for (const auto& j : joins) all.push_back(j.file);
  return all;
}

namespace {
// "E_glob_GPa|test.E_glob_GPa": the names one quantity goes by in different
// tools' summaries, tried in order in each file.
std::vector<std::string> split_alternatives(const std::string& source) {
  std::vector<std::string> names;
  std::istringstream parts(source);
  std::string name;
  while (std::getline(parts, name, '|'))
    if (!trim(name).empty()) names.push_back(trim(name));
  return names;
}

std::vector<std::string> split_key(const std::string& key) {
  std::vector<std::string> parts;
  for (std::size_t at = 0; at <= key.size();) {
    const auto comma = std::min(key.find(',', at), key.size());
    parts.push_back(trim(key.substr(at, comma - at)));
    at = comma + 1;
  }
  return parts;
}

// The selector with "{KEY}" replaced by the row's value of key column KEY.
std::optional<RowSelector> for_row(std::optional<RowSelector> where, const std::vector<std::string>& key_names,
                                   const std::vector<std::string>& key) {
  if (!where || where->second.size() < 3 || where->second.front() != '{' || where->second.back() != '}') return where;
  const std::string name = where->second.substr(1, where->second.size() - 2);
  const auto it = std::find(key_names.begin(), key_names.end(), name);
  if (it == key_names.end())
    throw InputError("row selector " + where->first + "=" + where->second + ": '" + name + "' is not a key column");
  where->second = key[std::size_t(it - key_names.begin())];
  return where;
}

// The mean or the median of a row's values; the median of an even count is the
// mean of the middle two.
double aggregate_of(std::vector<double> values, ColumnSource::Aggregate aggregate) {
  if (aggregate == ColumnSource::Aggregate::mean) {
    double sum = 0;
    for (double v : values) sum += v;
    return sum / double(values.size());
  }
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}
}  // namespace

namespace {

// GatherSpec::pareto: each objective as (column, +1 to minimise or -1 to maximise); then the front.
void mark_pareto_front(CsvTable& table, const std::vector<std::string>& objectives) {
  if (objectives.size() != 2)
    throw InputError("--pareto takes two objectives, min:COLUMN,max:COLUMN (got " + std::to_string(objectives.size()) + ")");
  std::vector<std::pair<std::size_t, double>> axes;
  for (const auto& o : objectives) {
    const auto colon = o.find(':');
    const std::string sense = o.substr(0, colon == std::string::npos ? 0 : colon);
    if (sense != "min" && sense != "max")
      throw InputError("--pareto objective '" + o + "' must be min:COLUMN or max:COLUMN");
    axes.push_back({table.column(o.substr(colon + 1)), sense == "min" ? 1.0 : -1.0});
  }
  const auto value = [&](std::size_t r, int k) { return as_number(table.rows[r][axes[k].first]); };
  table.header.push_back("pareto");
  const std::size_t n = table.rows.size();
  std::vector<bool> front(n, false);
  for (std::size_t r = 0; r < n; ++r) {
    if (!value(r, 0) || !value(r, 1)) continue;
    bool beaten = false;
    for (std::size_t q = 0; q < n && !beaten; ++q) {
      if (q == r || !value(q, 0) || !value(q, 1)) continue;
      const double d0 = axes[0].second * (*value(q, 0) - *value(r, 0)), d1 = axes[1].second * (*value(q, 1) - *value(r, 1));
      beaten = d0 <= 0 && d1 <= 0 && (d0 < 0 || d1 < 0);
    }
    front[r] = !beaten;
  }
  for (std::size_t r = 0; r < n; ++r) table.rows[r].push_back(front[r] ? "yes" : "");
}

}  // namespace

CsvTable gather_rows(const GatherSpec& spec) {
  if (spec.rows.empty()) throw InputError("a gathered table needs at least one row");
  if (spec.columns.empty()) throw InputError("a gathered table needs at least one column");
  const auto key_names = split_key(spec.key_name);
  CsvTable table;
  table.origin = "gathered table";
  table.header = key_names;
  for (const auto& c : spec.columns) table.header.push_back(c.name);
  for (const auto& row : spec.rows) {
    std::vector<Source> sources;
    for (const auto& f : row.files) sources.push_back(Source::load(f));
    std::vector<std::string> fields = split_key(row.key);
    if (fields.size() != key_names.size())
      throw InputError("row " + row.key + ": " + std::to_string(fields.size()) + " key part(s), the key " +
                       spec.key_name + " has " + std::to_string(key_names.size()));
    const auto key = fields;
    for (const auto& c : spec.columns) {
      const auto where = for_row(c.where ? c.where : spec.where, key_names, key);
      const auto alternatives = split_alternatives(c.source);
      std::vector<std::string> found;
      if (c.aggregate == ColumnSource::Aggregate::first) {
        // "A|B": A in any of the row's files, else B - by name first, so that the order of the
        // row's files does not decide between two names (a row listing a run's picks, which hold
        // E_d, before its material, which holds E_glob, still gets E_glob for "E_glob|E_d").
        for (const auto& a : alternatives) {
          for (const auto& s : sources)
            if (auto v = s.value(a, where, spec.significant_digits)) {
              found.push_back(*v);
              break;
            }
          if (!found.empty()) break;
        }
      } else {
        for (const auto& s : sources) {  // one value per file that holds the source (its first name)
          std::optional<std::string> v;
          for (const auto& a : alternatives)
            if ((v = s.value(a, where, spec.significant_digits))) break;
          if (v) found.push_back(*v);
        }
      }
      if (found.empty()) {
        std::string names;
        for (const auto& f : row.files) names += (names.empty() ? "" : ", ") + f.string();
        throw InputError("row " + row.key + ": no file holds '" + c.source + "' (" + names + ")");
      }
      if (c.aggregate == ColumnSource::Aggregate::first) {
        fields.push_back(found.front());
        continue;
      }
      std::vector<double> values;
      for (const auto& v : found) {
        const auto x = as_number(v);
        if (!x) throw InputError("row " + row.key + ": '" + c.source + "' holds '" + v + "', not a number to average");
        values.push_back(*x);
      }
      fields.push_back(format_exact(aggregate_of(values, c.aggregate)));
    }
    table.rows.push_back(std::move(fields));
  }
  for (const auto& j : spec.joins) join_columns(table, read_csv(j.file), key_names.front(), j.columns, spec.join_keys);
  for (const auto& [name, format] : spec.formats) {
    const auto col = table.column(name);
    for (auto& row : table.rows)
      if (!row[col].empty()) row[col] = apply_column_format(row[col], format, "column " + name);
  }
  if (!spec.pareto.empty()) mark_pareto_front(table, spec.pareto);
  return table;
}

void join_columns(CsvTable& table, const CsvTable& other, const std::string& key,
                  const std::vector<ColumnSource>& columns, const std::map<std::string, std::string>& aliases) {
  const auto key_here = table.column(key), key_there = other.column(key);
  std::vector<std::size_t> from;
  for (const auto& c : columns) from.push_back(other.column(c.source));
  for (std::size_t r = 0; r < other.rows.size(); ++r)
    for (std::size_t q = r + 1; q < other.rows.size(); ++q)
      if (same_key(other.text(r, key_there), other.text(q, key_there)))
        throw InputError(other.origin + " has " + key + " = " + other.text(r, key_there) + " twice");
  for (const auto& c : columns) table.header.push_back(c.name);
  for (auto& row : table.rows) {
    const auto alias = aliases.find(row[key_here]);
    const std::string& wanted = alias == aliases.end() ? row[key_here] : alias->second;
    std::optional<std::size_t> match;
    for (std::size_t r = 0; r < other.rows.size(); ++r)
      if (same_key(wanted, other.text(r, key_there))) match = r;
    for (auto col : from) row.push_back(match ? other.text(*match, col) : std::string());
  }
}

}  // namespace mesowave::io
