// The forward render's layer compositor (raster/layer_compositor.h) on small SVGs of our own
// (tests/data/paint) whose pixels can be computed by hand: gradient colours, spread methods,
// a radial centre, group opacity as one blend, a clip's coverage, a luminance mask; and its
// area coverage against the reference rasteriser.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "raster/area_coverage.h"
#include "raster/layer_compositor.h"
#include "raster/raster_plan.h"
#include "raster/raster_ref.h"
#include "svgmotion/render_size.h"
#include "svgmotion/svg_reader.h"
#include "test_paths.h"

using namespace svgm;

namespace {

struct Rendered {
  int w = 0, h = 0;
  std::vector<float> px;  // premultiplied RGBA over transparent
  const float* at(int x, int y) const { return px.data() + 4 * (static_cast<size_t>(y) * w + x); }
};

Rendered render_file(const std::string& name) {
  const Scene s = read_svg_file(svgm::test::data_path("paint/" + name));
  const RenderSize size = render_size(s, 0);
  return {size.width, size.height, composite_layers(s, size)};
}

// Colour tolerance: float compositing, far below one 8-bit level.
constexpr double kEps = 1e-5;

}  // namespace

TEST_SUITE("raster") {

TEST_CASE("a two-stop linear gradient has the interpolated colour at each pixel centre") {
  const Rendered r = render_file("linear_two_stop.svg");
  REQUIRE(r.w == 10);
  for (int x = 0; x < 10; ++x) {
    const double t = (x + 0.5) / 10;  // red (t = 0) to blue (t = 1)
    CHECK(r.at(x, 1)[0] == doctest::Approx(1 - t).epsilon(kEps));
    CHECK(r.at(x, 1)[1] == doctest::Approx(0).epsilon(kEps));
    CHECK(r.at(x, 1)[2] == doctest::Approx(t).epsilon(kEps));
    CHECK(r.at(x, 1)[3] == doctest::Approx(1).epsilon(kEps));
  }
}

TEST_CASE("pad, reflect and repeat continue a gradient beyond its vector") {
  // Vector 0..4 px: pixel x has t = (x + 0.5) / 4; the colour is grey t after the spread.
  const Rendered r = render_file("spread_methods.svg");
  struct Want {
    int x;
    double pad, reflect, repeat;
  };
  for (const Want& w : {Want{1, 0.375, 0.375, 0.375}, Want{5, 1.0, 0.625, 0.375},
                        Want{9, 1.0, 0.375, 0.375}, Want{6, 1.0, 0.375, 0.625}}) {
    CAPTURE(w.x);
    CHECK(r.at(w.x, 0)[0] == doctest::Approx(w.pad).epsilon(kEps));
    CHECK(r.at(w.x, 1)[0] == doctest::Approx(w.reflect).epsilon(kEps));
    CHECK(r.at(w.x, 2)[0] == doctest::Approx(w.repeat).epsilon(kEps));
  }
}

TEST_CASE("a radial gradient is its first stop at the centre and pads beyond the radius") {
  const Rendered r = render_file("radial_centre.svg");
  CHECK(r.at(5, 5)[0] == doctest::Approx(1).epsilon(kEps));            // distance 0
  CHECK(r.at(5, 8)[1] == doctest::Approx(1 - 3 / 5.5).epsilon(kEps));  // distance 3 of 5.5
  CHECK(r.at(0, 0)[2] == doctest::Approx(0).epsilon(kEps));            // beyond: last stop
  CHECK(r.at(0, 0)[3] == doctest::Approx(1).epsilon(kEps));
}

TEST_CASE("group opacity composites the group once: overlapping shapes blend one time") {
  const Rendered r = render_file("group_opacity.svg");
  // Red only, overlap (blue covers red inside the layer), blue only: each at 50 %.
  const float* red = r.at(1, 0);
  const float* overlap = r.at(5, 0);
  const float* blue = r.at(8, 0);
  CHECK(red[0] == doctest::Approx(0.5).epsilon(kEps));
  CHECK(red[3] == doctest::Approx(0.5).epsilon(kEps));
  CHECK(overlap[0] == doctest::Approx(0).epsilon(kEps));  // two blends would leave 0.25 red
  CHECK(overlap[2] == doctest::Approx(0.5).epsilon(kEps));
  CHECK(overlap[3] == doctest::Approx(0.5).epsilon(kEps));  // two blends: 0.75
  CHECK(blue[2] == doctest::Approx(0.5).epsilon(kEps));
}

TEST_CASE("a rectangle clipped by a circle covers the circle's area") {
  const Rendered r = render_file("clip_circle.svg");
  auto alpha_sum = [](const Rendered& img) {
    double sum = 0;
    for (int y = 0; y < img.h; ++y)
      for (int x = 0; x < img.w; ++x) sum += img.at(x, y)[3];
    return sum;
  };
  // The same circle filled: the clip's coverage is exactly its coverage (same flattening).
  const Scene circle = read_svg_string(
      "<svg xmlns='http://www.w3.org/2000/svg' width='10' height='10'><circle cx='5' cy='5' r='4'/></svg>", "c.svg");
  const RenderSize size = render_size(circle, 0);
  const Rendered filled{size.width, size.height, composite_layers(circle, size)};
  CHECK(alpha_sum(r) == doctest::Approx(alpha_sum(filled)).epsilon(1e-6));
  // 16 pi = 50.27 px²; chords within 0.1 px of the arc (the plan's tolerance) cut off at most
  // 2/3 x 0.1 x the 25 px circumference = 1.7 px².
  CHECK(alpha_sum(r) < 16 * M_PI);
  CHECK(alpha_sum(r) > 16 * M_PI - 1.7);
  CHECK(r.at(5, 5)[3] == doctest::Approx(1).epsilon(kEps));
  CHECK(r.at(0, 0)[3] == doctest::Approx(0).epsilon(kEps));
}

TEST_CASE("a luminance mask gives alpha = luminance of its content") {
  const Rendered r = render_file("luminance_mask.svg");
  CHECK(r.at(0, 0)[3] == doctest::Approx(1).epsilon(kEps));  // white: 0.2125 + 0.7154 + 0.0721
  CHECK(r.at(3, 1)[3] == doctest::Approx(128.0 / 255).epsilon(kEps));
  CHECK(r.at(3, 1)[0] == doctest::Approx(0).epsilon(kEps));  // black content stays black
}

TEST_CASE("area coverage by accumulation equals the reference rasteriser's winding integrals") {
  // Even-odd star, a partly off-canvas ellipse and a stroke with round joins.
  const Scene s = read_svg_string(
      "<svg xmlns='http://www.w3.org/2000/svg' width='23' height='17'>"
      "<path d='M11 1 L18 16 L2 6 L21 6 L4 16 Z' fill-rule='evenodd'/>"
      "<ellipse cx='-2' cy='9' rx='8.3' ry='5.1'/>"
      "<path d='M3 3 L12 9 L20 2' fill='none' stroke='black' stroke-width='2.5' stroke-linejoin='round'/>"
      "</svg>",
      "cov.svg");
  const RasterPlan plan = plan_raster(s, Affine{}, 23, 17);
  const std::vector<double> cp(plan.rest_cp.begin(), plan.rest_cp.end());
  std::vector<double> pts = ref::flatten(plan, cp);
  ref::stroke(plan, pts);
  REQUIRE(plan.draws.size() == 3);
  for (int d = 0; d < 3; ++d) {
    const std::vector<float> fast = draw_coverage(plan, pts, d);
    const std::vector<double> slow = ref::winding_integrals(plan, pts, d);
    double worst = 0;
    for (size_t i = 0; i < fast.size(); ++i)
      worst = std::max(worst, std::fabs(fast[i] - ref::fill_rule_coverage(slow[i], plan.draws[d].rule)));
    CAPTURE(d);
    CHECK(worst < 1e-6);
  }
}

}  // TEST_SUITE
