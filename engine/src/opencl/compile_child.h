// Compiling OpenCL programs in a child process, so that the compiler's memory is never in the
// long-lived process that fits (issue 38).
//
// PoCL compiles on the CPU with LLVM inside the calling process: building a program from source
// and, at each kernel's first launch with a new work-group size, its work-group function. A
// drawing's first run (empty kernel caches) measured 370-374 MB against 228-237 MB warm, the
// difference the compiler's pages and heap, live to the end. Here a program missing from the
// kernel cache (opencl/kernel_cache.h) is compiled by a child `svgmotion devices --warm-for
// SPEC`, which builds it, launches its kernels as the caller will (filling PoCL's own cache of
// work-group functions) and exits; the caller then loads the cached binary as a warm run does.
//
// Opt-in: the child's command is the environment's SVGMOTION_COMPILE_CHILD, an absolute path to
// the svgmotion executable; unset, empty or relative, programs compile in the process as before.
// Not the default because it lowers the largest process, not the job: measured on the bundled
// example's first run (session 49, RSS of the process tree sampled every 0.1 s), the fitting
// process peaked at 285 MB with a child against 439 MB without, but the child itself reached
// 341 MB while the parent lived, and the tree's sum 532 MB: a cgroup (Slurm's --mem) counts the
// sum. It helps where the limit is per process (ulimit -v, RLIMIT_AS). An environment variable
// rather than a setting because the plugins (the procedural provider) carry their own static copy
// of the engine.
#pragma once

#include <string>
#include <vector>

namespace svgm {

// The environment variable naming the executable that compiles in a child.
inline const char* const kCompileChildVar = "SVGMOTION_COMPILE_CHILD";

// Whether programs missing from the cache are compiled in a child (the variable set and not
// empty).
bool compile_child_enabled();

// Runs `$SVGMOTION_COMPILE_CHILD devices --warm-for SPEC [--device DEVICE]` with its output
// discarded and its environment inherited, the variable empty (so the child compiles in
// itself), and waits for it. True when it exited 0. Never throws: a child that cannot start or
// fails only means the caller compiles in its own process, as before.
bool compile_in_child(const std::string& spec, const std::string& device);

}  // namespace svgm
