// Run directories: which folder a run (or a fit) may write into, one process at a time, and
// the clean-up of what a killed one left behind.
//
// A folder is a run directory when it holds .svgmotion/ (made by the first run or fit into
// it). svgmotion deletes or replaces only its own names there: the stages' outputs (the video
// stage replaces candidates/ whole), the fit's and the page's files, and its own temporary
// files (svgmotion/atomic_file.h: ".NAME.svgm-tmp-PID", left behind only by a kill). So a
// folder that is neither empty nor a run directory is refused, unless the user forces it; and
// even then an entry there with one of the names the run writes is refused, naming it, since
// replacing it would lose the user's file. Anything else in the folder is never touched.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace svgm {

// The names a `run` writes in its run directory, and the ones a `fit -o DIR` writes.
const std::vector<std::string>& run_output_names();
const std::vector<std::string>& fit_output_names();

// Makes `dir` a run directory (creating it and its .svgmotion/) or checks that it is one.
// Throws svgm::Error with one line for: a path that is not a folder, a folder that cannot be
// written ("DIR: cannot write (read-only file system)"), a non-empty folder that is not a run
// directory ("DIR: not a svgmotion run directory and not empty (N entries); choose an empty
// folder or pass --force"), and, with `force`, an entry of that folder named in `ours`.
void claim_run_directory(const std::filesystem::path& dir, bool force, const std::vector<std::string>& ours);

// One process per run directory at a time: claims `dir` (above), then holds an advisory lock
// on .svgmotion/lock until destroyed (the kernel releases it however the process ends); a
// second holder is refused in one line naming the first one's pid. Holding it, removes the
// temporary files of processes that no longer run, in `dir` and `dir`/candidates.
class RunLock {
 public:
  RunLock(const std::filesystem::path& dir, bool force, const std::vector<std::string>& ours);
  ~RunLock();
  RunLock(const RunLock&) = delete;
  RunLock& operator=(const RunLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace svgm
