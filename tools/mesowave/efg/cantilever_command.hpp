#pragma once
// mw-efg cantilever's options (efg/cantilever: the elastic validation against Timoshenko & Goodier),
// added to a CLI11 (sub)command like efg/bending_report's, so that the tool's main stays a list of
// subcommands.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "mesowave/app/tool.hpp"
#include "mesowave/efg/cantilever.hpp"

namespace mesowave::efg {

struct CantileverCommandLine {
  CantileverBeam beam;
  CantileverOptions options;
  double spacing_m = 2.0;
  int refinements = 0;
  std::string method = "efg", basis = "linear", weight = "quartic-spline";
  std::filesystem::path table, snapshots, out;
  int threads = 0;
  /// The cells from the spacing (round(L/s) x round(D/s)) and the MLS basis and weight from their
  /// names; InputError for a spacing <= 0 or an unknown name.
  CantileverOptions resolve() const;
};
void add_cantilever_options(CLI::App& app, CantileverCommandLine& values);
/// The subcommand (moved out of mw-efg's main): the study, its metrics, --table, --snapshots (the
/// finest run), the summary with `threads` (the tool's thread choice).
void run_cantilever_command(const CantileverCommandLine& command_line, app::Run& run, const nlohmann::ordered_json& threads);

}  // namespace mesowave::efg
