// The process's heap policy (malloc_policy.h).
#include "cli/malloc_policy.h"

#include <cstdlib>  // defines __GLIBC__ on glibc

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace svgm::cli {

namespace {
// Blocks of this many bytes or more are mapped on their own (a frame of 256 px as float RGBA is
// 1 MB; a 512-px one 4 MB). Setting it also stops glibc adjusting it (mallopt(3)).
constexpr int kMmapThresholdBytes = 1 << 20;
}  // namespace

void use_returning_malloc() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, kMmapThresholdBytes);
#endif
}

}  // namespace svgm::cli
