#pragma once
// The options of a superposed run, one set for every solver that makes each burst frequency
// from one unit-impulse run (signal/superposition.hpp; mw-dem run, mw-fem box|rod): the
// frequencies, the file-name patterns ({f} the frequency in kHz) and the direct checks.
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace mesowave::app {

/// What differs between the solvers: the --help texts and the name of the per-frequency record.
struct SuperpositionOptionText {
  std::string method;         ///< how the responses are made, after "from one ... by superposition"
  std::string signals_example;  ///< "dem-{f}kHz.h5"
  std::string record_option;  ///< "--summary-pattern"
  std::string record_noun;    ///< "summary" (help: "each frequency's summary (JSON)")
};

/// Adds --frequencies-kHz (excluding `single_frequency`), --signals-pattern, the record pattern and
/// --check-kHz, the last three only with --frequencies-kHz; returns --frequencies-kHz, which further
/// options of the solver's own may need.
CLI::Option* add_superposition_options(CLI::App& command, CLI::Option* single_frequency,
                                       const SuperpositionOptionText& text, std::vector<double>& frequencies_kHz,
                                       std::string& signals_pattern, std::string& record_pattern,
                                       std::vector<double>& check_kHz);

}  // namespace mesowave::app
