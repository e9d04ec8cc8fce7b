// The `layers` stage logic: painter's order of groups from occlusion evidence (layer_order.h).
#include <doctest/doctest.h>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "group/grouped_svg.h"
#include "group/layer_order.h"
#include "svgmotion/png_io.h"
#include "svgmotion/svg_reader.h"

using namespace svgm;
namespace fs = std::filesystem;

namespace {

struct LayerTempDir {
  fs::path dir;
  explicit LayerTempDir(const std::string& name) {
    dir = fs::temp_directory_path() / ("svgm_layers_test_" + std::to_string(::getpid()) + "_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  ~LayerTempDir() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
};

std::string slurp(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void spit(const fs::path& f, const std::string& s) {
  std::ofstream out(f, std::ios::binary);
  out << s;
}

using Rgb = std::array<uint8_t, 3>;
struct Box {
  int x0, y0, x1, y1;  // pixels [x0, x1) x [y0, y1)
  Rgb c;
};

// A 100x100 frame over white with the boxes painted in order (last on top).
RgbaImage frame(const std::vector<Box>& boxes) {
  RgbaImage im{100, 100, std::vector<uint8_t>(100 * 100 * 4, 255)};
  for (const Box& b : boxes)
    for (int y = b.y0; y < b.y1; ++y)
      for (int x = b.x0; x < b.x1; ++x)
        for (int k = 0; k < 3; ++k) im.rgba[(static_cast<size_t>(y) * 100 + x) * 4 + k] = b.c[k];
  return im;
}

void write_frames(const fs::path& dir, const std::vector<Box>& boxes, int n = 3) {
  fs::create_directories(dir);
  for (int i = 0; i < n; ++i) write_png(dir / ("frame_" + std::to_string(i) + ".png"), frame(boxes));
}

std::string rect_path(const std::string& id, int x0, int y0, int x1, int y1, const std::string& fill) {
  return "<path id=\"" + id + "\" d=\"M" + std::to_string(x0) + " " + std::to_string(y0) + " H" +
         std::to_string(x1) + " V" + std::to_string(y1) + " H" + std::to_string(x0) + " Z\" fill=\"" +
         fill + "\"/>";
}

// Source SVG (one path per group, paint order as given), grouped.svg written by the grouper's
// writer, palette.json with the paths' own colours.
fs::path make_grouped(const fs::path& dir, const std::string& body, const std::string& palette) {
  const fs::path src = dir / "input.svg";
  spit(src, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"100\" height=\"100\">" + body + "</svg>");
  const Scene scene = read_svg_file(src);
  std::vector<std::vector<int>> groups;
  for (size_t i = 0; i < scene.paths.size(); ++i) groups.push_back({static_cast<int>(i)});
  write_grouped_svg(src, scene, groups, dir / "grouped.svg");
  spit(dir / "palette.json", palette);
  return dir / "grouped.svg";
}

std::vector<std::string> path_ids(const fs::path& svg) {
  std::vector<std::string> ids;
  for (const Path& p : read_svg_file(svg).paths) ids.push_back(p.id);
  return ids;
}

LayerOptions small() {
  LayerOptions o;
  o.width = 100;
  o.keyframes = 3;
  return o;
}

const Rgb kRed{255, 0, 0}, kBlue{0, 0, 255}, kGreen{0, 160, 0};
const char* kPaletteAB = R"({"colors": {"a": "#ff0000", "b": "#0000ff"}})";

}  // namespace

TEST_SUITE("group") {

TEST_CASE("layers: the video shows B above A where the SVG paints A above B: the order flips") {
  LayerTempDir t("flip");
  // B first (bottom), A on top.
  const fs::path grouped = make_grouped(
      t.dir, rect_path("b", 40, 40, 80, 80, "#0000ff") + rect_path("a", 20, 20, 60, 60, "#ff0000"),
      kPaletteAB);
  // The target: A painted first, B over it.
  write_frames(t.dir / "frames", {{20, 20, 60, 60, kRed}, {40, 40, 80, 80, kBlue}});
  const LayerResult r = run_layers(grouped, t.dir / "frames", t.dir / "palette.json",
                                   t.dir / "layered.svg", t.dir / "layers.json", small());
  CHECK(r.changed);
  CHECK(path_ids(grouped) == std::vector<std::string>{"b", "a"});
  CHECK(path_ids(t.dir / "layered.svg") == std::vector<std::string>{"a", "b"});
  const nlohmann::json j = nlohmann::json::parse(slurp(t.dir / "layers.json"));
  CHECK(j["order"] == nlohmann::json{"group-2", "group-1"});  // back to front: a, then b
  CHECK(j["order_direction"] == "back_to_front");
  CHECK(j["changed"] == true);
  CHECK(j["fallback"].is_null());
  REQUIRE(j["pairs"].size() == 1);
  const nlohmann::json& p = j["pairs"][0];
  CHECK(p["a"] == "group-1");  // b, painted first in grouped.svg
  CHECK(p["b"] == "group-2");
  CHECK(p["overlap_pixels"] == 400);
  CHECK(p["a_pixels"] == 3 * 400);  // every overlap pixel of every keyframe shows b
  CHECK(p["b_pixels"] == 0);
  CHECK(p["score"].get<double>() == doctest::Approx(1.0));
  CHECK(p["used"] == true);
  CHECK(p["front"] == "group-1");
  // Same paths, same ids, same geometry and paint.
  const Scene before = read_svg_file(grouped), after = read_svg_file(t.dir / "layered.svg");
  REQUIRE(after.paths.size() == 2);
  CHECK(after.paths[0].fill == before.paths[1].fill);
  CHECK(after.paths[0].subpaths[0].points == before.paths[1].subpaths[0].points);
  // Everything else byte for byte: the same lines, two of them swapped.
  auto lines = [](const std::string& s) {
    std::vector<std::string> out;
    size_t at = 0;
    for (size_t nl = s.find('\n'); nl != std::string::npos; at = nl + 1, nl = s.find('\n', at))
      out.push_back(s.substr(at, nl - at));
    out.push_back(s.substr(at));
    return out;
  };
  const auto in_lines = lines(slurp(grouped)), out_lines = lines(slurp(t.dir / "layered.svg"));
  REQUIRE(in_lines.size() == out_lines.size());
  size_t differ = 0;
  for (size_t i = 0; i < in_lines.size(); ++i) differ += in_lines[i] != out_lines[i];
  CHECK(differ > 0);
  CHECK(std::is_permutation(in_lines.begin(), in_lines.end(), out_lines.begin()));
}

TEST_CASE("layers: evidence that agrees with the SVG, or no overlap, keeps the file byte for byte") {
  SUBCASE("agreeing evidence") {
    LayerTempDir t("agree");
    const fs::path grouped = make_grouped(
        t.dir, rect_path("b", 40, 40, 80, 80, "#0000ff") + rect_path("a", 20, 20, 60, 60, "#ff0000"),
        kPaletteAB);
    write_frames(t.dir / "frames", {{40, 40, 80, 80, kBlue}, {20, 20, 60, 60, kRed}});
    const LayerResult r = run_layers(grouped, t.dir / "frames", t.dir / "palette.json",
                                     t.dir / "layered.svg", t.dir / "layers.json", small());
    CHECK(!r.changed);
    REQUIRE(r.pairs.size() == 1);
    CHECK(r.pairs[0].score == doctest::Approx(-1.0));
    CHECK(r.pairs[0].used);
    CHECK(slurp(t.dir / "layered.svg") == slurp(grouped));
  }
  SUBCASE("no overlap") {
    LayerTempDir t("apart");
    const fs::path grouped = make_grouped(
        t.dir, rect_path("b", 60, 60, 90, 90, "#0000ff") + rect_path("a", 0, 0, 30, 30, "#ff0000"),
        kPaletteAB);
    write_frames(t.dir / "frames", {{0, 0, 30, 30, kRed}, {60, 60, 90, 90, kBlue}});
    const LayerResult r = run_layers(grouped, t.dir / "frames", t.dir / "palette.json",
                                     t.dir / "layered.svg", t.dir / "layers.json", small());
    CHECK(!r.changed);
    CHECK(r.pairs.empty());
    CHECK(slurp(t.dir / "layered.svg") == slurp(grouped));
    const nlohmann::json j = nlohmann::json::parse(slurp(t.dir / "layers.json"));
    CHECK(j["order"] == nlohmann::json{"group-1", "group-2"});
    CHECK(j["changed"] == false);
  }
  SUBCASE("too little evidence") {
    LayerTempDir t("weak");
    const fs::path grouped = make_grouped(
        t.dir, rect_path("b", 40, 40, 80, 80, "#0000ff") + rect_path("a", 20, 20, 60, 60, "#ff0000"),
        kPaletteAB);
    // The overlap shows neither colour except a 3x3 blue patch (27 < 30 pixels over 3 frames).
    write_frames(t.dir / "frames", {{20, 20, 60, 60, kRed}, {40, 40, 80, 80, kBlue},
                                    {40, 40, 60, 60, {90, 90, 90}}, {45, 45, 48, 48, kBlue}});
    const LayerResult r = run_layers(grouped, t.dir / "frames", t.dir / "palette.json",
                                     t.dir / "layered.svg", t.dir / "layers.json", small());
    CHECK(!r.changed);
    REQUIRE(r.pairs.size() == 1);
    CHECK(r.pairs[0].a_pixels == 27);
    CHECK(!r.pairs[0].confident);
    CHECK(!r.pairs[0].used);
  }
}

TEST_CASE("layers: cyclic evidence falls back to the original order for the groups in the cycle") {
  LayerTempDir t("cycle");
  // Three bars overlapping pairwise in three corners, never all three at once:
  // a = top bar, b = right bar, c = an L (left bar + bottom bar).
  const std::string body = rect_path("a", 0, 0, 60, 10, "#ff0000") +
                           rect_path("b", 50, 0, 60, 60, "#0000ff") +
                           "<path id=\"c\" d=\"M0 0 H10 V50 H60 V60 H0 Z\" fill=\"#00a000\"/>";
  const fs::path grouped = make_grouped(
      t.dir, body, R"({"colors": {"a": "#ff0000", "b": "#0000ff", "c": "#00a000"}})");
  // Corners: a/b shows b, b/c shows c, c/a shows a: b over a, c over b, a over c.
  write_frames(t.dir / "frames", {{0, 0, 60, 10, kRed},
                                  {50, 0, 60, 60, kBlue},
                                  {0, 0, 10, 60, kGreen},
                                  {0, 50, 60, 60, kGreen},
                                  {50, 0, 60, 10, kBlue},
                                  {50, 50, 60, 60, kGreen},
                                  {0, 0, 10, 10, kRed}});
  const LayerResult r = run_layers(grouped, t.dir / "frames", t.dir / "palette.json",
                                   t.dir / "layered.svg", t.dir / "layers.json", small());
  CHECK(!r.changed);
  REQUIRE(r.fallback);
  CHECK(r.fallback->find("cyclic") != std::string::npos);
  REQUIRE(r.pairs.size() == 3);
  for (const LayerPair& p : r.pairs) {
    CHECK(p.overlap_pixels == 100);
    CHECK(p.confident);
    CHECK(!p.used);
  }
  CHECK(slurp(t.dir / "layered.svg") == slurp(grouped));
  const nlohmann::json j = nlohmann::json::parse(slurp(t.dir / "layers.json"));
  CHECK(j["fallback"].is_string());
  CHECK(j["order"] == nlohmann::json{"group-1", "group-2", "group-3"});
}

TEST_CASE("layers: order_groups is a stable topological sort; cycles keep their own order") {
  const std::vector<std::string> ids = {"g0", "g1", "g2", "g3", "g4"};
  auto pair = [](int a, int b, double score) {
    LayerPair p;
    p.a = a, p.b = b, p.score = score, p.confident = true;
    return p;
  };
  std::optional<std::string> fb;
  SUBCASE("no edges") {
    std::vector<LayerPair> pairs;
    CHECK(order_groups(ids, pairs, &fb) == std::vector<int>{0, 1, 2, 3, 4});
    CHECK(!fb);
  }
  SUBCASE("one flip moves only what it must") {
    std::vector<LayerPair> pairs = {pair(1, 3, 0.9), pair(0, 4, -0.8)};  // 1 over 3; 4 over 0
    CHECK(order_groups(ids, pairs, &fb) == std::vector<int>{0, 2, 3, 1, 4});
    CHECK(pairs[0].used);
    CHECK(pairs[1].used);
    CHECK(!fb);
  }
  SUBCASE("a cycle among 1, 2, 3 keeps them 1, 2, 3; an edge from outside still applies") {
    // 1 over 2, 2 over 3, 3 over 1 (cycle); 4 behind 3: 3 over 4 (score > 0 means a in front).
    std::vector<LayerPair> pairs = {pair(1, 2, 0.9), pair(2, 3, 0.9), pair(1, 3, -0.9),
                                    pair(3, 4, 0.7)};
    CHECK(order_groups(ids, pairs, &fb) == std::vector<int>{0, 1, 2, 4, 3});
    REQUIRE(fb);
    CHECK(fb->find("g1 g2 g3") != std::string::npos);
    CHECK(!pairs[0].used);
    CHECK(!pairs[1].used);
    CHECK(!pairs[2].used);
    CHECK(pairs[3].used);
  }
  SUBCASE("unconfident pairs are ignored") {
    std::vector<LayerPair> pairs = {pair(0, 1, 1.0)};
    pairs[0].confident = false;
    CHECK(order_groups(ids, pairs, &fb) == std::vector<int>{0, 1, 2, 3, 4});
    CHECK(!pairs[0].used);
  }
}

TEST_CASE("layers: write_layered_svg moves all runs of a group together and nothing else") {
  LayerTempDir t("runs");
  const std::string in =
      "<?xml version=\"1.0\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"10\" height=\"10\">\n"
      "  <defs><style>.x{}</style></defs>\n"
      "  <g id=\"group-1\" data-group=\"group-1\"><path id=\"p1\" d=\"M0 0 H1 V1 Z\"/></g>\n"
      "  <!-- a comment -->\n"
      "  <g id=\"group-2\" data-group=\"group-2\"><path id=\"p2\" d=\"M0 0 H2 V2 Z\"/></g>\n"
      "  <g id=\"group-1-b\" data-group=\"group-1\"><path id=\"p3\" d=\"M0 0 H3 V3 Z\"/></g>\n"
      "  <g id=\"group-3\" data-group=\"group-3\" data-note=\"a/>b '</g>'\"><path id=\"p4\" d=\"M0 0 H4 V4 Z\"/></g>\n"
      "</svg>\n";
  spit(t.dir / "in.svg", in);
  REQUIRE(write_layered_svg(t.dir / "in.svg", {"group-2", "group-3", "group-1"}, t.dir / "out.svg"));
  const std::string expected =
      "<?xml version=\"1.0\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"10\" height=\"10\">\n"
      "  <defs><style>.x{}</style></defs>\n"
      "  <g id=\"group-2\" data-group=\"group-2\"><path id=\"p2\" d=\"M0 0 H2 V2 Z\"/></g>\n"
      "  <!-- a comment -->\n"
      "  <g id=\"group-3\" data-group=\"group-3\" data-note=\"a/>b '</g>'\"><path id=\"p4\" d=\"M0 0 H4 V4 Z\"/></g>\n"
      "  <g id=\"group-1\" data-group=\"group-1\"><path id=\"p1\" d=\"M0 0 H1 V1 Z\"/></g>\n"
      "  <g id=\"group-1-b\" data-group=\"group-1\"><path id=\"p3\" d=\"M0 0 H3 V3 Z\"/></g>\n"
      "</svg>\n";
  CHECK(slurp(t.dir / "out.svg") == expected);
  CHECK(path_ids(t.dir / "out.svg") == std::vector<std::string>{"p2", "p4", "p1", "p3"});
  // An id without an element: nothing written.
  CHECK(!write_layered_svg(t.dir / "in.svg", {"group-2", "nope", "group-1"}, t.dir / "none.svg"));
  CHECK(!fs::exists(t.dir / "none.svg"));
}

}  // TEST_SUITE
