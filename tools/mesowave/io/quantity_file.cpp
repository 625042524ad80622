#include "mesowave/io/quantity_file.hpp"

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <toml++/toml.h>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"

namespace mesowave::io {
namespace {

const std::set<std::string> kSourceKinds = {"paper", "derived", "synthetic", "assumed"};

std::string scalar_text(const toml::node& node, const std::string& where) {
  if (auto v = node.value<double>()) return format_exact(*v);
  if (auto v = node.value<std::string>()) return *v;
  if (auto v = node.value<bool>()) return *v ? "true" : "false";
  throw InputError(where + ": value must be a number, a string or a boolean");
}

std::vector<Quantity> parse_toml(const std::string& text, const std::string& origin) {
  toml::table root;
  try {
    root = toml::parse(text, origin);
  } catch (const toml::parse_error& e) {
    const auto& at = e.source().begin;
    throw InputError(origin + ":" + std::to_string(at.line) + ": " + std::string(e.description()));
  }
  // toml++ keeps tables sorted by key; people read files top to bottom.
  std::vector<std::pair<std::string_view, const toml::node*>> entries;
  for (const auto& [key, node] : root) entries.emplace_back(key.str(), &node);
  std::stable_sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) {
    return a.second->source().begin.line < b.second->source().begin.line;
  });
  std::vector<Quantity> quantities;
  for (const auto& [key, node_ptr] : entries) {
    const toml::node& node = *node_ptr;
    const std::string name(key);
    const std::string where = origin + ": [" + name + "]";
    const toml::table* entry = node.as_table();
    if (!entry) throw InputError(where + " must be a table with value, unit and source");
    Quantity q;
    q.name = name;
    const toml::node* value = entry->get("value");
    if (!value) throw InputError(where + " has no value");
    q.value = scalar_text(*value, where);
    q.unit = entry->get("unit") ? entry->get("unit")->value_or(std::string()) : "";
    q.source = entry->get("source") ? entry->get("source")->value_or(std::string()) : "";
    q.cite = entry->get("cite") ? entry->get("cite")->value_or(std::string()) : "";
    if (!kSourceKinds.count(q.source))
      throw InputError(where + " has source '" + q.source + "'; it must be paper, derived, synthetic or assumed");
    if (q.source != "synthetic" && q.cite.empty())
      throw InputError(where + " is '" + q.source + "' but has no cite saying where it comes from");
    quantities.push_back(std::move(q));
  }
  return quantities;
}

std::vector<Quantity> parse_json(const std::string& text, const std::string& origin) {
  nlohmann::json root;
  try {
    root = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {  // parse_error, and out_of_range for a number beyond double
    throw InputError(origin + ": not valid JSON (" + std::string(e.what()) + ")");
  }
  if (!root.is_object()) throw InputError(origin + ": expected a JSON object");
  std::vector<Quantity> quantities;
  for (const auto& [key, value] : root.items()) {
    Quantity q;
    q.name = key;
    q.source = "output";
    q.cite = origin;
    if (value.is_number()) q.value = format_exact(value.get<double>());
    else if (value.is_string()) q.value = value.get<std::string>();
    else if (value.is_boolean()) q.value = value.get<bool>() ? "true" : "false";
    else continue;  // nested data is not an option value
    quantities.push_back(std::move(q));
  }
  return quantities;
}

}  // namespace

std::string Quantity::option_name() const {
  std::string option = unit.empty() ? name : name + "_" + unit;
  for (char& c : option)
    if (c == '_') c = '-';
  return option;
}

std::vector<Quantity> parse_quantity_text(const std::string& text, const std::string& origin) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && text[first] == '{') return parse_json(text, origin);
  return parse_toml(text, origin);
}

std::vector<Quantity> read_quantity_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read " + path.string());
  std::ostringstream content;
  content << in.rdbuf();
  return parse_quantity_text(content.str(), path.string());
}

}  // namespace mesowave::io
