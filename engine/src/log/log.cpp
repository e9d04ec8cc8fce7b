// Levelled logging (see svgmotion/log.h).
#include "svgmotion/log.h"

#include <cerrno>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <mutex>
#include <sys/time.h>

#include "svgmotion/error.h"
#include "svgmotion/utf8_text.h"

namespace svgm::log {

namespace {

struct Logger {
  std::mutex mutex;
  Level console = Level::Info;
  std::string command_line;
  std::FILE* file = nullptr;
  std::function<void(Level, const std::string&)> forward;
  ~Logger() {
    if (file) std::fclose(file);
  }
};

Logger& logger() {
  static Logger l;
  return l;
}

const char* level_name(Level l) {
  switch (l) {
    case Level::Debug: return "debug";
    case Level::Info: return "info";
    case Level::Warning: return "warning";
    case Level::Error: return "error";
  }
  return "info";
}

// "2026-12-02T06:50:01.123Z": UTC to the millisecond.
std::string timestamp() {
  timeval tv{};
  ::gettimeofday(&tv, nullptr);
  std::tm tm{};
  ::gmtime_r(&tv.tv_sec, &tm);
  char buf[40];
  const size_t n = std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%S", &tm);
  std::snprintf(buf + n, sizeof buf - n, ".%03dZ", static_cast<int>(tv.tv_usec / 1000));
  return buf;
}

std::string formatted(const char* format, va_list args) {
  va_list copy;
  va_copy(copy, args);
  const int n = std::vsnprintf(nullptr, 0, format, copy);
  va_end(copy);
  std::string s(n > 0 ? static_cast<size_t>(n) : 0, '\0');
  if (n > 0) std::vsnprintf(s.data(), s.size() + 1, format, args);
  return s;
}

}  // namespace

void set_console_level(Level level) {
  std::lock_guard lock(logger().mutex);
  logger().console = level;
}

Level console_level() {
  std::lock_guard lock(logger().mutex);
  return logger().console;
}

bool quiet() { return console_level() > Level::Info; }

void set_command_line(const std::string& line) {
  std::lock_guard lock(logger().mutex);
  logger().command_line = line;
}

void open_file(const std::filesystem::path& path) {
  Logger& l = logger();
  std::lock_guard lock(l.mutex);
  std::FILE* f = std::fopen(path.c_str(), "a");
  if (!f) throw Error(path.string() + ": cannot open the log file for writing (" + std::strerror(errno) + ")");
  if (l.file) std::fclose(l.file);
  l.file = f;
  std::fprintf(f, "%s ===== svgmotion %s: %s\n", timestamp().c_str(), SVGM_VERSION,
               shown_utf8(l.command_line).c_str());
  std::fflush(f);
}

void close_file() {
  std::lock_guard lock(logger().mutex);
  if (logger().file) std::fclose(logger().file);
  logger().file = nullptr;
}

void set_forward(std::function<void(Level, const std::string&)> forward) {
  std::lock_guard lock(logger().mutex);
  logger().forward = std::move(forward);
}

void write(Level level, const std::string& raw_message) {
  // A message naming a file whose name is not UTF-8 shows U+FFFD for the stray bytes
  // (svgmotion/utf8_text.h): the console, log.txt and the host's log all get valid UTF-8.
  const std::string message = shown_utf8(raw_message);
  Logger& l = logger();
  std::function<void(Level, const std::string&)> forward;
  {
    std::lock_guard lock(l.mutex);
    forward = l.forward;
    if (!forward) {
      const char* prefix = level == Level::Debug     ? "svgmotion: debug: "
                           : level == Level::Warning ? "svgmotion: warning: "
                           : level == Level::Error   ? "svgmotion: "
                                                     : "";
      if (level >= l.console) std::fprintf(stderr, "%s%s\n", prefix, message.c_str());
      if (l.file) {
        std::fprintf(l.file, "%s %-7s %s\n", timestamp().c_str(), level_name(level), message.c_str());
        std::fflush(l.file);  // a crash or Ctrl-C keeps every line written so far
      }
    }
  }
  if (forward) forward(level, message);  // outside the lock: the host may log back into its own
}

#define SVGM_LOG_FORM(name, level)       \
  void name(const char* format, ...) {   \
    va_list args;                        \
    va_start(args, format);              \
    const std::string m = formatted(format, args); \
    va_end(args);                        \
    write(level, m);                     \
  }
SVGM_LOG_FORM(debug, Level::Debug)
SVGM_LOG_FORM(info, Level::Info)
SVGM_LOG_FORM(warning, Level::Warning)
SVGM_LOG_FORM(error, Level::Error)
#undef SVGM_LOG_FORM

}  // namespace svgm::log
