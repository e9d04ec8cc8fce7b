// Fit groups along a procedural motion (fit/plan/motion_groups.h): a group whose paths the motion
// report partly holds still and partly moves is split, still paths keeping the group and the
// moving ones grouped by rig part; so is one whose moving paths belong to several parts; other
// groups and unknown reports leave the scene as it is.
#include <doctest/doctest.h>

#include "fit/plan/motion_groups.h"
#include "svgmotion/svg_reader.h"

using namespace svgm;

namespace {

const char* kDrawing = R"(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100">
  <g id="wheel_and_stand"><rect id="stand" x="10" y="80" width="80" height="10"/><rect id="spoke" x="45" y="10" width="10" height="60"/><rect id="rim" x="20" y="20" width="60" height="4"/></g>
  <g id="cloud"><rect id="puff" x="0" y="0" width="10" height="10"/></g></svg>)";

nlohmann::json report(double stand, double spoke, double rim) {
  return {{"parts", {{{"name", "stand"}, {"paths", {"stand", "puff"}}}, {{"name", "wheel"}, {"paths", {"rim"}}}, {{"name", "spokes"}, {"paths", {"spoke"}}}}},
          {"paths", {{{"id", "stand"}, {"max_travel", stand}}, {{"id", "spoke"}, {"max_travel", spoke}}, {{"id", "rim"}, {"max_travel", rim}}, {{"id", "puff"}, {"max_travel", 0.0}}}}};
}

}  // namespace

TEST_SUITE("fit") {

TEST_CASE("a group the motion moves apart is split: its still paths keep it, each moving part gets a group") {
  const Scene s = read_svg_string(kDrawing, "wheel.svg");
  REQUIRE(s.groups.size() == 2);
  std::vector<std::string> notes;
  const Scene out = split_groups_by_motion(s, report(0, 30, 40), &notes);
  REQUIRE(out.groups.size() == 4);
  CHECK(out.groups[0].id == s.groups[0].id);
  CHECK(out.groups[0].paths == std::vector<int>{0});
  CHECK(out.groups[1].paths == std::vector<int>{1});  // the moving parts next, in name order: spokes
  CHECK(out.groups[1].id == s.groups[0].id + "-spokes");
  CHECK(out.groups[2].paths == std::vector<int>{2});  // wheel
  CHECK(out.groups[3].id == s.groups[1].id);  // the cloud holds still whole: kept as it was
  CHECK(out.groups[3].paths == s.groups[1].paths);
  for (size_t g = 0; g < out.groups.size(); ++g)
    for (int p : out.groups[g].paths) CHECK(out.paths[p].group == static_cast<int>(g));
  REQUIRE(notes.size() == 1);
  CHECK(notes[0] == s.groups[0].id + ": 1 still paths keep the group; the moving ones fit as 2 groups (spokes, wheel)");
}

TEST_CASE("a group whose paths move as two parts is split: the part with the most paths keeps it") {
  // Hands the rig took from the head's group: the head (two paths) turns with the body, the
  // gloves (one path) swing with the arm.
  const Scene s = read_svg_string(kDrawing, "wheel.svg");
  nlohmann::json m = report(5, 30, 40);
  m["parts"] = {{{"name", "head"}, {"paths", {"stand", "rim", "puff"}}}, {{"name", "gloves"}, {"paths", {"spoke"}}}};
  std::vector<std::string> notes;
  const Scene out = split_groups_by_motion(s, m, &notes);
  REQUIRE(out.groups.size() == 3);
  CHECK(out.groups[0].id == s.groups[0].id);
  CHECK(out.groups[0].paths == std::vector<int>{0, 2});
  CHECK(out.groups[1].id == s.groups[0].id + "-gloves");
  CHECK(out.groups[1].paths == std::vector<int>{1});
  CHECK(out.groups[2].paths == s.groups[1].paths);
  for (size_t g = 0; g < out.groups.size(); ++g)
    for (int p : out.groups[g].paths) CHECK(out.paths[p].group == static_cast<int>(g));
  REQUIRE(notes.size() == 1);
  CHECK(notes[0] == s.groups[0].id + ": its paths move as 2 parts; head keeps the group, the others fit as groups of their own (gloves)");
}

TEST_CASE("a group that moves whole as one part, or holds whole, or a report without the paths, is not split") {
  const Scene s = read_svg_string(kDrawing, "wheel.svg");
  nlohmann::json one = report(5, 30, 40);
  one["parts"] = {{{"name", "wheel"}, {"paths", {"stand", "spoke", "rim", "puff"}}}};
  CHECK(split_groups_by_motion(s, one, nullptr).groups.size() == 2);
  CHECK(split_groups_by_motion(s, report(0, 0, 0.01), nullptr).groups.size() == 2);  // 0.01 px: still
  CHECK(split_groups_by_motion(s, nlohmann::json::object(), nullptr).groups.size() == 2);
  nlohmann::json partial = report(0, 30, 40);
  partial["paths"].erase(1);  // the spoke unknown: the group is left whole
  CHECK(split_groups_by_motion(s, partial, nullptr).groups.size() == 2);
}

TEST_CASE("the groups the motion holds wholly still are held: after a split, its still part; an unknown path is not still") {
  const Scene s = read_svg_string(kDrawing, "wheel.svg");
  const nlohmann::json m = report(0, 30, 40);
  const Scene split = split_groups_by_motion(s, m, nullptr);
  CHECK(still_groups(split, m) == std::vector<std::string>{s.groups[0].id, s.groups[1].id});  // the stand's and the cloud
  CHECK(still_groups(s, m) == std::vector<std::string>{s.groups[1].id});  // unsplit, the wheel's group moves
  nlohmann::json partial = m;
  partial["paths"].erase(3);  // the puff unknown: the cloud is not held
  CHECK(still_groups(s, partial).empty());
  CHECK(still_groups(s, nlohmann::json::object()).empty());
}

}  // TEST_SUITE
