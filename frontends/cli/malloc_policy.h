// The process's heap policy: large blocks go back to the system when freed (issue 38).
//
// glibc raises its mmap threshold to the size of each mmap-ed block freed (up to 32 MB), so
// after the first frame-sized buffers are freed, later ones of a few MB come from the heap and
// its per-thread arenas (PoCL allocates its buffers there too, with posix_memalign), whose freed
// holes stay resident, to be filled only by blocks that fit in them. Pinning
// the threshold keeps every block of 4 MB or more in its own mapping, returned whole on free.
// The bundled example's `run`: 640 / 634 / 703 MB -> 534 MB with the threshold alone (at 1 MB),
// the same animation.svg. The price is page faults on every fresh mapping: system time
// 4-5 s -> 14 s at 4 MB (21-26 s at 1 MB, for the same peak), elapsed time alike.
#pragma once

namespace svgm::cli {

// Call once, first thing in main (before any thread exists). No-op off glibc.
void use_returning_malloc();

}  // namespace svgm::cli
