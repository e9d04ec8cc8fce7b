// pack_white_runs / unpack_white_runs (fit/target/white_runs.h): a target's rgba held as runs of
// exact white while the refinement does not read it. Unpacking must give back the same bits
// (floats next to 1, white colour with another alpha, -0 and NaN included), and the packed
// form must hold the non-white pixels alone, counted by hand.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "fit/target/white_runs.h"
#include "svgmotion/error.h"

using namespace svgm;

TEST_SUITE("fit") {
  TEST_CASE("white runs: the same bits back, the white pixels as counts") {
    const float below = std::nextafter(1.f, 0.f), above = std::nextafter(1.f, 2.f);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    // Pixels: other, white, white, other, other, white, other (x3 kinds of near-white).
    const float px[7][4] = {{below, 1, 1, 1}, {1, 1, 1, 1}, {1, 1, 1, 1}, {1, 1, 1, 0.5f},
                            {-0.f, nan, 0.25f, 1}, {1, 1, 1, 1}, {1, above, 1, 1}};
    std::vector<float> rgba;
    for (const auto& p : px) rgba.insert(rgba.end(), p, p + 4);
    const std::vector<float> original = rgba;
    WhiteRuns packed = pack_white_runs(rgba);
    CHECK(rgba.empty());
    CHECK(packed.pixels == 7);
    // A first white run of 0, then other 1, white 2, other 2, white 1, other 1.
    CHECK(packed.runs == std::vector<uint32_t>{0, 1, 2, 2, 1, 1});
    CHECK(packed.others.size() == 4 * 4);
    CHECK(packed.bytes() == 6 * 4 + 16 * 4);
    const std::vector<float> back = unpack_white_runs(packed);
    REQUIRE(back.size() == original.size());
    CHECK(std::memcmp(back.data(), original.data(), back.size() * sizeof(float)) == 0);
    CHECK(std::signbit(back[16]));  // -0 stays -0
    CHECK(packed.pixels == 0);
  }

  TEST_CASE("white runs: any range of pixels unpacked alone is the same bits as its part of the whole") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    // White, other x2, white x3, other, white x2 (10 pixels; starting and ending on white).
    std::vector<float> rgba(4 * 10, 1.f);
    const float others[3][4] = {{0.5f, 0.25f, 1, 1}, {-0.f, nan, 0.75f, 1}, {1, 1, 1, 0.5f}};
    std::copy_n(others[0], 4, &rgba[4 * 1]);
    std::copy_n(others[1], 4, &rgba[4 * 2]);
    std::copy_n(others[2], 4, &rgba[4 * 6]);
    const std::vector<float> original = rgba;
    const WhiteRuns packed = pack_white_runs(rgba);
    CHECK(packed.runs == std::vector<uint32_t>{1, 2, 3, 1, 3});
    for (size_t first = 0; first <= 10; ++first)
      for (size_t count = 0; first + count <= 10; ++count) {
        std::vector<float> out(4 * count, 0.f);
        unpack_white_runs_range(packed, first, count, out.data());
        CAPTURE(first);
        CAPTURE(count);
        CHECK(std::memcmp(out.data(), &original[4 * first], out.size() * sizeof(float)) == 0);
      }
    CHECK(packed.pixels == 10);  // untouched
    float out[8];
    CHECK_THROWS_WITH_AS(unpack_white_runs_range(packed, 9, 2, out), "internal: unpacking pixels past the white runs' frames",
                         Error);
  }

  TEST_CASE("white runs: all white, empty, and a size that is not RGBA") {
    std::vector<float> white(4 * 1000, 1.f);
    WhiteRuns packed = pack_white_runs(white);
    CHECK(packed.runs == std::vector<uint32_t>{1000});
    CHECK(packed.others.empty());
    CHECK(unpack_white_runs(packed) == std::vector<float>(4 * 1000, 1.f));
    std::vector<float> none;
    WhiteRuns empty = pack_white_runs(none);
    CHECK(unpack_white_runs(empty).empty());
    std::vector<float> odd(6, 1.f);
    CHECK_THROWS_WITH_AS(pack_white_runs(odd), "internal: packing 6 floats as RGBA", Error);
    CHECK(odd.size() == 6);  // left as it was
  }

  TEST_CASE("white runs: frames appended one by one pack as the whole does, runs going on across frames") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    // Three frames of 4 pixels: the first ends on other, the second is other then white, the
    // third all white (its run goes on from the second's), then other at the very end.
    // o: other pixels of three kinds.
    const float o1[4] = {0.5f, 0.25f, 1, 1}, o2[4] = {-0.f, nan, 0.75f, 1}, o3[4] = {1, 1, 1, 0.5f};
    const float w[4] = {1, 1, 1, 1};
    const float* order[13] = {w, w, o1, o2, o3, w, w, w, w, w, w, w, o1};
    std::vector<float> rgba;
    for (const float* p : order) rgba.insert(rgba.end(), p, p + 4);
    std::vector<float> whole_copy = rgba;
    const WhiteRuns whole = pack_white_runs(whole_copy);
    CHECK(whole.runs == std::vector<uint32_t>{2, 3, 7, 1});
    for (const size_t frame : {size_t{1}, size_t{2}, size_t{4}, size_t{13}}) {
      CAPTURE(frame);
      WhiteRuns appended;
      for (size_t first = 0; first < 13; first += frame) append_white_runs(appended, &rgba[4 * first], std::min(frame, 13 - first));
      append_white_runs(appended, rgba.data(), 0);  // nothing: changes nothing
      CHECK(appended.pixels == whole.pixels);
      CHECK(appended.runs == whole.runs);
      REQUIRE(appended.others.size() == whole.others.size());
      CHECK(std::memcmp(appended.others.data(), whole.others.data(), whole.others.size() * sizeof(float)) == 0);
    }
    WhiteRuns none;
    append_white_runs(none, nullptr, 0);
    std::vector<float> empty;
    CHECK(none.runs == pack_white_runs(empty).runs);  // {0}: one empty white run
  }
}
