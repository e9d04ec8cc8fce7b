// The OpenCL compiler's clean pages released (compiler_pages.h).
#include "opencl/compiler_pages.h"

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace svgm {

namespace {

bool is_compiler(const std::string& path) {
  const size_t slash = path.rfind('/');
  const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  return name.rfind("libLLVM", 0) == 0 || name.rfind("libclang-cpp", 0) == 0;
}

struct Mapping {
  uintptr_t from = 0, to = 0;
  bool candidate = false;  // a compiler library's, not writable
  size_t rss_kb = 0, dirty_kb = 0;
};

size_t release(const Mapping& m) {
#if defined(__linux__)
  if (!m.candidate || m.dirty_kb != 0 || m.rss_kb == 0 || m.to <= m.from) return 0;
  return madvise(reinterpret_cast<void*>(m.from), m.to - m.from, MADV_DONTNEED) == 0 ? m.rss_kb : 0;
#else
  (void)m;
  return 0;
#endif
}

}  // namespace

size_t release_compiler_pages() {
  std::ifstream smaps("/proc/self/smaps");
  if (!smaps) return 0;
  size_t dropped = 0;
  Mapping m;
  std::string line;
  // A mapping's header ("start-end perms offset dev inode path"), then its "Key: value kB" lines.
  while (std::getline(smaps, line)) {
    const size_t dash = line.find('-'), space = line.find(' ');
    const bool header = dash != std::string::npos && space != std::string::npos && dash < space &&
                        line.find(':') > space;
    if (header) {
      dropped += release(m);
      m = Mapping{};
      m.from = std::strtoull(line.c_str(), nullptr, 16);
      m.to = std::strtoull(line.c_str() + dash + 1, nullptr, 16);
      const std::string perms = line.substr(space + 1, 4);
      const size_t path = line.find('/');
      m.candidate = perms.size() == 4 && perms[1] != 'w' && path != std::string::npos && is_compiler(line.substr(path));
      continue;
    }
    if (line.rfind("Rss:", 0) == 0) m.rss_kb = std::strtoull(line.c_str() + 4, nullptr, 10);
    else if (line.rfind("Private_Dirty:", 0) == 0) m.dirty_kb = std::strtoull(line.c_str() + 14, nullptr, 10);
  }
  dropped += release(m);
  return dropped;
}

}  // namespace svgm
