// The compiled-program cache files (see kernel_cache.h).
#include "opencl/kernel_cache.h"

#include <unistd.h>

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string_view>

namespace svgm {

namespace fs = std::filesystem;

namespace {

// "SVGMKC1\n", then the payload length and its FNV-1a hash, both little-endian uint64.
constexpr std::string_view kMagic = "SVGMKC1\n";
constexpr size_t kHeaderBytes = 8 + 8 + 8;

uint64_t fnv1a(std::string_view s) {
  uint64_t h = 1469598103934665603ull;
  for (unsigned char c : s) h = (h ^ c) * 1099511628211ull;
  return h;
}

void put_u64(std::string& out, uint64_t v) {
  for (int i = 0; i < 8; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
}

uint64_t get_u64(std::string_view in) {
  uint64_t v = 0;
  for (int i = 7; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(in[static_cast<size_t>(i)]);
  return v;
}

// Unique per host (pids repeat across the nodes of a shared file system), process and call.
std::string temp_suffix() {
  static std::atomic<unsigned> counter{0};
  char host[64] = "host";
  if (::gethostname(host, sizeof host - 1) != 0) std::strcpy(host, "host");
  host[sizeof host - 1] = '\0';
  return std::string(".tmp.") + host + "." + std::to_string(::getpid()) + "." + std::to_string(counter++);
}

}  // namespace

fs::path kernel_cache_dir() {
  if (const char* d = std::getenv("SVGMOTION_CACHE_DIR"); d && *d) return fs::path(d);
  if (const char* d = std::getenv("XDG_CACHE_HOME"); d && *d) return fs::path(d) / "svgmotion";
  if (const char* d = std::getenv("HOME"); d && *d) return fs::path(d) / ".cache" / "svgmotion";
  return {};
}

std::optional<std::string> read_cached_binary(const fs::path& file) {
  std::ifstream f(file, std::ios::binary);
  if (!f) return std::nullopt;
  const std::string all((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  if (all.size() < kHeaderBytes || std::string_view(all).substr(0, kMagic.size()) != kMagic) return std::nullopt;
  const std::string_view header(all.data() + kMagic.size(), 16);
  const std::string_view payload(all.data() + kHeaderBytes, all.size() - kHeaderBytes);
  if (get_u64(header.substr(0, 8)) != payload.size() || get_u64(header.substr(8, 8)) != fnv1a(payload))
    return std::nullopt;
  return std::string(payload);
}

void write_cached_binary(const fs::path& file, const std::string& payload) {
  std::error_code ec;
  fs::create_directories(file.parent_path(), ec);
  std::string bytes(kMagic);
  put_u64(bytes, payload.size());
  put_u64(bytes, fnv1a(payload));
  bytes += payload;
  const fs::path tmp = file.string() + temp_suffix();
  {
    std::ofstream f(tmp, std::ios::binary);
    if (!f) return;
    f.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    f.flush();
    if (!f) {
      f.close();
      fs::remove(tmp, ec);
      return;
    }
  }
  fs::rename(tmp, file, ec);
  if (ec) fs::remove(tmp, ec);
}

}  // namespace svgm
