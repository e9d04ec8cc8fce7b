// Room to move (pipeline/canvas_room.h): which drawings fill their canvas, and the document
// with room around it, checked against numbers worked out by hand.
#include <doctest/doctest.h>

#include <string>

#include "error_of.h"
#include "pipeline/canvas_room.h"
#include "procedural/travel_words.h"
#include "scene/backdrop.h"
#include "svgmotion/svg_reader.h"

using namespace svgm;
using svgm::test::error_of;

namespace {

Scene read(const std::string& text) { return read_svg_string(text, "t.svg"); }

// A 100 x 50 canvas; a body from x 5 to 90 (85 % of the width, under kFillsCanvas), 20 tall.
Scene wide_body() {
  return read(R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 50">
    <rect x="5" y="15" width="85" height="20" fill="red"/></svg>)");
}

}  // namespace

TEST_SUITE("pipeline") {

TEST_CASE("canvas room: the figure's span leaves out a backdrop rectangle but not a disc filling the canvas") {
  // A 36-unit canvas: a backdrop rectangle over all of it and a 10-wide square from 13 to 23.
  const Scene boxed = read(R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 36 36">
    <rect width="36" height="36" fill="#ccc"/><rect x="13" y="4" width="10" height="20" fill="red"/></svg>)");
  const FigureSpan s = figure_span(boxed);
  CHECK_FALSE(s.empty);
  CHECK(s.x == doctest::Approx(10.0 / 36));
  CHECK(s.y == doctest::Approx(20.0 / 36));
  // A face: a disc touching all four sides is the figure itself.
  const FigureSpan face = figure_span(read(R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 36 36">
    <circle cx="18" cy="18" r="18" fill="gold"/></svg>)"));
  CHECK(face.x == doctest::Approx(1.0));
  CHECK(face.y == doctest::Approx(1.0));
  // A stroke's half width counts; what hangs off the canvas does not.
  const FigureSpan line = figure_span(read(R"(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="50">
    <path d="M10 25 H 200" stroke="black" stroke-width="4" fill="none"/></svg>)"));
  CHECK(line.x == doctest::Approx(0.92));  // from 8 to the edge at 100
  CHECK(line.y == doctest::Approx(4.0 / 50));
  CHECK(figure_span(read(R"(<svg xmlns="http://www.w3.org/2000/svg" width="10" height="10"/>)")).empty);
}

TEST_CASE("canvas room: a figure across 85 % of its canvas gets room when the prompt sends it across, not when it stays") {
  const Scene wide = wide_body();
  char why[160] = "";
  CHECK(auto_room(wide, "the zebra trots across", why, sizeof why) == kAutoRoom);
  CHECK(std::string(why) == "the prompt sends the figure across and it spans 85 % of its canvas's width");
  CHECK(auto_room(wide, "the lizard crawls to the left", nullptr, 0) == kTurnRoom);  // told a way: it may turn round
  CHECK(auto_room(wide, "the dog walks", nullptr, 0) == kAutoRoom);  // untold: the way it faces
  // Kept where it is, only its limbs or tail named, no gait, or sent up: no room across.
  CHECK(auto_room(wide, "the jogger runs on the spot", nullptr, 0) == 0);
  CHECK(auto_room(wide, "the grasshopper rubs its hind legs together", nullptr, 0) == 0);
  CHECK(auto_room(wide, "the zebra wags its tail", nullptr, 0) == 0);
  CHECK(auto_room(wide, "the ladybird crawls up", nullptr, 0) == 0);
  CHECK(auto_room(wide, "", nullptr, 0) == 0);
  CHECK(auto_room(wide, "the cyclist pedals hard", nullptr, 0) == 0);  // untold, a rider stays: no gait
  CHECK(auto_room(wide, "the cyclist pedals to the left", nullptr, 0) == kTurnRoom);
  // At 60 % of the width it has room enough: kTravelReach of its width each way fits.
  const Scene narrow = read(R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 50">
    <rect x="20" y="15" width="60" height="20" fill="red"/></svg>)");
  CHECK(auto_room(narrow, "the zebra trots to the right", nullptr, 0) == 0);
  // Filling the canvas gets room whatever the prompt says.
  const Scene full = read(R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 50">
    <rect x="2" y="15" width="96" height="20" fill="red"/></svg>)");
  CHECK(auto_room(full, "the zebra wags its tail", nullptr, 0) == kAutoRoom);
}

TEST_CASE("canvas room: a figure told a way gets the turning figure's room, a fifth of its width on each side") {
  // Told a way, a figure drawn facing the other way turns round and its whole trip (twice
  // kTravelReach of its width) lies on the told side: kTurnRoom, more than kAutoRoom, for a
  // gait, a drive or a glide told a way; as before for a figure sent across with no way said,
  // kept on the spot, or with limbs named.
  const Scene wide = wide_body();
  char why[160] = "";
  CHECK(auto_room(wide, "the zebra trots to the right", why, sizeof why) == kTurnRoom);
  CHECK(std::string(why) == "the prompt tells the figure a way to go and it spans 85 % of its canvas's width");
  CHECK(auto_room(wide, "the lorry drives away to the right", nullptr, 0) == kTurnRoom);
  CHECK(auto_room(wide, "the bullet train glides off to the left", nullptr, 0) == kTurnRoom);
  CHECK(auto_room(wide, "the lorry drives", nullptr, 0) == 0);  // no way told, no gait: stays
  CHECK(auto_room(wide, "the dog walks", nullptr, 0) == kAutoRoom);
  CHECK_FALSE(sends_figure_one_way(parse_prompt("the jogger runs to the right on the spot")));  // kept where it is
  CHECK(kTurnRoom > kAutoRoom);
  // A figure as wide as its canvas then has kTurnRoom of its width on each side: its trip there
  // is at least 20 % of its width.
  CHECK(kTurnRoom >= 0.2);
}

TEST_CASE("canvas room: the viewBox grows by the share on each side, width and height by 1 + 2 share, the rest kept") {
  const std::string doc = "<?xml version=\"1.0\"?>\n<!-- mine -->\n<svg xmlns=\"http://www.w3.org/2000/svg\" "
                          "width=\"72px\" height=\"36\" viewBox=\"10 0 72 36\">\n  <path d=\"M10 0h72v36z\"/>\n</svg>";
  const std::string out = give_canvas_room(doc, "t.svg", read(doc), 0.25);
  // (pugixml keeps no whitespace between the nodes outside the root; the fitter's writer does
  // not either.)
  CHECK(out == "<?xml version=\"1.0\"?><!-- mine --><svg xmlns=\"http://www.w3.org/2000/svg\" "
               "width=\"108px\" height=\"54\" viewBox=\"-8 -9 108 54\" data-svgmotion-room=\"0.25\">\n  <path d=\"M10 0h72v36z\"/>\n</svg>");
  // Read back: the canvas is 1.5 times as large and the shape keeps its size and sits in the middle.
  const Scene s = read(out);
  CHECK(s.width == doctest::Approx(108));
  CHECK(s.height == doctest::Approx(54));
  CHECK(s.paths[0].subpaths[0].points[0].x == doctest::Approx(18));
  CHECK(s.paths[0].subpaths[0].points[0].y == doctest::Approx(9));
  CHECK(s.room == doctest::Approx(0.25));
  CHECK(read(doc).room == 0);
}

TEST_CASE("canvas room: a backdrop of the drawing's own canvas is still a backdrop once the drawing has room") {
  // A sky over the whole 128-unit canvas, painted first, and a small figure on it: with 15 %
  // room the sky reaches none of the larger canvas's edges, but all of the drawing's own.
  const std::string doc = R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 128 128">
    <rect x="4" y="4" width="120" height="90" fill="#9cf"/><rect x="50" y="60" width="20" height="40" fill="red"/>
    <rect x="52" y="50" width="10" height="10" fill="red"/><rect x="60" y="50" width="10" height="10" fill="red"/></svg>)";
  const Scene roomy = read(give_canvas_room(doc, "t.svg", read(doc), 0.15));
  REQUIRE(roomy.room == doctest::Approx(0.15));
  const double o = 0.15 * 128;  // the drawing's canvas starts here on the larger one
  CHECK(is_backdrop(roomy, {0}, 4 + o, 4 + o, 124 + o, 94 + o, 0.0));
  CHECK_FALSE(is_backdrop(4 + o, 4 + o, 124 + o, 94 + o, 0.0, roomy.width, roomy.height));  // the larger canvas's edges
  CHECK_FALSE(is_backdrop(roomy, {1}, 50 + o, 50 + o, 70 + o, 100 + o, 0.25));  // the figure
}

TEST_CASE("canvas room: a document without a viewBox gets one from its canvas; a percentage size is left alone") {
  const std::string plain = R"(<svg xmlns="http://www.w3.org/2000/svg" width="40" height="20"><rect width="40" height="20"/></svg>)";
  const std::string out = give_canvas_room(plain, "t.svg", read(plain), 0.1);
  CHECK(out.find("width=\"48\" height=\"24\" viewBox=\"-4 -2 48 24\"") != std::string::npos);
  const std::string pct = R"(<svg xmlns="http://www.w3.org/2000/svg" width="100%" viewBox="0 0 10 10"><rect width="10" height="10"/></svg>)";
  CHECK(give_canvas_room(pct, "t.svg", read(pct), 0.5).find("width=\"100%\" viewBox=\"-5 -5 20 20\"") != std::string::npos);
}

TEST_CASE("canvas room: a bad share or an unreadable viewBox is one line naming the file") {
  const std::string ok = R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10"/>)";
  CHECK(error_of([&] { give_canvas_room(ok, "a.svg", read(ok), 0.6); }) == "a.svg: room must be a share in (0, 0.5]");
  const std::string bad = R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 ten 10"/>)";
  CHECK(error_of([&] { give_canvas_room(bad, "b.svg", Scene{}, 0.1); }) == "b.svg: viewBox \"0 0 ten 10\" is not four numbers");
}

}  // TEST_SUITE
