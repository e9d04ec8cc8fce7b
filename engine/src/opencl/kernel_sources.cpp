// Lookup of embedded kernel sources by file name.
#include "opencl/kernel_sources.h"

#include "svgmotion/error.h"

namespace svgm {

std::string_view kernel_source(std::string_view name) {
  for (const auto& k : embedded_kernels())
    if (name == k.name) return k.text;
  throw Error("internal: no embedded kernel named " + std::string(name));
}

}  // namespace svgm
