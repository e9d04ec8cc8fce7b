// Releasing the OpenCL compiler's clean pages. PoCL's CPU driver links LLVM and clang (libLLVM,
// libclang-cpp: ~65 MB of the process's resident set in a `run`); loading them runs their
// static constructors and relocations, which leave pages resident even when every kernel comes
// from the kernel cache (opencl/kernel_cache.h) and nothing is compiled. Those pages count in a
// fit's peak (issue 38).
#pragma once

#include <cstddef>

namespace svgm {

// Drops from the resident set the pages of the compiler's mappings that hold no written page:
// madvise MADV_DONTNEED on each mapping of libLLVM / libclang-cpp that is not writable and has no
// private dirty page (/proc/self/smaps), so nothing but clean file pages goes (read again from
// the file if the compiler runs later, e.g. a kernel built from source). Returns the kB dropped
// (the mappings' Rss as smaps counted it); 0 where /proc is missing.
size_t release_compiler_pages();

}  // namespace svgm
