#pragma once
// Running the built tools from tests: exit status, stdout and stderr.
#include <filesystem>
#include <string>
#include <vector>

namespace mesowave::test {

struct ToolResult {
  int exit_status = -1;         ///< the exit code, or 128 + N for a process signal N ended
  bool killed_by_signal = false;  ///< a signal ended it (it did not exit by itself)
  bool signal_sent = false;       ///< run_tool_and_signal: the signal was delivered while it ran
  std::string out;
  std::string err;
};

/// Runs bin/<tool> with `args` (no shell), optionally with extra environment
/// entries ("NAME=value"), and waits for it.
ToolResult run_tool(const std::string& tool, const std::vector<std::string>& args,
                    const std::vector<std::string>& env = {});

/// Runs any program (absolute path) the same way.
ToolResult run_command(const std::filesystem::path& program, const std::vector<std::string>& args,
                       const std::vector<std::string>& env = {});

/// As run_tool, but sends `signal` to the tool once its stderr holds `marker` (or after
/// `timeout_s`), then waits for it. If it ends before, signal_sent stays false.
ToolResult run_tool_and_signal(const std::string& tool, const std::vector<std::string>& args,
                               const std::string& marker, int signal, double timeout_s = 120);

/// As run_tool, but the tool runs as user `uid` (for read-only checks when
/// the tests run as root, who can write anywhere). Only root can do this.
ToolResult run_tool_as(unsigned uid, const std::string& tool, const std::vector<std::string>& args);

/// Path of a built tool.
std::filesystem::path tool_path(const std::string& tool);

/// A fresh empty directory under the system temp dir, removed by the destructor.
class TempDir {
public:
  TempDir();
  ~TempDir();
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

private:
  std::filesystem::path path_;
};

/// Whole content of a file.
std::string read_file(const std::filesystem::path& path);
/// Writes `content` to `path`.
void write_file(const std::filesystem::path& path, const std::string& content);
/// Number of regular files below `dir`.
std::size_t count_files(const std::filesystem::path& dir);

}  // namespace mesowave::test
