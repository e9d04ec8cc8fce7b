// The structural grouper (which paths move together) and the flat grouped SVG writer.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <string>
#include <unistd.h>

#include "group/grouped_svg.h"
#include "group/structural_grouper.h"
#include "svgmotion/svg_reader.h"

#include "temp_dir.h"

using namespace svgm;
using Groups = std::vector<std::vector<int>>;

namespace {

std::string svg(const std::string& body, const std::string& root = "width=\"200\" height=\"200\"") {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" " +
         root + ">" + body + "</svg>";
}

Scene read(const std::string& body, const std::string& root = "width=\"200\" height=\"200\"") {
  return read_svg_string(svg(body, root), "t.svg");
}

std::string circle(double cx, double cy, double r, const std::string& fill = "#888") {
  std::ostringstream s;
  s << "<circle cx=\"" << cx << "\" cy=\"" << cy << "\" r=\"" << r << "\" fill=\"" << fill << "\"/>";
  return s.str();
}

std::string square(double x, double y, double w, const std::string& fill = "#888") {
  std::ostringstream s;
  s << "<rect x=\"" << x << "\" y=\"" << y << "\" width=\"" << w << "\" height=\"" << w
    << "\" fill=\"" << fill << "\"/>";
  return s.str();
}

// Every path in exactly one group, each group sorted, groups ordered by their first path.
void check_partition(const Scene& scene, const Groups& groups) {
  std::vector<int> seen(scene.paths.size(), 0);
  for (size_t k = 0; k < groups.size(); ++k) {
    REQUIRE(!groups[k].empty());
    CHECK(std::is_sorted(groups[k].begin(), groups[k].end()));
    if (k > 0) CHECK(groups[k - 1][0] < groups[k][0]);
    for (int i : groups[k]) ++seen[static_cast<size_t>(i)];
  }
  for (int s : seen) CHECK(s == 1);
}

struct TempDir : test::TempDir {
  TempDir() : test::TempDir("svgm_group_test") {}
};

}  // namespace

namespace {
std::string text_of(const std::filesystem::path& f) {
  std::ifstream in(f);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}
}  // namespace

TEST_SUITE("group") {

TEST_CASE("eyes inside a head join the head; a far part stays apart") {
  // Head with two eyes and a mouth line, and a separate body shape far below.
  const Scene scene = read(circle(50, 50, 30, "#f0c090") + circle(40, 42, 4, "#000") +
                           circle(60, 42, 4, "#000") +
                           "<path d=\"M38 62 Q50 70 62 62\" fill=\"none\" stroke=\"#800\"/>" +
                           square(130, 130, 50, "#3050a0"));
  const Groups g = group_paths(scene);
  check_partition(scene, g);
  CHECK(g == Groups{{0, 1, 2, 3}, {4}});
}

TEST_CASE("a backdrop painted first does not swallow the figure it contains; it joins last") {
  // A hill over the lower canvas (at three edges), then a wheel and a leg on it, apart.
  const std::string hill = "<path d=\"M0 80 L200 60 L200 200 L0 200 Z\" fill=\"#6a4\"/>";
  const std::string parts = circle(50, 150, 20, "#333") + square(130, 120, 20, "#c33");
  const Scene scene = read(hill + parts);
  GroupingOptions o;
  o.min_groups = 1;
  const Groups g = group_paths(scene, o);
  check_partition(scene, g);
  CHECK(g == Groups{{0}, {1}, {2}});
  // Three groups at most two: the wheel and the leg, not the hill (the hill joins only when one
  // group is asked for).
  o.max_groups = 2;
  CHECK(group_paths(scene, o) == Groups{{0}, {1, 2}});
  // The same hill painted last is no backdrop (a large figure's body): it takes its contents.
  const Scene late = read(parts + hill);
  o.max_groups = 15;
  CHECK(group_paths(late, o).size() == 1);
}

TEST_CASE("containment is geometric: inside the box of an L but outside its fill is not inside") {
  // An L shape; a dot inside its vertical arm (contained) and a dot in the empty corner of its
  // bounding box, far from the L's fill; and a far square. A bounding-box test would put both
  // dots with the L.
  const Scene scene = read("<path d=\"M0 0 H100 V20 H20 V100 H0 Z\" fill=\"#444\"/>" +
                           circle(10, 60, 4, "#f00") + circle(75, 75, 5, "#f00") +
                           square(150, 150, 40));
  const Groups g = group_paths(scene);
  check_partition(scene, g);
  CHECK(g == Groups{{0, 1}, {2}, {3}});
}

TEST_CASE("even-odd holes: a dot in a ring's hole is not contained by the ring") {
  const Scene scene = read(
      "<path fill-rule=\"evenodd\" fill=\"#444\" d=\"M20 20 H180 V180 H20 Z M40 40 H160 V160 H40 Z\"/>" +
      circle(100, 100, 5, "#f00") + circle(30, 100, 4, "#0f0"));
  const Groups g = group_paths(scene);
  check_partition(scene, g);
  CHECK(g == Groups{{0, 2}, {1}});
}

TEST_CASE("far-apart parts stay apart when the count allows it") {
  const Scene scene = read(square(5, 5, 20) + square(175, 5, 20) + square(5, 175, 20) +
                           square(175, 175, 20));
  const Groups g = group_paths(scene);
  CHECK(g == Groups{{0}, {1}, {2}, {3}});
  for (const auto& grp : g) CHECK_FALSE(check_group(scene, grp).far_mix);
}

TEST_CASE("the count is bounded; far-apart clusters merge nearest first only when needed") {
  // 20 squares in a row, 10 units apart (5% of the diagonal of 400x200 is 22): a chain of
  // nearby parts, then a far one at the end.
  std::string body;
  for (int i = 0; i < 20; ++i) body += square(2 + 15 * i, 20, 5);
  body += square(380, 180, 10);
  const Scene scene = read(body, "width=\"400\" height=\"200\"");
  GroupingOptions opt;
  opt.max_groups = 5;
  const Groups g = group_paths(scene, opt);
  check_partition(scene, g);
  CHECK(g.size() == 5);
  // The far square is still alone: the chain merged among itself first.
  CHECK(g.back() == std::vector<int>{20});
  for (const auto& grp : g) CHECK_FALSE(check_group(scene, grp).far_mix);

  opt.max_groups = 1;  // forced below the far split: everything, and the check says so
  opt.min_groups = 1;
  const Groups one = group_paths(scene, opt);
  REQUIRE(one.size() == 1);
  const GroupCheck c = check_group(scene, one[0]);
  CHECK(c.far_mix);
  CHECK(c.components_at_touch == 21);  // 10-unit gaps are above the touch distance (4.5)
  CHECK(c.largest_gap == doctest::Approx(std::hypot(380.0 - 292.0, 180.0 - 25.0)).epsilon(1e-6));
}

TEST_CASE("the minimum count is respected: strong links stop at min_groups") {
  // Three nested circles and nothing else: containment would make one group.
  const Scene scene = read(circle(100, 100, 80) + circle(100, 100, 40) + circle(100, 100, 10));
  const Groups g = group_paths(scene);
  CHECK(g.size() == 2);
  check_partition(scene, g);
}

TEST_CASE("existing top-level groups are kept when they are good") {
  const Scene scene = read("<g id=\"head\">" + circle(50, 50, 30) + circle(45, 45, 4) +
                           "</g><g id=\"body\">" + square(120, 120, 40) + square(150, 150, 40) +
                           "</g>" + circle(180, 20, 5));
  const Groups g = group_paths(scene);
  CHECK(g == Groups{{0, 1}, {2, 3}, {4}});

  SUBCASE("but not when a group mixes far-apart unconnected paths") {
    // The first group holds two far-apart squares; the dot lies inside the first square.
    const Scene bad = read("<g>" + square(0, 0, 30) + square(160, 160, 30) + "</g><g>" +
                           circle(15, 15, 3) + circle(100, 5, 3) + "</g>");
    const Groups b = group_paths(bad);
    check_partition(bad, b);
    CHECK(b == Groups{{0, 2}, {1}, {3}});
  }
}

TEST_CASE("a grouper's part names travel in data-name on every run and are read back as Group::name") {
  TempDir tmp;
  const auto src = tmp.path / "in.svg";
  std::ofstream(src) << svg(square(10, 10, 20) + circle(100, 100, 10) + square(150, 150, 20));
  const Scene scene = read_svg_file(src);
  REQUIRE(scene.paths.size() == 3);
  const auto out = tmp.path / "grouped.svg";
  write_grouped_svg(src, scene, Groups{{0, 2}, {1}}, out, {"left wing", ""});  // g1 g2 g1-b
  const Scene back = read_svg_file(out);
  REQUIRE(back.groups.size() == 2);
  CHECK(back.groups[0].name == "left wing");  // both runs carry it; read once
  CHECK(back.groups[0].paths == std::vector<int>{0, 2});
  CHECK(back.groups[1].name.empty());  // no name: no attribute
  std::ifstream in(out);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  size_t count = 0;
  for (size_t at = text.find("data-name=\"left wing\""); at != std::string::npos; at = text.find("data-name=\"left wing\"", at + 1)) ++count;
  CHECK(count == 2);
  CHECK(text.find("data-name=\"\"") == std::string::npos);
}

TEST_CASE("deterministic") {
  std::string body;
  unsigned s = 12345;
  auto rnd = [&](int m) {
    s = s * 1103515245u + 12345u;
    return static_cast<int>((s >> 8) % static_cast<unsigned>(m));
  };
  for (int i = 0; i < 40; ++i) body += circle(rnd(200), rnd(200), 3 + rnd(20));
  const Scene scene = read(body);
  const Groups a = group_paths(scene), b = group_paths(scene);
  CHECK(a == b);
  CHECK(a.size() >= 2);
  CHECK(a.size() <= 15);
  check_partition(scene, a);
}

TEST_CASE("grouped SVG round trip, with interleaved groups split into runs") {
  TempDir tmp;
  const std::string source =
      "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" "
      "width=\"200\" height=\"100\" viewBox=\"0 0 100 50\">"
      "<style>.k { fill: #00ff00 } #b { fill: #0000ff }</style>"
      "<defs><circle id=\"dot\" r=\"3\"/></defs>"
      "<g transform=\"translate(10 5) rotate(20)\" opacity=\"0.5\">"
      "<path id=\"a\" d=\"M0 0 L20 0 Q25 10 20 20 A5 5 0 0 1 0 20 Z M5 5 L8 5 L8 8 Z\" "
      "fill=\"#ff0000\" fill-rule=\"evenodd\" fill-opacity=\"0.5\"/>"
      "<rect id=\"b\" class=\"k\" x=\"30\" y=\"0\" width=\"10\" height=\"10\" stroke=\"#123456\" "
      "stroke-width=\"2\" stroke-linejoin=\"round\" stroke-linecap=\"square\"/></g>"
      "<ellipse cx=\"60\" cy=\"25\" rx=\"8\" ry=\"4\" fill=\"rgb(10%,20%,30.5%)\"/>"
      "<use xlink:href=\"#dot\" x=\"80\" y=\"40\" fill=\"#abcdef\"/>"
      "<path id=\"e\" d=\"M70 10 C75 0 85 0 90 10\" fill=\"none\" stroke=\"#000\" stroke-miterlimit=\"7\"/>"
      "</svg>";
  const auto src = tmp.path / "in.svg";
  std::ofstream(src) << source;
  const Scene scene = read_svg_file(src);
  REQUIRE(scene.paths.size() == 5);
  const Groups groups{{0, 2, 4}, {1, 3}};  // interleaved: g1 g2 g1 g2 g1
  const auto out = tmp.path / "grouped.svg";
  write_grouped_svg(src, scene, groups, out);
  CHECK_FALSE(std::filesystem::exists(out.string() + ".part" + std::to_string(::getpid())));

  const Scene back = read_svg_file(out);
  REQUIRE(back.paths.size() == scene.paths.size());
  CHECK(back.width == scene.width);
  CHECK(back.height == scene.height);
  for (size_t i = 0; i < scene.paths.size(); ++i) {
    const Path &p = scene.paths[i], &q = back.paths[i];
    CAPTURE(p.id);
    CHECK(q.id == p.id);
    REQUIRE(q.subpaths.size() == p.subpaths.size());
    for (size_t s = 0; s < p.subpaths.size(); ++s) {
      CHECK(q.subpaths[s].closed == p.subpaths[s].closed);
      REQUIRE(q.subpaths[s].points.size() == p.subpaths[s].points.size());
      for (size_t k = 0; k < p.subpaths[s].points.size(); ++k) {
        CHECK(std::fabs(q.subpaths[s].points[k].x - p.subpaths[s].points[k].x) < 1e-3);
        CHECK(std::fabs(q.subpaths[s].points[k].y - p.subpaths[s].points[k].y) < 1e-3);
      }
    }
    CHECK(q.has_fill == p.has_fill);
    CHECK(q.fill_rule == p.fill_rule);
    CHECK(q.has_stroke == p.has_stroke);
    CHECK(std::fabs(q.opacity - p.opacity) < 1e-5);
    if (p.has_fill) {
      CHECK(std::fabs(q.fill.r - p.fill.r) < 1e-5);
      CHECK(std::fabs(q.fill.g - p.fill.g) < 1e-5);
      CHECK(std::fabs(q.fill.b - p.fill.b) < 1e-5);
      CHECK(std::fabs(q.fill.a - p.fill.a) < 1e-5);
    }
    if (p.has_stroke) {
      CHECK(q.stroke.color == p.stroke.color);
      CHECK(std::fabs(q.stroke.width - p.stroke.width) < 1e-5);
      CHECK(q.stroke.join == p.stroke.join);
      CHECK(q.stroke.cap == p.stroke.cap);
      CHECK(q.stroke.miter_limit == p.stroke.miter_limit);
    }
  }
  // The runs g1, g2, g1-b, g2-b, g1-c are joined again by their data-group when read back:
  // two parts, each with its paths in paint order.
  REQUIRE(back.groups.size() == 2);
  CHECK(back.groups[0].id == "group-1");
  CHECK(back.groups[1].id == "group-2");
  CHECK(text_of(out).find("id=\"group-1-c\"") != std::string::npos);
  std::ifstream in(out);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(text.find("data-group=\"group-1\"") != std::string::npos);
  CHECK(text.find("<style>") != std::string::npos);
  CHECK(text.find("<defs>") != std::string::npos);
  CHECK(text.find("viewBox=\"0 0 200 100\"") != std::string::npos);

  SUBCASE("groups that are not a partition are refused") {
    CHECK_THROWS(write_grouped_svg(src, scene, Groups{{0, 1, 2}, {3}}, out));
    CHECK_THROWS(write_grouped_svg(src, scene, Groups{{0, 1, 2}, {2, 3, 4}}, out));
  }
}

TEST_CASE("grouping then writing: the grouped file reads back with one group per part") {
  TempDir tmp;
  const auto src = tmp.path / "face.svg";
  std::ofstream(src) << svg(circle(50, 50, 30, "#f0c090") + circle(40, 42, 4, "#000") +
                            square(130, 130, 50, "#3050a0") + circle(60, 42, 4, "#000"));
  const Scene scene = read_svg_file(src);
  const Groups g = group_paths(scene);
  CHECK(g == Groups{{0, 1, 3}, {2}});
  const auto out = tmp.path / "grouped.svg";
  write_grouped_svg(src, scene, g, out);
  const Scene back = read_svg_file(out);
  // The eye drawn after the body is a second run of group 1, joined back by data-group.
  REQUIRE(back.groups.size() == 2);
  CHECK(back.groups[0].paths == std::vector<int>{0, 1, 3});
  CHECK(text_of(out).find("id=\"group-1-b\"") != std::string::npos);
  // Reading the grouped file and grouping again keeps its two parts.
  CHECK(group_paths(back).size() == 2);
}

// Small triangles around `clumps` centres on a 2000 x 2000 canvas (the far distance is
// 0.05 * 2828 = 141 units; clumps are 600 apart, their paths within 60 of the centre), in
// paint order round-robin over the clumps so no clump is a run of paint order. Each path's
// clump goes to `clump_of`; with `grouped`, each clump is one top-level <g>.
std::string clump_scene(int paths, int clumps, std::vector<int>& clump_of, bool grouped) {
  std::vector<std::ostringstream> bodies(static_cast<size_t>(clumps));
  std::ostringstream flat;
  unsigned state = 12345;
  auto next = [&] { return (state = state * 1103515245u + 12345u) / 65536u % 1000u / 1000.0; };
  clump_of.clear();
  for (int i = 0; i < paths; ++i) {
    const int c = i % clumps;
    const double x = 200 + 600 * (c % 3) + 120 * next() - 60;
    const double y = 200 + 600 * (c / 3) + 120 * next() - 60;
    std::ostringstream p;
    p << "<path d=\"M" << x << ' ' << y << " l3 1 l-1 3 z\" fill=\"#" << (c % 2 ? "c33" : "33c")
      << "\"/>";
    (grouped ? bodies[static_cast<size_t>(c)] : flat) << p.str();
    clump_of.push_back(c);
  }
  std::string body;
  if (grouped) {
    // Paint order is then clump by clump.
    clump_of.clear();
    for (int c = 0; c < clumps; ++c) {
      body += "<g>" + bodies[static_cast<size_t>(c)].str() + "</g>";
      for (int i = c; i < paths; i += clumps) clump_of.push_back(c);
    }
  } else {
    body = flat.str();
  }
  return svg(body, "width=\"2000\" height=\"2000\"");
}

TEST_CASE("a 1,500-path scene: a partition within bounds, no group spanning two clumps") {
  std::vector<int> clump_of;
  const Scene scene = read_svg_string(clump_scene(1500, 6, clump_of, false), "t.svg");
  REQUIRE(scene.paths.size() == 1500);
  std::string note = "stale";
  const Groups g = group_paths(scene, {}, &note);
  check_partition(scene, g);
  CHECK(g.size() >= 6);
  CHECK(g.size() <= 15);
  CHECK(note.empty());  // the full analysis ran
  for (const auto& grp : g)
    for (int i : grp)
      CHECK(clump_of[static_cast<size_t>(i)] == clump_of[static_cast<size_t>(grp[0])]);
}

TEST_CASE("above 2,000 paths: the coarse fallback partitions within bounds and says so") {
  std::vector<int> clump_of;
  const Scene scene = read_svg_string(clump_scene(5000, 6, clump_of, false), "t.svg");
  REQUIRE(scene.paths.size() == 5000);
  std::string note;
  const Groups g = group_paths(scene, {}, &note);
  check_partition(scene, g);
  CHECK(g.size() >= 2);
  CHECK(g.size() <= 15);
  CHECK(note.find("5000 paths (above 2000, no overlap analysis)") == 0);
  CHECK(note.find("grid") != std::string::npos);
  // The clumps are 480 apart (600 between centres) and the grid cells narrower: no cell
  // holds paths of two clumps.
  for (const auto& grp : g)
    for (int i : grp)
      CHECK(clump_of[static_cast<size_t>(i)] == clump_of[static_cast<size_t>(grp[0])]);
  GroupingOptions few;
  few.max_groups = 3;
  const Groups three = group_paths(scene, few);
  check_partition(scene, three);
  CHECK(three.size() >= 2);
  CHECK(three.size() <= 3);
}

TEST_CASE("above 2,000 paths: top-level groups within bounds are kept as they are") {
  std::vector<int> clump_of;
  const Scene scene = read_svg_string(clump_scene(3000, 4, clump_of, true), "t.svg");
  REQUIRE(scene.groups.size() == 4);
  std::string note;
  const Groups g = group_paths(scene, {}, &note);
  check_partition(scene, g);
  REQUIRE(g.size() == 4);
  for (const auto& grp : g) {
    CHECK(grp.size() == 750);
    for (int i : grp)
      CHECK(clump_of[static_cast<size_t>(i)] == clump_of[static_cast<size_t>(grp[0])]);
  }
  CHECK(note.find("kept the 4 top-level groups") != std::string::npos);
}

}  // TEST_SUITE
