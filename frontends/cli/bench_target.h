// `svgmotion bench target`: the target stage's speed on a real video (see bench_target.cpp).
#pragma once

#include <string>
#include <vector>

namespace svgm::cli {

int bench_target(const std::vector<std::string>& argv);

}  // namespace svgm::cli
