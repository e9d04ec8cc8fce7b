// The process's heap policy (malloc_policy.h).
#include "cli/malloc_policy.h"

#include <cstdlib>  // defines __GLIBC__ on glibc

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace svgm::cli {

namespace {
// Blocks of this many bytes or more are mapped on their own: a 512-px frame as float RGBA is
// 4 MB, the loss's Q and R of 21 keyframes at 256 px 11 MB each. 1 MB gave the same peak with
// half again the system time (malloc_policy.h). Setting it also stops glibc adjusting it
// (mallopt(3)).
constexpr int kMmapThresholdBytes = 4 << 20;
}  // namespace

void use_returning_malloc() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, kMmapThresholdBytes);
#endif
}

}  // namespace svgm::cli
