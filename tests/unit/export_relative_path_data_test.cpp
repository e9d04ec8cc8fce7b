// The compact export's relative path data (relative_path_data.h): read back by the SVG parser
// it gives exactly the absolute points rounded to the written decimals, over subpaths long
// enough for summed relative numbers to drift, with numbers glued where the grammar allows.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "export/relative_path_data.h"
#include "svg/path_data.h"

using namespace svgm;

TEST_SUITE("export") {
TEST_CASE("relative path data reads back as the rounded absolute points") {
  Path path;
  std::vector<double> cp;
  // Two subpaths (one closed) of 40 cubics, coordinates with every sign and size of fraction.
  for (int s = 0; s < 2; ++s) {
    Subpath sp;
    sp.closed = s == 0;
    for (int i = 0; i <= 120; ++i) {
      Vec2 q{100 * std::sin(0.37 * i + s) + 0.0041 * i, 80 * std::cos(0.23 * i) - 0.5 + 0.07 * s};
      if (sp.closed && i == 120) q = sp.points[0];  // ends where it starts: no closing line read back
      sp.points.push_back(q);
      cp.insert(cp.end(), {q.x, q.y});
    }
    path.subpaths.push_back(sp);
  }
  for (int decimals : {0, 1, 2, 3}) {
    const std::string d = relative_path_data(path, cp.data(), Affine{}, decimals);
    std::vector<Subpath> back;
    const svg::PathDataResult r = svg::parse_path_data(d, back);
    REQUIRE(r.ok);
    REQUIRE(back.size() == 2);
    const double f = std::pow(10.0, decimals);
    double worst = 0;
    for (size_t s = 0; s < 2; ++s) {
      REQUIRE(back[s].points.size() == path.subpaths[s].points.size());
      CHECK(back[s].closed == path.subpaths[s].closed);
      for (size_t i = 0; i < back[s].points.size(); ++i) {
        const Vec2 q = path.subpaths[s].points[i];
        worst = std::max({worst, std::fabs(back[s].points[i].x - std::round(q.x * f) / f),
                          std::fabs(back[s].points[i].y - std::round(q.y * f) / f)});
      }
    }
    CHECK(worst < 1e-9);
  }
  // The tight spelling: one "c" per subpath, no leading zero, no space before a minus sign.
  Path small;
  small.subpaths.push_back({{{1, 1}, {1.5, 0.5}, {1.25, 1.75}, {1, 1}}, false});
  const std::vector<double> scp{1, 1, 1.5, 0.5, 1.25, 1.75, 1, 1};
  CHECK(relative_path_data(small, scp.data(), Affine{}, 2) == "M1 1c.5-.5.25.75 0 0");
}
}  // TEST_SUITE
