// Levelled logging (see svgmotion/log.h) over spdlog: one logger, a console sink on stderr and,
// while a run directory's log.txt is open, a file sink. This file keeps the engine's API and its
// exact line forms (tests and users grep them); spdlog does the sinks, levels and time stamps.
#include "svgmotion/log.h"

#include <algorithm>
#include <cerrno>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <memory>
#include <mutex>
#include <sys/time.h>

#include <spdlog/logger.h>
#include <spdlog/pattern_formatter.h>
#include <spdlog/sinks/basic_file_sink.h>
#include <spdlog/sinks/stdout_sinks.h>

#include "svgmotion/error.h"
#include "svgmotion/utf8_text.h"

namespace svgm::log {

namespace {

spdlog::level::level_enum spdlog_level(Level l) {
  switch (l) {
    case Level::Debug: return spdlog::level::debug;
    case Level::Info: return spdlog::level::info;
    case Level::Warning: return spdlog::level::warn;
    case Level::Error: return spdlog::level::err;
  }
  return spdlog::level::info;
}

// The console's "%*": "svgmotion: debug: ", "svgmotion: warning: ", "svgmotion: " (errors) or
// nothing (info lines carry their own "run: ", "svgmotion: " ...).
class ConsolePrefix final : public spdlog::custom_flag_formatter {
 public:
  void format(const spdlog::details::log_msg& msg, const std::tm&, spdlog::memory_buf_t& dest) override {
    const std::string_view prefix = msg.level == spdlog::level::debug  ? "svgmotion: debug: "
                                    : msg.level == spdlog::level::warn ? "svgmotion: warning: "
                                    : msg.level == spdlog::level::err  ? "svgmotion: "
                                                                       : "";
    dest.append(prefix.data(), prefix.data() + prefix.size());
  }
  std::unique_ptr<custom_flag_formatter> clone() const override { return std::make_unique<ConsolePrefix>(); }
};

// The sinks are single-threaded: every write holds Logger::mutex, which also guards swapping the
// file sink in and out.
struct Logger {
  std::mutex mutex;
  Level console = Level::Info;
  std::string command_line;
  std::shared_ptr<spdlog::sinks::stderr_sink_st> console_sink;
  std::shared_ptr<spdlog::sinks::basic_file_sink_st> file_sink;
  std::shared_ptr<spdlog::logger> logger;
  std::function<void(Level, const std::string&)> forward;

  Logger() {
    console_sink = std::make_shared<spdlog::sinks::stderr_sink_st>();
    auto console_format = std::make_unique<spdlog::pattern_formatter>();
    console_format->add_flag<ConsolePrefix>('*').set_pattern("%*%v");
    console_sink->set_formatter(std::move(console_format));
    console_sink->set_level(spdlog_level(console));
    logger = std::make_shared<spdlog::logger>("svgmotion", console_sink);
    logger->set_level(spdlog::level::debug);  // each sink filters for itself
    logger->flush_on(spdlog::level::debug);   // a crash or Ctrl-C keeps every line written so far
  }
};

Logger& logger() {
  static Logger l;
  return l;
}

// "2026-12-02T06:50:01.123Z": UTC to the millisecond (the file sink's pattern says the same).
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
  logger().console_sink->set_level(spdlog_level(level));
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
  // The header line is written before spdlog appends: it has no level, and opening the file
  // here first gives the error line its reason (spdlog's exception would not name it).
  std::FILE* f = std::fopen(path.c_str(), "a");
  if (!f) throw Error(path.string() + ": cannot open the log file for writing (" + std::strerror(errno) + ")");
  std::fprintf(f, "%s ===== svgmotion %s: %s\n", timestamp().c_str(), SVGM_VERSION,
               shown_utf8(l.command_line).c_str());
  std::fclose(f);
  std::shared_ptr<spdlog::sinks::basic_file_sink_st> sink;
  try {
    sink = std::make_shared<spdlog::sinks::basic_file_sink_st>(path.string(), /*truncate=*/false);
  } catch (const spdlog::spdlog_ex& e) {
    throw Error(path.string() + ": cannot open the log file for writing (" + e.what() + ")");
  }
  sink->set_formatter(std::make_unique<spdlog::pattern_formatter>("%Y-%m-%dT%H:%M:%S.%eZ %-7l %v",
                                                                  spdlog::pattern_time_type::utc));
  sink->set_level(spdlog::level::debug);  // every message, whatever the console shows
  auto& sinks = l.logger->sinks();
  if (l.file_sink) sinks.erase(std::find(sinks.begin(), sinks.end(), l.file_sink));
  l.file_sink = sink;
  sinks.push_back(sink);
}

void close_file() {
  Logger& l = logger();
  std::lock_guard lock(l.mutex);
  if (!l.file_sink) return;
  auto& sinks = l.logger->sinks();
  sinks.erase(std::find(sinks.begin(), sinks.end(), l.file_sink));
  l.file_sink.reset();
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
    // The message is passed as it is, never as a format string: it may hold '{' and '%'.
    if (!forward) l.logger->log(spdlog_level(level), spdlog::string_view_t(message));
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
