#pragma once
// One table of a TOML input file as its readers see it: every key read is
// marked, and finish() names any key left over, so a typo is an error and
// never a silent default. The DEM scene files (dem/scene/scene_keys.hpp) and
// the experiment files (experiment/experiment.cpp) read their tables with it.
#include <optional>
#include <set>
#include <string>
#include <toml++/toml.h>
#include <vector>

#include "mesowave/core/error.hpp"

namespace mesowave::io {

class TomlKeys {
public:
  TomlKeys(const toml::table& table, std::string where) : table_(table), where_(std::move(where)) {}

  const toml::node* get(const std::string& key) {
    used_.insert(key);
    return table_.get(key);
  }
  bool has(const std::string& key) const { return table_.contains(key); }

  std::optional<double> number(const std::string& key) {
    const toml::node* n = get(key);
    if (!n) return std::nullopt;
    if (auto v = n->value<double>()) return *v;
    throw InputError(where_ + "." + key + " must be a number");
  }
  double number(const std::string& key, double fallback) { return number(key).value_or(fallback); }
  double required_number(const std::string& key) {
    auto v = number(key);
    if (!v) throw InputError(where_ + " needs " + key);
    return *v;
  }
  std::optional<std::string> text(const std::string& key) {
    const toml::node* n = get(key);
    if (!n) return std::nullopt;
    if (auto v = n->value<std::string>()) return *v;
    throw InputError(where_ + "." + key + " must be a string");
  }
  std::string text(const std::string& key, const std::string& fallback) { return text(key).value_or(fallback); }
  std::optional<std::vector<double>> numbers(const std::string& key, std::size_t count) {
    const toml::node* n = get(key);
    if (!n) return std::nullopt;
    const toml::array* a = n->as_array();
    if (!a || a->size() != count)
      throw InputError(where_ + "." + key + " must be an array of " + std::to_string(count) + " numbers");
    std::vector<double> out;
    for (const auto& e : *a) {
      auto v = e.value<double>();
      if (!v) throw InputError(where_ + "." + key + " must be an array of " + std::to_string(count) + " numbers");
      out.push_back(*v);
    }
    return out;
  }
  const std::string& where() const { return where_; }
  void finish() const {
    for (const auto& [key, node] : table_)
      if (!used_.count(std::string(key.str())))
        throw InputError(where_ + " has an unknown key \"" + std::string(key.str()) + "\"");
  }

private:
  const toml::table& table_;
  std::string where_;
  std::set<std::string> used_;
};

}  // namespace mesowave::io
