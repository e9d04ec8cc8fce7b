// The command that made a run, recorded in the run directory, and the exact command that runs
// it again with another candidate video (report.html's "use this one").
//
// `svgmotion run` records its working directory, its binary and its arguments in
// <run>/.svgmotion/command.json. The command for candidate NAME is that one, in that
// directory, without `--from` (nothing needs forcing) and with `stages.ranker.choose=NAME`
// (replacing an earlier choice): the settings stay the run's own, so every stage before the
// ranker is up to date and the chosen video goes through layers, tracker and fitter
// (pipeline/candidate_choice.h).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace svgm {

// Writes <run>/.svgmotion/command.json for `svgmotion run ARGS` (args without "run"), run
// from the current directory by this process's binary, with the run's prompt (shown by the
// page). Throws svgm::Error.
void record_run_command(const std::filesystem::path& run, const std::vector<std::string>& args,
                        const std::string& prompt);

// The shell command (POSIX sh) re-running <run> with candidate `name`; nothing when the run
// recorded no command (made before this was recorded, or not by `svgmotion run`).
std::optional<std::string> choose_command(const std::filesystem::path& run, const std::string& name);

// `word` quoted for sh when it needs quoting: '...' with every ' written as '\''.
std::string shell_quote(const std::string& word);

}  // namespace svgm
