#include "mesowave/app/subprocess.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "mesowave/core/error.hpp"

extern char** environ;

namespace mesowave::app {

ProcessResult run_process(const std::vector<std::string>& argv) {
  if (argv.empty()) throw InputError("run_process: no command");
  int pipe_fd[2];
  if (pipe(pipe_fd) != 0) throw InputError(std::string("cannot create a pipe: ") + std::strerror(errno));
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, pipe_fd[1], STDERR_FILENO);
  posix_spawn_file_actions_addclose(&actions, pipe_fd[0]);
  posix_spawn_file_actions_addclose(&actions, pipe_fd[1]);
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(pipe_fd[1]);
  if (spawned != 0) {
    close(pipe_fd[0]);
    throw InputError("cannot run " + argv[0] + ": " + std::strerror(spawned));
  }
  ProcessResult result;
  char buffer[4096];
  for (ssize_t n; (n = read(pipe_fd[0], buffer, sizeof buffer)) != 0;) {
    if (n < 0) {
      if (errno == EINTR) continue;
      break;
    }
    result.stderr_text.append(buffer, std::size_t(n));
  }
  close(pipe_fd[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  result.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return result;
}

void run_process_or_throw(const std::vector<std::string>& argv, const std::string& what) {
  const ProcessResult r = run_process(argv);
  if (r.exit_status == 0) return;
  std::string why = r.stderr_text;
  while (!why.empty() && (why.back() == '\n' || why.back() == '\r')) why.pop_back();
  if (const auto nl = why.rfind('\n'); nl != std::string::npos) why = why.substr(nl + 1);
  throw InputError(what + " (" + std::filesystem::path(argv.at(0)).filename().string() + ", exit " +
                   std::to_string(r.exit_status) + ") failed: " + why);
}

std::filesystem::path sibling_tool(const std::string& name) {
  std::error_code ec;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return name;
  return self.parent_path() / name;
}

}  // namespace mesowave::app
