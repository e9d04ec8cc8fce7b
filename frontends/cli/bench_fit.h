// `svgmotion bench fit`: the fitter's speed on a real target (see bench_fit.cpp).
#pragma once

#include <string>
#include <vector>

namespace svgm::cli {

int bench_fit(const std::vector<std::string>& argv);

}  // namespace svgm::cli
