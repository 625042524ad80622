#pragma once
// Running another mesowave tool as a child process: a tool that drives others
// (mw-calibrate runs mw-dem once per trial) keeps each run a run of its own,
// recorded in the provenance database by the tool that did it.
#include <filesystem>
#include <string>
#include <vector>

namespace mesowave::app {

struct ProcessResult {
  int exit_status = -1;   ///< the child's exit code; 128 + signal if it was killed
  std::string stderr_text;  ///< what it wrote on stderr (its one-line error, progress)
};

/// Runs argv[0] with argv (no shell), stdout discarded, stderr captured;
/// waits for it. InputError if it cannot be started.
ProcessResult run_process(const std::vector<std::string>& argv);

/// run_process for a child that must succeed: InputError "WHAT (NAME, exit N)
/// failed: LAST LINE OF ITS STDERR" (its one-line error) otherwise.
void run_process_or_throw(const std::vector<std::string>& argv, const std::string& what);

/// Another tool's executable: `name` beside this one (/proc/self/exe's folder).
std::filesystem::path sibling_tool(const std::string& name);

}  // namespace mesowave::app
