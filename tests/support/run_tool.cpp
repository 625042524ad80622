#include "support/run_tool.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <thread>

extern char** environ;

namespace mesowave::test {
namespace fs = std::filesystem;

fs::path tool_path(const std::string& tool) { return fs::path(MESOWAVE_BIN_DIR) / tool; }

ToolResult run_tool(const std::string& tool, const std::vector<std::string>& args, const std::vector<std::string>& env) {
  return run_command(tool_path(tool), args, env);
}

namespace {

// Starts `program` with stdout and stderr going to files in `capture`; the environment is the
// test's own without MESOWAVE_DB (tests name their database explicitly), plus `env`.
pid_t spawn(const fs::path& program, const std::vector<std::string>& args, const std::vector<std::string>& env,
            const TempDir& capture) {
  const fs::path out_file = capture / "stdout", err_file = capture / "stderr";
  std::vector<std::string> argv_s = {program.string()};
  argv_s.insert(argv_s.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : argv_s) argv.push_back(a.data());
  argv.push_back(nullptr);

  std::vector<std::string> env_s;
  for (char** e = environ; *e; ++e) {
    const std::string entry = *e;
    if (entry.rfind("MESOWAVE_DB=", 0) == 0) continue;
    env_s.push_back(entry);
  }
  env_s.insert(env_s.end(), env.begin(), env.end());
  std::vector<char*> envp;
  for (auto& e : env_s) envp.push_back(e.data());
  envp.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw std::runtime_error("cannot start " + argv_s[0]);
  return pid;
}

ToolResult collect(int status, const TempDir& capture) {
  ToolResult result;
  result.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  result.killed_by_signal = WIFSIGNALED(status);
  result.out = read_file(capture / "stdout");
  result.err = read_file(capture / "stderr");
  return result;
}

}  // namespace

ToolResult run_command(const fs::path& program, const std::vector<std::string>& args, const std::vector<std::string>& env) {
  TempDir capture;
  const pid_t pid = spawn(program, args, env, capture);
  int status = 0;
  waitpid(pid, &status, 0);
  return collect(status, capture);
}

ToolResult run_tool_and_signal(const std::string& tool, const std::vector<std::string>& args,
                               const std::string& marker, int signal, double timeout_s) {
  TempDir capture;
  const pid_t pid = spawn(tool_path(tool), args, {}, capture);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  int status = 0;
  bool sent = false;
  for (;;) {
    if (waitpid(pid, &status, WNOHANG) == pid) return collect(status, capture);  // ended before the signal
    if (read_file(capture / "stderr").find(marker) != std::string::npos) break;
    if (std::chrono::steady_clock::now() > deadline) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  sent = ::kill(pid, signal) == 0;
  waitpid(pid, &status, 0);
  auto result = collect(status, capture);
  result.signal_sent = sent;
  return result;
}

ToolResult run_tool_as(unsigned uid, const std::string& tool, const std::vector<std::string>& args) {
  TempDir capture;
  fs::permissions(capture.path(), fs::perms::all, fs::perm_options::add);
  const fs::path out_file = capture / "stdout", err_file = capture / "stderr";
  // The checkout may sit in a home directory the other user cannot enter:
  // run a copy of the tool from the world-readable capture directory.
  const fs::path program = capture / tool;
  fs::copy_file(tool_path(tool), program);
  fs::permissions(program, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                               fs::perms::others_read | fs::perms::others_exec);
  std::vector<std::string> argv_s = {program.string()};
  argv_s.insert(argv_s.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : argv_s) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    const int out = open(out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0666);
    const int err = open(err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0666);
    dup2(out, 1);
    dup2(err, 2);
    if (setgid(uid) != 0 || setuid(uid) != 0) _exit(126);
    char* envp[] = {nullptr};
    execve(argv[0], argv.data(), envp);
    _exit(127);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  ToolResult result;
  result.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  result.killed_by_signal = WIFSIGNALED(status);
  result.out = read_file(out_file);
  result.err = read_file(err_file);
  return result;
}

TempDir::TempDir() {
  std::random_device rd;
  path_ = fs::temp_directory_path() / ("mesowave-test-" + std::to_string(::getpid()) + "-" + std::to_string(rd()));
  fs::create_directories(path_);
}

TempDir::~TempDir() {
  std::error_code ignored;
  fs::permissions(path_, fs::perms::owner_all, fs::perm_options::add, ignored);
  fs::remove_all(path_, ignored);
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_file(const fs::path& path, const std::string& content) {
  std::ofstream out(path, std::ios::binary);
  out << content;
}

std::size_t count_files(const fs::path& dir) {
  std::size_t n = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) ++n;
  return n;
}

}  // namespace mesowave::test
