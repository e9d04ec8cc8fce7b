// What `svgmotion devices --warm-for SPEC` runs: one OpenCL program made and every kernel of it
// launched, in the child process that compiles a program for a fit (opencl/compile_child.h).
//
// PoCL compiles a program's kernels a second time at their first launch, once per work-group
// size and per zero or non-zero global offset (its work-group functions, kept in its own
// cache, ~/.cache/pocl/kcache). Building the program alone would leave those compiles, most of
// the work (about 14 times the build), to the process that fits. So the child launches each
// kernel as a fit does: the same work-group sizes (fixed per kernel, or fixed by the width's
// tuning) and both kinds of offset (frames rendered one by one; the loss a chunk of frames at
// a time).
#pragma once

#include <string>

#include "opencl/runtime.h"

namespace svgm::cli {

// SPEC is "raster WIDTH HEIGHT SIGMA CHROMA_SIGMA CHROMA_WEIGHT" (ClRaster's program for that
// size and blur) or "fitter" (the fitter's program). Throws svgm::Error on a malformed SPEC.
void warm_for(ClRuntime& rt, const std::string& spec);

// The raster program of a WIDTH x HEIGHT render with that blur, every kernel launched.
void warm_raster(ClRuntime& rt, int width, int height, double sigma, double chroma_sigma, double chroma_weight);

// The fitter's program, every kernel launched by a few steps of a small fit at 256 px.
void warm_fitter(ClRuntime& rt);

}  // namespace svgm::cli
