// The clock of an animated SVG (export/smil_clock.h): its pass, and the frame rate svgmotion's
// writer states on the root (data-svgmotion-fps), which `render` makes a clip at by default
// (a 24 fps fit's clip was resampled to 30 fps before).
#include <doctest/doctest.h>

#include <string>

#include "export/smil_clock.h"
#include "svgmotion/error.h"

using namespace svgm;

namespace {

const std::string kAnimated =
    "<?xml version=\"1.0\"?>\n<!-- a comment with <svg> in it -->\n"
    "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"8\" height=\"8\" data-x='a>b'>"
    "<rect width=\"4\" height=\"4\"><animate attributeName=\"x\" values=\"0;4\" dur=\"2s\" "
    "repeatCount=\"indefinite\"/></rect></svg>\n";

}  // namespace

TEST_SUITE("export") {
TEST_CASE("smil clock: the writer's frame rate on the root is read back; none reads as 0") {
  const SmilClock plain = smil_clock(kAnimated, "a.svg");
  CHECK(plain.animations == 1);
  CHECK(plain.duration_s == doctest::Approx(2));
  CHECK(plain.fps == 0);

  const std::string stamped = with_frame_rate(kAnimated, "a.svg", 24);
  // The attribute goes at the end of the root's start tag (past a quoted '>'); every other byte stays.
  CHECK(stamped == "<?xml version=\"1.0\"?>\n<!-- a comment with <svg> in it -->\n"
                   "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"8\" height=\"8\" data-x='a>b' "
                   "data-svgmotion-fps=\"24\"><rect width=\"4\" height=\"4\"><animate attributeName=\"x\" "
                   "values=\"0;4\" dur=\"2s\" repeatCount=\"indefinite\"/></rect></svg>\n");
  CHECK(smil_clock(stamped, "a.svg").fps == 24);
  // Stamping again replaces the rate rather than adding a second attribute (not well-formed).
  const std::string again = with_frame_rate(stamped, "a.svg", 12.5);
  CHECK(again.find("data-svgmotion-fps=\"24\"") == std::string::npos);
  CHECK(smil_clock(again, "a.svg").fps == 12.5);
  CHECK(again.size() == stamped.size() + 2);
  // Written by hand (single quotes, a new line before it, spaces round '='), or only inside
  // another attribute's value: replaced in place, or added once; the result parses.
  const std::string hand = "<svg xmlns=\"http://www.w3.org/2000/svg\" data-note=\" data-svgmotion-fps='3'\"\n"
                           "  data-svgmotion-fps = '30'><rect width=\"4\" height=\"4\"/></svg>";
  const std::string restamped = with_frame_rate(hand, "h.svg", 24);
  CHECK(restamped == "<svg xmlns=\"http://www.w3.org/2000/svg\" data-note=\" data-svgmotion-fps='3'\"\n"
                     "  data-svgmotion-fps = '24'><rect width=\"4\" height=\"4\"/></svg>");
  CHECK(smil_clock(restamped, "h.svg").fps == 24);
  const std::string quoted_only = "<svg xmlns=\"http://www.w3.org/2000/svg\" data-note=\" data-svgmotion-fps='3'\"/>";
  CHECK(with_frame_rate(quoted_only, "q.svg", 24) ==
        "<svg xmlns=\"http://www.w3.org/2000/svg\" data-note=\" data-svgmotion-fps='3'\" data-svgmotion-fps=\"24\"/>");
  // A rate no clip could have is ignored (below 1 fps a GIF's delays overflow).
  std::string slow = stamped;
  slow.replace(slow.find("\"24\""), 4, "\"0.5\"");
  CHECK(smil_clock(slow, "a.svg").fps == 0);
  std::string absurd = stamped;
  absurd.replace(absurd.find("\"24\""), 4, "\"1e9\"");
  CHECK(smil_clock(absurd, "a.svg").fps == 0);
  CHECK_THROWS_WITH_AS(with_frame_rate("<svg", "b.svg", 24), doctest::Contains("b.svg: "), Error);
}
}  // TEST_SUITE
