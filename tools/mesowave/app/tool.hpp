#pragma once
// What every mesowave tool shares, so that a tool's main file is only its
// options, a call into the library and its output:
//  - `--help`, `--version`;
//  - `--from FILE` (repeatable): lab-data TOML or an earlier tool's JSON whose
//    entries fill options not given on the command line (t_p in "us" fills
//    --t-p-us; the last file named wins, the command line beats them all).
//    Every entry must fill an option of the tool or of its chosen subcommand:
//    one that does not is an error naming the entry and the file (exit 1),
//    unless the file declares it foreign (`foreign_keys`, io/quantity_file.hpp:
//    the producer's word) or `--from-ignore KEY` names it (the reader's word);
//    the entries so left untaken are recorded in the run's parameters as
//    "from_ignored": {"FILE": ["entry", ...]};
//  - `--db PATH` or MESOWAVE_DB: the provenance database that records the run;
//  - exit status 0 on success, 1 on bad input (one line: `error: <what>`),
//    2 on internal failure, 128 + N when signal N (SIGINT 130, SIGTERM 143)
//    interrupted a run's app::Progress loop (app/interrupt.hpp): the body
//    stops at its next Progress::update, nothing is written and the run is
//    recorded as interrupted with the step it reached;
//  - outputs staged and renamed into place only when the run succeeded.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "mesowave/io/output_stage.hpp"
#include "mesowave/io/quantity_file.hpp"
#include "mesowave/prov/run_record.hpp"

namespace mesowave::app {

/// The run in progress, as the tool's body sees it.
class Run {
public:
  /// Declares a file the run reads (hashed now, recorded as an input).
  void input(const std::filesystem::path& path);
  /// Reserves an output and returns the temporary path to write it to; it is
  /// renamed to `path` when the run succeeds (see io::OutputStage).
  std::filesystem::path output(const std::filesystem::path& path);
  /// Stages `path` with `content`.
  void write_text(const std::filesystem::path& path, std::string_view content);
  /// A named result with its unit ("" if dimensionless), queryable later.
  void metric(const std::string& name, double value, const std::string& unit);
  /// A parameter that is not an option (a derived choice worth recording).
  void param(const std::string& name, nlohmann::ordered_json value);
  /// A file written in place, outside the whole-or-nothing outputs, that stays when the run is
  /// interrupted (a checkpoint): the interrupted run's record names it, `what` says what it holds.
  void keep_on_interrupt(const std::filesystem::path& path, const std::string& what);

  /// Where the value of `option` ("--nu-st") came from, for a result that must say what it was
  /// computed from (mw-calibrate's targets): {"option", "given": "command line"}; or the --from
  /// file that filled it - the last one named with an entry for it, as --from takes them -
  /// {"option", "file" (as named), "entry", "sha256", "source", "cite" (TOML entries)}; or
  /// {"option", "given": "default"}.
  nlohmann::ordered_json origin(const std::string& option) const;

  /// Prints `object` (pretty, one key per line) on stdout and, if
  /// `out_path` is not empty, stages it to that file as well.
  void emit_json(const nlohmann::ordered_json& object, const std::filesystem::path& out_path = {});

  std::ostream& out();

private:
  friend class Tool;
  io::OutputStage stage_;
  std::vector<prov::FileRecord> inputs_;
  std::vector<prov::MetricRecord> metrics_;
  nlohmann::ordered_json extra_params_ = nlohmann::ordered_json::object();
  std::vector<std::string> kept_;  ///< keep_on_interrupt: "path (what)"
  struct FromFile {
    std::string path;  ///< as named on the command line
    io::QuantityFile content;
    std::string sha256;
  };
  std::vector<FromFile> from_files_;         ///< in command-line order
  std::vector<std::string> command_line_;  ///< the arguments but the --from ones
};

class Tool {
public:
  /// `name` as invoked (mw-upv); `description` is the first paragraph of --help.
  Tool(std::string name, std::string description);

  CLI::App& cli() { return app_; }

  /// Tools that only read the database (mw-prov) do not record themselves.
  void set_records_runs(bool records) { records_runs_ = records; }
  /// A process that leaves the record of its runs to another (mw-dem's ranks but rank 0) may be
  /// the only one to see a failure (its own part of the model): after a failure `gate` is asked,
  /// and if it returns true this process records the failed run itself. mw-dem's gate waits for
  /// rank 0 to record and end a failure every rank meets, so that such a one is recorded once.
  void set_failure_recording(std::function<bool()> gate) { failure_gate_ = std::move(gate); }
  /// Where the one-line error goes (default: "error: LINE" on stderr) with the exit status it
  /// ends with. mw-dem on several MPI ranks hands it to the MPI session, which prints it once
  /// and ends every rank (a failure on one rank must not leave the others waiting).
  void set_error_report(std::function<void(const std::string& line, int status)> report) { error_report_ = std::move(report); }
  /// The database named by --db or MESOWAVE_DB ("" if none), after parsing.
  const std::string& db_path() const { return db_path_; }

  /// Parses argv, opens the database if one is named, runs `body`, records
  /// the run and returns the exit status for main().
  int run(int argc, char** argv, const std::function<void(Run&)>& body);

private:
  std::string name_;
  CLI::App app_;
  std::string db_path_;
  std::vector<std::string> from_ignore_;
  bool records_runs_ = true;
  std::function<void(const std::string&, int)> error_report_;
  std::function<bool()> failure_gate_;
  void report_error(const std::string& line, int status) const;
};

/// The --from contract on the producer's side: declares every entry of `object` but `products`
/// foreign (a "foreign_keys" array at its end, docs/formats.md). A reader of the file may leave
/// the inputs echoed and the side results, and must take each product or name it in
/// --from-ignore: a product renamed here is then an error in the reader, not a value left at its
/// default. A product missing from `object` is a programming error (std::logic_error).
void declare_products(nlohmann::ordered_json& object, const std::vector<std::string>& products);

/// Adds the usual `--out FILE` option (JSON result also written to FILE).
CLI::Option* add_out_option(CLI::App& app, std::filesystem::path& out, const std::string& what = "the JSON result");

}  // namespace mesowave::app
