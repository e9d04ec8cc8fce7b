// Device buffers initialised from host memory (see input_buffer in cl.h).
#include <algorithm>
#include <array>
#include <cstring>

#include "opencl/cl.h"

namespace svgm {

cl::Buffer input_buffer(const cl::Context& ctx, const void* host, size_t bytes, cl_mem_flags access) {
  if (bytes >= kMinBufferBytes)
    return cl::Buffer(ctx, access | CL_MEM_COPY_HOST_PTR, bytes, const_cast<void*>(host));
  // Short or empty: the buffer is kMinBufferBytes, so the copy comes from a block that size.
  std::array<unsigned char, kMinBufferBytes> padded{};
  if (bytes > 0) std::memcpy(padded.data(), host, bytes);
  return cl::Buffer(ctx, access | CL_MEM_COPY_HOST_PTR, padded.size(), padded.data());
}

}  // namespace svgm
