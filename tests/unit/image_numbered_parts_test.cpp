// draw_numbered_parts: the image a vision model reads the parts from. Each part's outline is
// traced in its own colour (part 1 red, part 2 green: the first two of the table), its number is
// drawn in black on a white label at its box's centre, and two parts whose boxes share a centre
// get labels that do not cover each other.
#include <doctest/doctest.h>

#include <array>

#include "image/numbered_parts.h"

using namespace svgm;

namespace {

RgbaImage white(int w, int h) { return RgbaImage{w, h, std::vector<uint8_t>(static_cast<size_t>(w) * h * 4, 255)}; }

std::array<int, 4> at(const RgbaImage& im, int x, int y) {
  const uint8_t* p = &im.rgba[(static_cast<size_t>(y) * im.width + x) * 4];
  return {p[0], p[1], p[2], p[3]};
}

NumberedPart square(int number, double x0, double y0, double x1, double y1) {
  NumberedPart p;
  p.number = number;
  p.outlines = {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}, {x0, y0}}};
  p.box_min = {x0, y0};
  p.box_max = {x1, y1};
  return p;
}

// Dark pixels (the digits) inside [x0, x1) x [y0, y1).
int dark(const RgbaImage& im, int x0, int y0, int x1, int y1) {
  int n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const auto c = at(im, x, y);
      n += c[0] < 80 && c[1] < 80 && c[2] < 80;
    }
  return n;
}

}  // namespace

TEST_SUITE("image") {
  TEST_CASE("draw_numbered_parts: outlines in each part's colour, the number on a white label at the box's centre") {
    RgbaImage im = white(200, 100);
    draw_numbered_parts(im, {square(1, 10, 10, 90, 90), square(2, 110, 10, 190, 90)});
    // The left edges, halfway down: part 1's red, part 2's green (opaque).
    CHECK(at(im, 10, 50) == std::array<int, 4>{230, 25, 75, 255});
    CHECK(at(im, 110, 50) == std::array<int, 4>{60, 180, 75, 255});
    // Digits near each centre, none in the empty corners inside the squares.
    CHECK(dark(im, 40, 40, 60, 60) > 5);
    CHECK(dark(im, 140, 40, 160, 60) > 5);
    CHECK(dark(im, 15, 15, 35, 35) == 0);
    CHECK(dark(im, 115, 65, 135, 85) == 0);
    // The label is white round its digit: the pixel just left of the digits at mid height.
    CHECK(at(im, 45, 50)[0] == 255);
  }

  TEST_CASE("draw_numbered_parts: labels of parts with one centre do not cover each other") {
    RgbaImage im = white(100, 100);
    draw_numbered_parts(im, {square(1, 20, 20, 80, 80), square(2, 30, 30, 70, 70)});
    // Two labels: digits above and below the centre row band, so two separate dark clusters.
    int rows_with_ink = 0, bands = 0;
    bool inside = false;
    for (int y = 0; y < 100; ++y) {
      const bool ink = dark(im, 35, y, 65, y + 1) > 0;
      rows_with_ink += ink;
      bands += ink && !inside;
      inside = ink;
    }
    CHECK(bands == 2);
    CHECK(rows_with_ink > 10);
  }
}
