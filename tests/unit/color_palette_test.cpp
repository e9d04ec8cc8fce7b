// distinct_palette / min_distance: table sizes, distinct colours away from white, quality
// against published maximin packings of points in a cube, determinism, the live path (N > 256).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>
#include <tuple>

#include "color/palette.h"
#include "color/palette_optimiser.h"

using namespace svgm;

namespace {

// Best known maximin distance of N+1 points in the unit cube (N colours plus white), from
// H. Pfoertner's table of best packings of n equal spheres in a cube (2005; radius r in
// [-1,1]^3, distance r / (1 - r)), which includes Gensane's 2004 packings (Electron. J.
// Combin. 11 #R33), and D. W. Cantrell's 2012 improvements (cube side L for unit spheres,
// distance 2 / (L - 2)). Small exact values: sqrt(3), sqrt(2), sqrt(2), sqrt(5)/2, 3 sqrt(2)/4,
// 1.00109 (Schaer's 1 is not optimal for 7 points), 1, sqrt(3)/2.
struct Reference {
  int n;
  double distance;
};
constexpr Reference kReference[] = {
    {1, 1.732051},  // 2 points
    {2, 1.414213},  // 3 points
    {3, 1.414213},  // 4 points
    {4, 1.118034},  // 5 points
    {5, 1.060660},  // 6 points
    {6, 1.001090},  // 7 points
    {7, 1.000000},  // 8 points
    {8, 0.866025},  // 9 points
    {9, 0.750000},  // 10 points
    {10, 0.710116},  // 11 points
    {11, 0.707107},  // 12 points
    {12, 0.707107},  // 13 points
    {13, 0.707107},  // 14 points
    {14, 0.625000},  // 15 points
    {15, 0.606667},  // 16 points
    {16, 0.606092},  // 17 points
    {17, 0.600925},  // 18 points
    {18, 0.578209},  // 19 points
    {19, 0.554761},  // 20 points
    {20, 0.549038},  // 21 points
    {21, 0.530330},  // 22 points
    {22, 0.523539},  // 23 points
    {23, 0.517637},  // 24 points
    {24, 0.505134},  // 25 points
    {25, 0.501074},  // 26 points
    {26, 0.500000},  // 27 points
    {27, 0.471415},  // 28 points
    {28, 0.471404},  // 29 points
    {29, 0.471404},  // 30 points
    {30, 0.471404},  // 31 points
    {31, 0.471404},  // 32 points
    {32, 0.447619},  // 33 points
    {33, 0.437264},  // 34 points
    {34, 0.435414},  // 35 points
    {35, 0.425755},  // 36 points
    {36, 0.424751},  // 37 points
    {37, 0.424659},  // 38 points
    {38, 0.418912},  // 39 points
    {39, 0.416667},  // 40 points
    {40, 0.407806},  // 41 points
    {41, 0.400728},  // 42 points
    {42, 0.395290},  // 43 points
    {43, 0.392216},  // 44 points
    {44, 0.391331},  // 45 points
    {45, 0.389841},  // 46 points
    {46, 0.388730},  // 47 points, Cantrell 2012
    {47, 0.388730},  // 48 points
    {48, 0.375239},  // 49 points
    {49, 0.373452},  // 50 points
    {50, 0.369887},  // 51 points
    {51, 0.365448},  // 52 points
    {52, 0.363253},  // 53 points
    {53, 0.357349},  // 54 points
    {54, 0.354772},  // 55 points, Cantrell 2012
    {55, 0.353622},  // 56 points, Cantrell 2012
    {56, 0.353556},  // 57 points, Cantrell 2012
    {57, 0.353553},  // 58 points
    {58, 0.353553},  // 59 points
    {59, 0.353553},  // 60 points
    {60, 0.353553},  // 61 points
};

// The one N where pinning white costs more than 2%: the best 6-point packing (3 sqrt(2)/4) has
// no point at a corner, and with one point pinned at a corner the best found by every one of
// thousands of restarts (several seeds) is 1.036508; N = 5 is held to 2% of that instead.
constexpr double kPinnedSixPoints = 1.036508;

std::set<std::tuple<int, int, int>> as_set(const std::vector<Rgb8>& p) {
  std::set<std::tuple<int, int, int>> s;
  for (const auto& c : p) s.insert({c.r, c.g, c.b});
  return s;
}

}  // namespace

TEST_SUITE("color") {
  TEST_CASE("min_distance counts white only when asked, in unit-cube units") {
    const double inf = std::numeric_limits<double>::infinity();
    CHECK(min_distance({}, false) == inf);
    CHECK(min_distance({}, true) == inf);
    CHECK(min_distance({{0, 0, 0}}, false) == inf);
    CHECK(min_distance({{0, 0, 0}}, true) == doctest::Approx(std::sqrt(3.0)));
    CHECK(min_distance({{0, 0, 0}, {255, 0, 0}}, false) == doctest::Approx(1.0));
    CHECK(min_distance({{0, 0, 0}, {255, 0, 0}}, true) == doctest::Approx(1.0));
    CHECK(min_distance({{250, 255, 255}}, true) == doctest::Approx(5.0 / 255));
  }

  TEST_CASE("the table has N distinct non-white colours for every N up to 256") {
    for (int n = 1; n <= 256; ++n) {
      const auto p = distinct_palette(n);
      REQUIRE(p.size() == static_cast<size_t>(n));
      CHECK(as_set(p).size() == static_cast<size_t>(n));
      CHECK(as_set(p).count({255, 255, 255}) == 0);
      // White is one of the points being kept apart: no colour is closer to it than the
      // palette's own minimum distance, and that minimum stays usefully large.
      const double d = min_distance(p, true);
      CHECK(d <= min_distance(p, false));
      CHECK(d > 0.15);
    }
    CHECK(distinct_palette(0).empty());
    CHECK(distinct_palette(1) == std::vector<Rgb8>{{0, 0, 0}});  // the far corner from white
    CHECK_THROWS_AS(distinct_palette(-1), std::invalid_argument);
    CHECK_THROWS_AS(distinct_palette(kMaxPaletteSize + 1), std::invalid_argument);
  }

  TEST_CASE("8-bit palettes are within 2% of the best known packings for N = 1..60") {
    for (const auto& ref : kReference) {
      CAPTURE(ref.n);
      const double d = min_distance(distinct_palette(ref.n), true);
      CHECK(d >= 0.98 * (ref.n == 5 ? kPinnedSixPoints : ref.distance));
      CHECK(d >= 0.975 * ref.distance);
      CHECK(d <= ref.distance * (1 + 1e-5));  // sanity (the published radii have 7 digits)
    }
  }

  TEST_CASE("the distance falls smoothly with N across the table") {
    double prev = min_distance(distinct_palette(1), true);
    for (int n = 2; n <= 256; ++n) {
      CAPTURE(n);
      const double d = min_distance(distinct_palette(n), true);
      CHECK(d <= prev * 1.01);  // never notably better than with fewer colours
      prev = d;
    }
  }

  TEST_CASE("the optimiser is deterministic for a seed and keeps white pinned") {
    color::PackOptions o;
    o.seed = 42;
    o.work = 3e6;
    const auto a = color::pack_points(40, o), b = color::pack_points(40, o);
    CHECK(a.points == b.points);
    CHECK(a.min_distance == b.min_distance);
    CHECK(a.min_distance == doctest::Approx(color::packing_min_distance(a.points, true)));
    const auto q = color::quantise_packing(a.points);
    CHECK(q == color::quantise_packing(b.points));
    // Rounding to the 1/255 grid costs at most sqrt(3)/255 per pair; the grid search never
    // makes it worse than plain rounding.
    CHECK(min_distance(q, true) >= a.min_distance - std::sqrt(3.0) / 255);
  }

  TEST_CASE("N > 256 runs the live optimiser: deterministic, distinct, well spread") {
    const auto p = distinct_palette(257);
    REQUIRE(p.size() == 257);
    CHECK(as_set(p).size() == 257);
    CHECK(as_set(p).count({255, 255, 255}) == 0);
    const double d256 = min_distance(distinct_palette(256), true);
    CHECK(min_distance(p, true) >= 0.9 * d256);
  }
}
