// Handing the heap's free pages back to the system between a fit's steps (issue 38).
//
// Blocks under the mmap threshold (4 MB in `svgmotion`, frontends/cli/malloc_policy.h: a
// 256-px frame as float RGBA is 1 MB, the decoder's and the denoiser's frames, PoCL's smaller
// buffers) come from the heap and the threads' arenas; once freed they stay resident until a
// block that fits reuses them. A step that makes and frees many of them (a target's load, the
// judging of the frames between keyframes, the earlier stages of a `run`) leaves tens of MB
// resident that the next step does not reuse: measured on the bundled example's `run`,
// malloc_trim after the frames were judged took VmRSS from 428 to 359 MB, after the preview
// from 433 to 371, and the refinement ran 60 MB lower with the trims before it.
#pragma once

namespace svgm {

// Returns the free pages of every arena to the system (malloc_trim(0): the holes too, not only
// the top). A few ms; no-op off glibc. Call after a step has freed its temporaries.
void trim_heap();

}  // namespace svgm
