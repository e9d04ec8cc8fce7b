// distance_field_from_mask / fill_distance_fields (fit/target/distance_field.h): a target's
// distance field made again from its mask, as the refinement does once its fitter needs it.
// The distances are checked by hand on a small mask; equality with the load's own field, bit
// for bit, is checked on real loads in fit_load_compact_test.cpp.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "fit/target/distance_field.h"
#include "svgmotion/error.h"

using namespace svgm;

TEST_SUITE("fit") {
  TEST_CASE("distance field from a mask: 0 on it, the Euclidean distance to it elsewhere, w + h when empty") {
    constexpr int W = 5, H = 3;
    std::vector<uint8_t> mask(W * H, 0);
    mask[1 * W + 1] = 1;  // one pixel, at (1, 1)
    std::vector<float> sdf(W * H, -1.f);
    distance_field_from_mask(mask.data(), W, H, sdf.data());
    auto at = [&](int x, int y) { return sdf[static_cast<size_t>(y) * W + x]; };
    CHECK(at(1, 1) == 0.f);
    CHECK(at(0, 1) == doctest::Approx(1).epsilon(1e-5));
    CHECK(at(2, 1) == doctest::Approx(1).epsilon(1e-5));
    CHECK(at(0, 0) == doctest::Approx(std::sqrt(2.0)).epsilon(1e-5));
    CHECK(at(3, 1) == doctest::Approx(2).epsilon(1e-5));
    CHECK(at(4, 1) == doctest::Approx(3).epsilon(1e-5));
    CHECK(at(4, 0) == doctest::Approx(std::sqrt(10.0)).epsilon(1e-5));
    CHECK(at(4, 2) == doctest::Approx(std::sqrt(10.0)).epsilon(1e-5));

    std::vector<uint8_t> none(W * H, 0);
    distance_field_from_mask(none.data(), W, H, sdf.data());
    for (float d : sdf) CHECK(d == 8.f);  // w + h: farther than any pixel of the frame
  }

  TEST_CASE("fill_distance_fields: every keyframe's field from its mask, and a mask of the wrong size refused") {
    TargetFrames t;
    t.width = 3;
    t.height = 2;
    t.keyframes = 2;
    t.mask = {1, 0, 0, 0, 0, 0,   // keyframe 0: the top left pixel
              0, 0, 0, 0, 0, 0};  // keyframe 1: empty
    fill_distance_fields(t);
    REQUIRE(t.sdf.size() == 12);
    CHECK(t.sdf[0] == 0.f);
    CHECK(t.sdf[2] == doctest::Approx(2).epsilon(1e-5));
    CHECK(t.sdf[5] == doctest::Approx(std::sqrt(5.0)).epsilon(1e-5));
    for (size_t i = 6; i < 12; ++i) CHECK(t.sdf[i] == 5.f);
    t.mask.pop_back();
    CHECK_THROWS_WITH_AS(fill_distance_fields(t), "internal: a distance field without its mask", Error);
  }
}
