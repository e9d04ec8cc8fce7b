// Writing a file so that readers never see half of it: the bytes go to a temporary name in the
// same folder, which is then renamed over the target. Every output of svgmotion is written so.
//
// The rename would replace whatever sits at the path, so the target is checked first: a path
// that is a device (/dev/full), a FIFO, a socket or a directory is refused and nothing is
// written. A symbolic link is written through: the link is followed to the file it finally
// names, and that file is replaced atomically (the link itself stays a link), as `cp` or a
// shell redirection would write through it; a link to anything but a regular file (or to a name
// that does not exist yet) is refused like the thing it points to.
#pragma once

#include <filesystem>
#include <string_view>

namespace svgm {

// The path an output written to `file` should be renamed onto: `file` itself, or the end of
// its chain of symbolic links. Throws svgm::Error "<file>: not a regular file" when that
// exists and is not a regular file (a link adds " (it links to <target>)").
std::filesystem::path output_target(const std::filesystem::path& file);

// Throws svgm::Error "<file>: not a regular file" (see output_target) or
// "<file>: cannot write: <reason>"; on failure nothing is left behind.
void write_file_atomic(const std::filesystem::path& file, std::string_view bytes);

}  // namespace svgm
