// What a turning wheel carries (procedural/wheel_riders.h): what turns with it, what rides its rim,
// riders stacked into one, and the symmetry of riders evenly round it, on boxes and points
// made for these tests.
#include <doctest/doctest.h>

#include "procedural/wheel_riders.h"

using namespace svgm;

TEST_SUITE("motion") {

TEST_CASE("a spoke reaching in and a ring about the centre turn with a wheel; a cabin on the rim and a stand do not") {
  const RigBox wheel{40, 30, 160, 150};  // centre (100,90), radius 60
  const std::vector<Vec2> spoke{{100, 40}, {100, 88}};
  CHECK(turns_with_wheel({99, 40, 101, 88}, spoke, wheel));
  const std::vector<Vec2> ring{{37, 90}, {100, 27}, {163, 90}, {100, 153}};  // 63 > 60 but within the pad
  CHECK(turns_with_wheel({37, 27, 163, 153}, ring, wheel));
  const std::vector<Vec2> cabin_body{{93, 31}, {107, 31}, {93, 41}, {107, 41}};  // inside, never nearer than 49
  CHECK_FALSE(turns_with_wheel({93, 31, 107, 41}, cabin_body, wheel));
  const std::vector<Vec2> leg{{97, 90}, {56, 190}};
  CHECK_FALSE(turns_with_wheel({56, 90, 97, 190}, leg, wheel));

  CHECK(rides_wheel({93, 31, 107, 41}, wheel));
  CHECK(rides_wheel({154, 86, 166, 93}, wheel));
  CHECK_FALSE(rides_wheel({94, 84, 106, 96}, wheel));   // the hub: at the centre
  CHECK_FALSE(rides_wheel({50, 90, 150, 190}, wheel));  // the stand: large
}

TEST_CASE("a cabin's roof and its body stack into one rider; riders side by side do not") {
  const RigBox roof{94, 24, 106, 31}, body{93, 31, 107, 41}, beside{108, 24, 120, 31};
  CHECK(riders_stack(roof, body));
  CHECK_FALSE(riders_stack(roof, beside));
  const auto stacks = rider_stacks({roof, beside, body});
  CHECK(stacks[0].y1 == 41.0);
  CHECK(stacks[2].y0 == 24.0);
  CHECK(stacks[1].y1 == 31.0);
}

TEST_CASE("riders evenly round a wheel give its symmetry, stacked pieces counted once; uneven ones none") {
  const RigBox wheel{40, 30, 160, 150};
  const std::vector<RigBox> four{{94, 24, 106, 31}, {93, 31, 107, 41}, {154, 86, 166, 93}, {94, 146, 106, 153}, {34, 86, 46, 93}};
  CHECK(rider_symmetry(rider_stacks(four), wheel) == 4);
  const std::vector<RigBox> uneven{{94, 24, 106, 31}, {154, 86, 166, 93}, {145, 110, 157, 117}};
  CHECK(rider_symmetry(rider_stacks(uneven), wheel) == 0);
  const std::vector<RigBox> two{{94, 24, 106, 31}, {94, 146, 106, 153}};
  CHECK(rider_symmetry(rider_stacks(two), wheel) == 0);  // fewer than kMinSymmetricRiders
}

TEST_CASE("riders come in sets: a piece drawn once among cabins does not ride; a lone cabin or two do") {
  const std::vector<RigBox> many{{94, 24, 106, 31}, {154, 86, 166, 93}, {94, 146, 106, 153}, {34, 86, 46, 93}, {80, 147, 120, 152}};
  CHECK(in_rider_sets(many) == std::vector<char>{1, 1, 1, 1, 0});
  const std::vector<RigBox> two{{94, 24, 106, 31}, {80, 147, 120, 152}};
  CHECK(in_rider_sets(two) == std::vector<char>{1, 1});
}

}  // TEST_SUITE
