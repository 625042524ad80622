#pragma once
// Shared by the CLI tests of the lab raw-data tools: the shipped synthetic set
// and its ground truth.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "mesowave/io/quantity_file.hpp"

namespace mesowave::test {

inline std::filesystem::path raw_dir() {
  return std::filesystem::path(MESOWAVE_SOURCE_DIR) / "lab-data/concrete-cube/raw";
}

/// The value of entry `name` in a truth TOML.
inline double truth(const std::string& file, const std::string& name) {
  for (const auto& q : io::read_quantity_file(raw_dir() / file))
    if (q.name == name) return std::stod(q.value);
  throw std::runtime_error(file + " has no entry " + name);
}

inline nlohmann::json parse_json(const std::string& text) { return nlohmann::json::parse(text); }

}  // namespace mesowave::test
