// Compiling OpenCL programs in a child process (see compile_child.h).
#include "opencl/compile_child.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

#include "svgmotion/log.h"

extern char** environ;

namespace svgm {

bool compile_child_enabled() {
  // Absolute only: posix_spawn does not search PATH, and a relative name would run whatever file
  // of that name the working directory holds.
  const char* exe = std::getenv(kCompileChildVar);
  return exe && exe[0] == '/';
}

bool compile_in_child(const std::string& spec, const std::string& device) {
  if (!compile_child_enabled()) return false;
  const char* exe = std::getenv(kCompileChildVar);
  std::vector<std::string> args{exe, "devices", "--warm-for", spec};
  if (!device.empty()) args.insert(args.end(), {"--device", device});
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  // The environment with the variable empty: the child compiles in itself (the CLI sets it
  // only when it is unset).
  std::string off = std::string(kCompileChildVar) + "=";
  std::vector<char*> envp;
  for (char** e = environ; e && *e; ++e)
    if (std::strncmp(*e, off.c_str(), off.size()) != 0) envp.push_back(*e);
  envp.push_back(off.data());
  envp.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&fa, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&fa, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, exe, &fa, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&fa);
  if (rc != 0) {
    log::debug("opencl: cannot start %s to compile the kernels (%s): compiling them here", exe, std::strerror(rc));
    return false;
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return false;
  const bool ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  if (!ok) log::debug("opencl: the kernels' compile in a child (%s) failed: compiling them here", spec.c_str());
  return ok;
}

}  // namespace svgm
