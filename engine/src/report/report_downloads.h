// report.html's list of outputs (section svgm-downloads): every file of the run
// directory with its size, what it is, and a link relative to the page (the
// page lives in the run directory, so the links work wherever the folder is
// copied). Hidden files (.svgmotion/, temporary names) and report.html itself
// are left out; candidate videos are listed from candidates/.
#pragma once

#include <filesystem>
#include <string>

namespace svgm {

// The section's HTML.
std::string downloads_section(const std::filesystem::path &run);

// `relative` (a path inside the run directory, '/'-separated) as a URL path:
// every byte but unreserved ones and '/' percent-encoded, so no name can leave
// the attribute or the folder's meaning (a file named "a#b" or "x?y" links to
// itself).
std::string url_path(const std::string &relative);

} // namespace svgm
