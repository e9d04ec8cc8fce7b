// The one place the OpenCL C++ bindings are included, with the project's settings.
//
// Exceptions are enabled so that every failing call surfaces; engine code catches cl::Error at
// the routine boundary and rethrows svgm::Error with a sentence a user can act on.
#pragma once

#ifndef CL_HPP_ENABLE_EXCEPTIONS
#define CL_HPP_ENABLE_EXCEPTIONS
#endif
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wignored-attributes"
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
#include <CL/opencl.hpp>
#pragma GCC diagnostic pop

#include <string>

namespace svgm {

// "CL_OUT_OF_RESOURCES (-5)" style name for an OpenCL status code.
std::string cl_status_name(int status);

// OpenCL refuses zero-sized buffers: every buffer has at least this many bytes.
constexpr size_t kMinBufferBytes = 16;

// A device buffer of max(bytes, kMinBufferBytes) bytes holding the `bytes` bytes at `host`.
// CL_MEM_COPY_HOST_PTR reads the whole buffer size from the host pointer, so a short input is
// copied into a zero-padded block first (never read past `host`), and an empty one (whose
// data() may be null: CL_INVALID_HOST_PTR) never passes its own pointer. Throws cl::Error.
cl::Buffer input_buffer(const cl::Context& ctx, const void* host, size_t bytes,
                        cl_mem_flags access = CL_MEM_READ_ONLY);

// n rounded up to a multiple of m: global sizes must be multiples of the work-group size.
inline size_t round_up(size_t n, size_t m) { return (n + m - 1) / m * m; }

// The work-group size of a launch that needs none of its own: the largest power of two up to 64
// dividing the first global size, 1 in the others. Left to the driver, PoCL picks a size from
// the whole range and compiles the kernel again for every size it picks: with the frames as the
// second dimension, progressive keyframe activation compiled each kernel once per frame count
// (319 kernel compiles, most of a first run's minute, in the bundled example's run).
inline cl::NDRange stable_local_size(const cl::NDRange& global) {
  if (global.dimensions() == 0) return cl::NullRange;
  size_t l = 64;
  while (l > 1 && global[0] % l != 0) l /= 2;
  if (global.dimensions() == 1) return cl::NDRange(l);
  if (global.dimensions() == 2) return cl::NDRange(l, 1);
  return cl::NDRange(l, 1, 1);
}

// Enqueues `k` over `global` with stable_local_size(global).
inline void enqueue_stable(cl::CommandQueue& q, cl::Kernel& k, const cl::NDRange& global) {
  q.enqueueNDRangeKernel(k, cl::NullRange, global, stable_local_size(global));
}

// Sets a kernel's arguments 0, 1, 2, ... in order.
template <class... A>
void set_args(cl::Kernel& k, const A&... args) {
  cl_uint i = 0;
  (k.setArg(i++, args), ...);
}

// Sets a kernel's arguments first, first + 1, ... in order.
template <class... A>
void set_args_at(cl::Kernel& k, cl_uint first, const A&... args) {
  cl_uint i = first;
  (k.setArg(i++, args), ...);
}

}  // namespace svgm
