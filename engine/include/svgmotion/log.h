// Levelled logging: every message of the engine, the CLI and (through the host) the plugins.
//
// Four levels: debug (per-stage details, fitter progress; shown with --verbose), info (what a
// command is doing and what it wrote), warning and error. The console (stderr) shows messages at
// or above its level: info by default, debug with --verbose, warnings and errors with --quiet,
// errors only with --quiet twice. A log file, when open (`run` keeps RUN_DIR/log.txt), receives
// every message whatever the console shows, each line with a UTC timestamp and its level.
//
// Console forms: info lines as given (they carry their own "run: ", "svgmotion: " ...),
// "svgmotion: warning: ...", "svgmotion: debug: ..." and "svgmotion: ..." for errors.
//
// A plugin links its own copy of the engine, so its messages would reach a logger the host
// never configured: set_forward() (plugin_glue.h does it) hands every message to the host's
// log callback instead, which passes it to the host's logger. Thread-safe (one mutex).
#pragma once

#include <filesystem>
#include <functional>
#include <string>

namespace svgm::log {

enum class Level { Debug = 0, Info = 1, Warning = 2, Error = 3 };

void set_console_level(Level level);
Level console_level();
// True when the console hides info lines (--quiet): commands skip their progress displays.
bool quiet();

// The command line, for the header line a log file gets when opened.
void set_command_line(const std::string& line);
// Appends to `path` from now on: one header line (time and command line), then every message.
// Throws svgm::Error naming the file when it cannot be opened.
void open_file(const std::filesystem::path& path);
void close_file();

// Every message goes to `forward` instead of this logger's console and file (a plugin's copy
// of the engine forwarding to the host); an empty function restores the console.
void set_forward(std::function<void(Level, const std::string&)> forward);

void write(Level level, const std::string& message);
// printf-style forms of write().
void debug(const char* format, ...) __attribute__((format(printf, 1, 2)));
void info(const char* format, ...) __attribute__((format(printf, 1, 2)));
void warning(const char* format, ...) __attribute__((format(printf, 1, 2)));
void error(const char* format, ...) __attribute__((format(printf, 1, 2)));

}  // namespace svgm::log
