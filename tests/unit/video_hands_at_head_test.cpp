// Hands drawn at the face (procedural/hands_at_head.h) on boxes made for these tests: which of a
// head part's paths an arm holds.
#include <doctest/doctest.h>

#include "procedural/hands_at_head.h"

using namespace svgm;

TEST_SUITE("motion") {

TEST_CASE("a glove beside the face on an arm is the arm's; the face, what lies on it and what no arm reaches stay") {
  const RigBox face{80, 20, 120, 62}, eye{90, 30, 96, 36}, glove{55, 40, 82, 68}, lacing{58, 44, 64, 50},
      ear{120, 35, 128, 48}, cheek{78, 45, 86, 52};
  const std::vector<RigBox> boxes{face, eye, glove, lacing, ear, cheek};
  const std::vector<double> areas{1680, 36, 756, 36, 104, 56};
  const RigBox arm{60, 62, 90, 105}, other_arm{130, 70, 160, 110};
  const std::vector<int> held = held_at_head(boxes, areas, {other_arm, arm});
  CHECK(held[0] == -1);  // the face: the largest path
  CHECK(held[1] == -1);  // the eye: on the face
  CHECK(held[2] == 1);   // the glove: beside the face, on the arm more than on the face
  CHECK(held[3] == 1);   // its lacing: beside the face, on the glove
  CHECK(held[4] == -1);  // an ear beside the face that no arm reaches
  CHECK(held[5] == -1);  // a cheek with its middle on the face, though inside the glove's box
  // No arms, or a head of one path: nothing is held.
  CHECK(held_at_head(boxes, areas, {}) == std::vector<int>(6, -1));
  CHECK(held_at_head({face}, {1680}, {arm}) == std::vector<int>{-1});
}

TEST_CASE("a path beside the face that lies more on the face than on the arm stays the head's") {
  // A hair tuft beside the face reaching over its edge, the arm's box grazing it.
  const RigBox face{80, 20, 120, 62}, tuft{60, 10, 84, 30}, arm{60, 29, 90, 90};
  const std::vector<int> held = held_at_head({face, tuft}, {1680, 200}, {arm});
  CHECK(held[1] == -1);
}

}  // TEST_SUITE
