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

// placeholder: a value copied from another study by scripts/new-study, still to be replaced by
// this specimen's own (its cite says where it was copied from).
const std::set<std::string> kSourceKinds = {"paper", "derived", "synthetic", "assumed", "placeholder"};

std::string scalar_text(const toml::node& node, const std::string& where) {
  if (auto v = node.value<double>()) return format_exact(*v);
  if (auto v = node.value<std::string>()) return *v;
  if (auto v = node.value<bool>()) return *v ? "true" : "false";
  throw InputError(where + ": value must be a number, a string or a boolean");
}

// Every name of a foreign_keys array must be an entry of the file: a renamed
// entry must not leave a declaration that silently covers nothing.
std::vector<std::string> foreign_names(const std::vector<std::string>& names, const std::set<std::string>& entries,
                                       const std::string& origin) {
  for (const auto& name : names)
    if (!entries.count(name))
      throw InputError(origin + ": " + kForeignKeys + " names '" + name + "', which is not an entry of the file");
  return names;
}

QuantityFile parse_toml(const std::string& text, const std::string& origin) {
  toml::table root;
  try {
    root = toml::parse(text, origin);
  } catch (const toml::parse_error& e) {
    const auto& at = e.source().begin;
    throw InputError(origin + ":" + std::to_string(at.line) + ": " + std::string(e.description()));
  }
  // toml++ keeps tables sorted by key; people read files top to bottom.
  std::vector<std::pair<std::string_view, const toml::node*>> entries;
  std::vector<std::string> declared;
  std::set<std::string> names;
  for (const auto& [key, node] : root) {
    if (key.str() != kForeignKeys) {
      entries.emplace_back(key.str(), &node);
      names.emplace(key.str());
      continue;
    }
    const toml::array* list = node.as_array();
    if (!list) throw InputError(origin + ": " + kForeignKeys + " must be an array of entry names");
    for (const auto& element : *list) {
      const auto name = element.value<std::string>();
      if (!name) throw InputError(origin + ": " + kForeignKeys + " must hold only strings (entry names)");
      declared.push_back(*name);
    }
  }
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
      throw InputError(where + " has source '" + q.source + "'; it must be paper, derived, synthetic, assumed or placeholder");
    if (q.source != "synthetic" && q.cite.empty())
      throw InputError(where + " is '" + q.source + "' but has no cite saying where it comes from");
    quantities.push_back(std::move(q));
  }
  return {std::move(quantities), foreign_names(declared, names, origin)};
}

QuantityFile parse_json(const std::string& text, const std::string& origin) {
  nlohmann::json root;
  try {
    root = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {  // parse_error, and out_of_range for a number beyond double
    throw InputError(origin + ": not valid JSON (" + std::string(e.what()) + ")");
  }
  if (!root.is_object()) throw InputError(origin + ": expected a JSON object");
  std::vector<Quantity> quantities;
  std::vector<std::string> declared;
  std::set<std::string> names;
  for (const auto& [key, value] : root.items()) {
    if (key == kForeignKeys) {
      if (!value.is_array()) throw InputError(origin + ": " + kForeignKeys + " must be an array of key names");
      for (const auto& element : value) {
        if (!element.is_string()) throw InputError(origin + ": " + kForeignKeys + " must hold only strings (key names)");
        declared.push_back(element.get<std::string>());
      }
      continue;
    }
    names.insert(key);
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
  return {std::move(quantities), foreign_names(declared, names, origin)};
}

}  // namespace

std::string Quantity::option_name() const {
  std::string option = unit.empty() ? name : name + "_" + unit;
  for (char& c : option)
    if (c == '_') c = '-';
  return option;
}

QuantityFile parse_quantity_document(const std::string& text, const std::string& origin) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && text[first] == '{') return parse_json(text, origin);
  return parse_toml(text, origin);
}

QuantityFile read_quantity_document(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read " + path.string());
  std::ostringstream content;
  content << in.rdbuf();
  return parse_quantity_document(content.str(), path.string());
}

std::vector<Quantity> parse_quantity_text(const std::string& text, const std::string& origin) {
  return parse_quantity_document(text, origin).quantities;
}

std::vector<Quantity> read_quantity_file(const std::filesystem::path& path) {
  return read_quantity_document(path).quantities;
}

}  // namespace mesowave::io
