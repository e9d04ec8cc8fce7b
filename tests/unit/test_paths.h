// Where the unit tests find their data and the CLI they start as a child.
//
// The paths are compiled into test_paths.cpp alone (tests/CMakeLists.txt gives that one file the
// definitions), not into every test object: an absolute path on every object's command line made
// each checkout's test build (a worktree, a fresh clone) miss the shared compiler cache, about 20
// minutes on two cores, where now one object differs.
#pragma once

#include <string>

namespace svgm::test {

// tests/data/ joined with `relative` ("svg/shapes.svg").
std::string data_path(const std::string& relative);

// The svgmotion executable this build made.
std::string cli_exe();

}  // namespace svgm::test
