// Work-group sizes of the raster kernels whose launches would otherwise take the largest size
// dividing a count of the drawing (stable_local_size in opencl/cl.h).
//
// PoCL compiles a kernel's work-group function once per work-group size; fixed sizes make the
// functions a drawing launches the same for every drawing, so a child process compiling them
// ahead (opencl/compile_child.h) compiles the ones this drawing will launch. Each work-item of
// these kernels is its own stroke or row: the size changes no value.
#pragma once

#include "opencl/cl.h"

namespace svgm {

// stroke and stroke_backward (one stroke per work-item; the global size is rounded up to 8).
inline const cl::NDRange kStrokeGroup{8, 1};
// blur_y_loss_rows (one row per work-item; the global size is rounded up to 16).
inline const cl::NDRange kRowGroup{16, 1};

}  // namespace svgm
