// Writing a file so that readers never see half of it: the bytes go to a temporary name in the
// same folder, which is then renamed over the target. Every output of svgmotion is written so.
#pragma once

#include <filesystem>
#include <string_view>

namespace svgm {

// Throws svgm::Error "<file>: cannot write: <reason>"; on failure nothing is left behind.
void write_file_atomic(const std::filesystem::path& file, std::string_view bytes);

}  // namespace svgm
