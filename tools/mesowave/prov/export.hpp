#pragma once
// The whole provenance database as a graph for other tools: W3C PROV-JSON
// (https://www.w3.org/submissions/prov-json/) and Graphviz DOT.
//   entity   = a file version (path + SHA-256)
//   activity = a tool run (start/end time, parameters, exit status, cost)
//   agent    = a tool build (tool, version, binary SHA-256)
//   used / wasGeneratedBy / wasAssociatedWith link them.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "mesowave/prov/database.hpp"

namespace mesowave::prov {

nlohmann::ordered_json export_prov_json(const Database& db);
std::string export_dot(const Database& db, const std::filesystem::path& base);

}  // namespace mesowave::prov
