// The names of svgmotion's temporary files: every output is written under one and renamed
// (svgmotion/atomic_file.h, preview videos, copied candidates), and only a kill leaves one.
//
// ".NAME.svgm-tmp-PID": hidden, and of a form no user's file has, so that cleaning up what a
// killed run left (run/run_directory.h) can never take a user's file (the old
// "NAME.part<pid>" pattern once took "thesis.part1.pdf").
#pragma once

#include <filesystem>
#include <string_view>

namespace svgm {

// The temporary name a write to `target` goes through: ".NAME.svgm-tmp-PID" beside it, then
// `suffix` (FFmpeg picks a container by the extension: ".mp4").
std::filesystem::path temporary_path(const std::filesystem::path& target, std::string_view suffix = {});
// The process id in a name of temporary_path()'s form (".mp4" or ".webm" after it allowed);
// -1 for any other name.
long temporary_name_pid(std::string_view filename);

}  // namespace svgm
