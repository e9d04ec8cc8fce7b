// A look at a plugin file before dlopen. The dynamic loader maps a module's segments as the
// program headers describe them; when the file is shorter than that (a copy cut short, a
// download interrupted), touching the missing pages raises SIGBUS inside dlopen, which kills
// the process before it can say anything. So the ELF header, the program and section header
// tables and every loaded segment are checked against the file's size first.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace svgm {

// Why `file` cannot be a loadable module for this process ("truncated: 4096 bytes, but its
// segments end at 16384"), or nothing when dlopen may be tried.
std::optional<std::string> module_problem(const std::filesystem::path& file);

}  // namespace svgm
