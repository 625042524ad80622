#pragma once
// What a run's exit_status means (the tool's exit status, recorded in runs.exit_status):
// 0 success, 1 bad input, 2 internal failure, 128 + N interrupted by signal N - the shells'
// convention for a process a signal ended (130 SIGINT, 143 SIGTERM; app/interrupt.hpp).

namespace mesowave::prov {

constexpr int interrupted_exit_status(int signal) { return 128 + signal; }
constexpr bool is_interrupted(int exit_status) { return exit_status > 128 && exit_status <= 128 + 64; }

/// "ok", "bad input", "failed" or "interrupted".
constexpr const char* status_name(int exit_status) {
  return exit_status == 0 ? "ok" : exit_status == 1 ? "bad input" : is_interrupted(exit_status) ? "interrupted" : "failed";
}

}  // namespace mesowave::prov
