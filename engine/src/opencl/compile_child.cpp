// Compiling OpenCL programs in a child process (see compile_child.h).
#include "opencl/compile_child.h"

#include <cstdlib>
#include <exception>

#include "generators/command_runner.h"
#include "svgmotion/log.h"

namespace svgm {

namespace {
// The child's limit: a program's build and its kernels' first launches took 43 s from empty
// caches on a 2-core machine (`devices --warm`, three programs); ten times that before it is
// taken for hung, and the caller compiles in itself.
constexpr double kChildTimeoutSeconds = 600;
}  // namespace

bool compile_child_enabled() {
  // Absolute only: a relative name would run whatever file of that name the working directory
  // (or PATH, which run_command searches) holds.
  const char* exe = std::getenv(kCompileChildVar);
  return exe && exe[0] == '/';
}

bool compile_in_child(const std::string& spec, const std::string& device) {
  if (!compile_child_enabled()) return false;
  std::vector<std::string> argv{std::getenv(kCompileChildVar), "devices", "--warm-for", spec};
  if (!device.empty()) argv.insert(argv.end(), {"--device", device});
  // Through run_command (generators/command_runner.h): a process group of its own, stopped on a
  // time limit or the user's Ctrl-C, none of this process's descriptors (OpenCL drivers,
  // sockets) inherited. The environment is this one's; the child empties the variable itself
  // (cmd_devices.cpp), so it compiles in itself.
  CommandResult r;
  try {
    r = run_command(argv, "/dev/null", kChildTimeoutSeconds);
  } catch (const std::exception& e) {
    log::debug("opencl: cannot start %s to compile the kernels (%s): compiling them here", argv[0].c_str(), e.what());
    return false;
  }
  if (!r.ok())
    log::debug("opencl: the kernels' compile in a child (%s) %s: compiling them here", spec.c_str(),
               describe(r, kChildTimeoutSeconds).c_str());
  return r.ok();
}

}  // namespace svgm
