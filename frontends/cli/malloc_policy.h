// The process's heap policy: large blocks go back to the system when freed (issue 38).
//
// glibc raises its mmap threshold to the size of each mmap-ed block freed (up to 32 MB), so
// after the first frame-sized buffers are freed, later ones of 1-32 MB come from the heap and
// its per-thread arenas (PoCL's workers allocate there too), whose freed holes stay resident.
// The bundled example's `run` held ~110 MB of such holes at its peak (640 MB -> 534 MB with the
// threshold pinned; the same animation.svg). Pinning the threshold keeps every block of 1 MB
// or more in its own mapping, returned whole on free; smaller ones stay on the heap.
#pragma once

namespace svgm::cli {

// Call once, first thing in main (before any thread exists). No-op off glibc.
void use_returning_malloc();

}  // namespace svgm::cli
