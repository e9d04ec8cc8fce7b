// Atomic file writes (see svgmotion/atomic_file.h).
#include "svgmotion/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "svgmotion/error.h"

namespace svgm {

namespace fs = std::filesystem;

namespace {

// The kernel's own limit on links followed in one lookup (Linux MAXSYMLINKS).
constexpr int kMaxLinks = 40;

}  // namespace

fs::path output_target(const fs::path& file) {
  fs::path p = file;
  std::error_code ec;
  for (int hops = 0;; ++hops) {
    const fs::file_status st = fs::symlink_status(p, ec);
    if (ec || st.type() == fs::file_type::not_found) {
      // Absent (or unreadable: the write itself will say why): a new file goes here.
      return p;
    }
    if (st.type() == fs::file_type::regular) return p;
    if (st.type() != fs::file_type::symlink)
      throw Error(file.string() + ": not a regular file" +
                  (p == file ? std::string() : " (it links to " + p.string() + ")"));
    if (hops == kMaxLinks) throw Error(file.string() + ": too many levels of symbolic links");
    const fs::path to = fs::read_symlink(p, ec);
    if (ec) throw Error(file.string() + ": cannot write: " + ec.message());
    p = to.is_absolute() ? to : p.parent_path() / to;
  }
}

void write_file_atomic(const fs::path& file, std::string_view bytes) {
  const fs::path target = output_target(file);
  // The pid keeps two processes writing the same file from sharing a temporary.
  const fs::path tmp = target.string() + ".part" + std::to_string(::getpid());
  auto fail = [&](const std::string& why) {
    ::unlink(tmp.c_str());
    throw Error(file.string() + ": cannot write: " + why);
  };
  // O_EXCL after removing a stale temporary of ours: the write never follows a link or
  // opens a FIFO someone left at the temporary name.
  ::unlink(tmp.c_str());
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) throw Error(file.string() + ": cannot write: " + std::strerror(errno));
  for (size_t done = 0; done < bytes.size();) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const std::string why = std::strerror(n < 0 ? errno : EIO);
      ::close(fd);
      fail(why);
    }
    done += static_cast<size_t>(n);
  }
  if (::close(fd) != 0) fail(std::strerror(errno));
  std::error_code ec;
  fs::rename(tmp, target, ec);
  if (ec) fail(ec.message());
}

}  // namespace svgm
