// The paths of test_paths.h, from the definitions tests/CMakeLists.txt gives this file alone.
#include "test_paths.h"

namespace svgm::test {

std::string data_path(const std::string& relative) { return std::string(SVGM_TEST_DATA) + "/" + relative; }

std::string cli_exe() { return SVGM_CLI_EXE; }

}  // namespace svgm::test
