// Atomic file writes (see svgmotion/atomic_file.h).
#include "svgmotion/atomic_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <string>

#include "svgmotion/error.h"

namespace svgm {

void write_file_atomic(const std::filesystem::path& file, std::string_view bytes) {
  namespace fs = std::filesystem;
  // The pid keeps two processes writing the same file from sharing a temporary.
  const fs::path tmp = file.string() + ".part" + std::to_string(::getpid());
  std::error_code ec;
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    if (!f) throw Error(file.string() + ": cannot write: " + std::strerror(errno));
    f.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    f.flush();
    if (!f) {
      fs::remove(tmp, ec);
      throw Error(file.string() + ": cannot write: " + std::strerror(errno));
    }
  }
  fs::rename(tmp, file, ec);
  if (ec) {
    const std::string why = ec.message();
    fs::remove(tmp, ec);
    throw Error(file.string() + ": cannot write: " + why);
  }
}

}  // namespace svgm
