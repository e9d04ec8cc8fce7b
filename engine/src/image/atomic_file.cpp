// Atomic file writes (see svgmotion/atomic_file.h).
#include "svgmotion/atomic_file.h"
#include "svgmotion/temporary_name.h"

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

constexpr std::string_view kTempMark = ".svgm-tmp-";

}  // namespace

fs::path temporary_path(const fs::path& target, std::string_view suffix) {
  // The pid keeps two processes writing the same file from sharing a temporary.
  return target.parent_path() /
         ("." + target.filename().string() + std::string(kTempMark) + std::to_string(::getpid()) + std::string(suffix));
}

long temporary_name_pid(std::string_view name) {
  for (std::string_view ext : {".mp4", ".webm"})
    if (name.size() > ext.size() && name.substr(name.size() - ext.size()) == ext) {
      const std::string_view rest = name.substr(0, name.size() - ext.size());
      if (const long pid = temporary_name_pid(rest); pid >= 0) return pid;
    }
  const size_t at = name.rfind(kTempMark);
  // "." + a name of at least one character before the mark, digits after it.
  if (name.size() < 2 || name[0] != '.' || at == std::string_view::npos || at < 2) return -1;
  const std::string_view digits = name.substr(at + kTempMark.size());
  if (digits.empty() || digits.size() > 10) return -1;
  long pid = 0;
  for (char c : digits) {
    if (c < '0' || c > '9') return -1;
    pid = pid * 10 + (c - '0');
  }
  return pid;
}

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
  const fs::path tmp = temporary_path(target);
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
