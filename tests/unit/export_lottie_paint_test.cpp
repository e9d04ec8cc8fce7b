// The Lottie export of what is more than flat paths: gradients as gf/gs placed exactly (the
// colour parameter a player computes at the shape's corners is the SVG's), elliptical radial
// gradients through a group with the gradient's map, clip-path / mask / group opacity as
// precompositions and mattes, the one "cannot express" warning, and the .lottie archive.
#include <doctest/doctest.h>
#include <zlib.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>

#include "export/dotlottie.h"
#include "export/lottie_paint.h"
#include "export/lottie_writer.h"
#include "raster/raster_plan.h"
#include "svgmotion/svg_reader.h"

using namespace svgm;

namespace {

struct Static {
  Scene scene;
  LottieDocument doc;
  nlohmann::json j;
};

Static export_static(const char* svg) {
  Static s;
  s.scene = read_svg_string(svg, "t.svg");
  const RasterPlan plan = plan_raster(s.scene, Affine{}, s.scene.width, s.scene.height);
  AnimationTiming timing;
  timing.keyframes = 1;
  s.doc = lottie_animation(s.scene, plan, std::vector<double>(plan.rest_cp.begin(), plan.rest_cp.end()), timing,
                           LottieOptions{});
  s.j = nlohmann::json::parse(s.doc.json);
  return s;
}

// The item of type `ty` in the first group of a shape layer.
nlohmann::json item(const nlohmann::json& layer, const std::string& ty) {
  for (const auto& i : layer["shapes"][0]["it"])
    if (i["ty"] == ty) return i;
  return nullptr;
}

Vec2 point(const nlohmann::json& p) { return {p["k"][0].get<double>(), p["k"][1].get<double>()}; }

// A player's linear-gradient parameter at x: the projection on start -> end.
double linear_t(Vec2 s, Vec2 e, Vec2 x) {
  const Vec2 d = e - s, v = x - s;
  return (v.x * d.x + v.y * d.y) / (d.x * d.x + d.y * d.y);
}

// The files of a zip archive (both of our methods: stored, deflated), checking their CRCs.
std::map<std::string, std::string> unzip(const std::string& z) {
  auto u16 = [&](size_t at) { return static_cast<uint32_t>(static_cast<uint8_t>(z[at]) | static_cast<uint8_t>(z[at + 1]) << 8); };
  auto u32 = [&](size_t at) { return u16(at) | u16(at + 2) << 16; };
  std::map<std::string, std::string> out;
  const size_t end = z.size() - 22;
  REQUIRE(u32(end) == 0x06054b50u);
  size_t at = u32(end + 16);
  for (uint32_t e = 0; e < u16(end + 10); ++e) {
    REQUIRE(u32(at) == 0x02014b50u);
    const uint32_t method = u16(at + 10), crc = u32(at + 16), csize = u32(at + 20), usize = u32(at + 24);
    const uint32_t nlen = u16(at + 28), local = u32(at + 42);
    const std::string name = z.substr(at + 46, nlen);
    REQUIRE(u32(local) == 0x04034b50u);
    const std::string packed = z.substr(local + 30 + u16(local + 26) + u16(local + 28), csize);
    std::string data(usize, '\0');
    if (method == 0) {
      data = packed;
    } else {
      REQUIRE(method == 8);
      z_stream s{};
      REQUIRE(inflateInit2(&s, -MAX_WBITS) == Z_OK);
      s.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(packed.data()));
      s.avail_in = static_cast<uInt>(packed.size());
      s.next_out = reinterpret_cast<Bytef*>(data.data());
      s.avail_out = static_cast<uInt>(data.size());
      CHECK(inflate(&s, Z_FINISH) == Z_STREAM_END);
      inflateEnd(&s);
    }
    CHECK(crc32(0, reinterpret_cast<const Bytef*>(data.data()), static_cast<uInt>(data.size())) == crc);
    out[name] = data;
    at += 46 + nlen + u16(at + 30) + u16(at + 32);
  }
  return out;
}

}  // namespace

TEST_SUITE("export") {

TEST_CASE("lottie: a bounding-box linear gradient on a wide rect is a gf whose ramp is the SVG's at every corner") {
  // In box units the vector (0,0)->(1,1) runs corner to corner; on a 40 x 10 box its colour
  // lines are not perpendicular to that diagonal in canvas space: t = (u + v) / 2.
  const Static s = export_static(R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="60" height="30">
    <linearGradient id="g" x2="1" y2="1"><stop offset="0" stop-color="#f00"/><stop offset="1" stop-color="#00f" stop-opacity="0.5"/></linearGradient>
    <rect id="r" x="10" y="5" width="40" height="10" fill="url(#g)" fill-opacity="0.8"/></svg>)svg");
  CHECK(s.doc.warnings.empty());
  const auto gf = item(s.j["layers"][0], "gf");
  REQUIRE(gf.is_object());
  CHECK(gf["t"] == 1);
  CHECK(gf["o"]["k"] == 80);
  // Colour stops, then opacity stops (the second stop is half transparent): 4 more stops on
  // the straight blend between them, so that a player blending premultiplied colours (rlottie)
  // draws the same.
  CHECK(gf["g"]["p"] == 6);
  const std::vector<double> stops = gf["g"]["k"]["k"].get<std::vector<double>>();
  REQUIRE(stops.size() == 6 * 4 + 6 * 2);
  CHECK(stops[1] == 1);               // red first
  CHECK(stops[8] == doctest::Approx(0.4));  // third stop at 0.4: 60 % red, 40 % blue
  CHECK(stops[9] == doctest::Approx(0.6));
  CHECK(stops[11] == doctest::Approx(0.4));
  CHECK(stops[23] == 1);              // blue last
  CHECK(stops[24 + 4] == doctest::Approx(0.4));  // opacity stop 2 at 0.4: 1 - 0.4 * 0.5
  CHECK(stops[24 + 5] == doctest::Approx(0.8));
  CHECK(stops[35] == 0.5);
  const Vec2 a = point(gf["s"]), b = point(gf["e"]);
  CHECK(linear_t(a, b, {10, 5}) == doctest::Approx(0).epsilon(1e-3));
  CHECK(linear_t(a, b, {50, 15}) == doctest::Approx(1).epsilon(1e-3));
  CHECK(linear_t(a, b, {50, 5}) == doctest::Approx(0.5).epsilon(1e-3));
  CHECK(linear_t(a, b, {10, 15}) == doctest::Approx(0.5).epsilon(1e-3));
}

TEST_CASE("lottie: a repeating linear gradient is a pad gradient holding the repeated stops over the shape") {
  const Static s = export_static(R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="40" height="10">
    <linearGradient id="g" gradientUnits="userSpaceOnUse" x1="0" x2="10" spreadMethod="reflect">
      <stop offset="0" stop-color="#000"/><stop offset="1" stop-color="#fff"/></linearGradient>
    <rect width="40" height="10" fill="url(#g)"/></svg>)svg");
  const auto gf = item(s.j["layers"][0], "gf");
  CHECK(gf["g"]["p"] == 8);  // 4 periods of 2 stops, every other one mirrored
  const std::vector<double> k = gf["g"]["k"]["k"].get<std::vector<double>>();
  CHECK(k[4] == doctest::Approx(0.25));  // end of period 0: white
  CHECK(k[5] == 1);
  CHECK(k[9] == 1);  // period 1 starts white (mirrored)
  CHECK(point(gf["e"]).x == doctest::Approx(40));
}

TEST_CASE("lottie: a circular radial gradient with a focal point is written in canvas space") {
  const Static s = export_static(R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="40" height="40" viewBox="0 0 20 20">
    <radialGradient id="g" gradientUnits="userSpaceOnUse" cx="10" cy="10" r="8" fx="10" fy="14">
      <stop offset="0" stop-color="#fff"/><stop offset="1" stop-color="#000"/></radialGradient>
    <circle cx="10" cy="10" r="9" fill="url(#g)"/></svg>)svg");
  const auto gf = item(s.j["layers"][0], "gf");
  CHECK(gf["t"] == 2);
  CHECK(point(gf["s"]).x == doctest::Approx(20));
  const Vec2 d = point(gf["e"]) - point(gf["s"]);
  CHECK(std::hypot(d.x, d.y) == doctest::Approx(16));  // r 8 at twice the scale
  CHECK(gf["h"]["k"] == 50);                            // focal 4 of 8 along
  CHECK(gf["a"]["k"] == 90);                            // +y, from the s->e direction (+x)
}

TEST_CASE("lottie: an elliptical radial gradient fills through a group with the gradient's map") {
  const Static s = export_static(R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="60" height="30">
    <radialGradient id="g"><stop offset="0" stop-color="#ff0"/><stop offset="1" stop-color="#00f"/></radialGradient>
    <rect x="10" y="5" width="40" height="10" fill="url(#g)" stroke="#000"/></svg>)svg");
  CHECK(s.doc.warnings.empty());
  // Outer group: [stroke group (shapes, st), fill group, tr]; fill group A > A2 > [X > Y > shapes, gf].
  const auto& it = s.j["layers"][0]["shapes"][0]["it"];
  REQUIRE(it.size() == 3);
  CHECK(it[0]["it"][1]["ty"] == "st");
  const auto& A = it[1];
  const auto& A2 = A["it"][0];
  CHECK(A2["it"][1]["ty"] == "gf");
  CHECK(A2["it"][0]["it"][0]["it"][0]["ty"] == "sh");
  // A's scale is the box's (40 x 10, r = 0.5 in box units: 20 x 5 radii) under one rotation.
  const std::vector<double> scale = A["it"][1]["s"]["k"].get<std::vector<double>>();
  CHECK(std::fabs(scale[0] * scale[1]) == doctest::Approx(100.0 * 100.0 * 40 * 10));
}

TEST_CASE("lottie: split_affine recovers the map as rotate-scale-rotate") {
  for (const Affine& m : {Affine{2, 0.5, -0.3, 0.7, 0, 0}, Affine{1, 0, 0, -3, 0, 0}, Affine{0.2, 1.5, 1.1, 0.1, 0, 0}}) {
    const lottie::RotateScaleRotate p = lottie::split_affine(m);
    const Affine r = Affine::rotate_deg(p.rotate1) * Affine::scale(p.sx, p.sy) * Affine::rotate_deg(p.rotate2);
    CHECK(r.a == doctest::Approx(m.a));
    CHECK(r.b == doctest::Approx(m.b));
    CHECK(r.c == doctest::Approx(m.c));
    CHECK(r.d == doctest::Approx(m.d));
  }
}

TEST_CASE("lottie: clip-path, mask and group opacity become precompositions with track mattes") {
  const Static s = export_static(R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="40" height="40">
    <clipPath id="c"><circle cx="20" cy="20" r="10"/></clipPath>
    <mask id="m" maskUnits="userSpaceOnUse" x="0" y="0" width="30" height="40"><rect width="40" height="40" fill="#fff"/></mask>
    <g id="clipped" clip-path="url(#c)"><rect id="a" width="40" height="40" fill="#f00"/></g>
    <g id="both" clip-path="url(#c)" mask="url(#m)" opacity="0.5"><rect id="b" width="20" height="20" fill="#0f0"/></g></svg>)svg");
  const auto& L = s.j["layers"];
  REQUIRE(L.size() == 4);
  // Top: "both" = clip matte (td) above a precomp (alpha matte, the opacity) of [mask matte,
  // content (alpha matte)].
  CHECK(L[0]["td"] == 1);
  CHECK(L[1]["tt"] == 1);
  CHECK(L[1]["ks"]["o"]["k"] == 50);
  CHECK(L[2]["td"] == 1);  // "clipped": its clip's matte
  CHECK(L[3]["tt"] == 1);
  CHECK(item(L[0], "fl")["c"]["k"] == nlohmann::json::array({0, 0, 0, 1}));  // the clip's shapes, opaque
  nlohmann::json masked;
  for (const auto& a : s.j["assets"])
    if (a["id"] == L[1]["refId"]) masked = a["layers"];
  REQUIRE(masked.size() == 2);
  CHECK(masked[0]["td"] == 1);
  CHECK(masked[0]["hasMask"] == true);  // the mask's region
  CHECK(masked[0]["masksProperties"][0]["mode"] == "a");
  CHECK(masked[1]["tt"] == 1);  // a luminance mask, as an alpha matte of its content made white
  nlohmann::json mask_content;
  for (const auto& a : s.j["assets"])
    if (a["id"] == masked[0]["refId"]) mask_content = a["layers"];
  REQUIRE(mask_content.size() == 1);
  CHECK(item(mask_content[0], "fl")["c"]["k"] == nlohmann::json::array({1, 1, 1, 1}));  // #fff: L 1, alpha 1
}

TEST_CASE("lottie: group opacity over overlapping paths is an alpha matte of the canvas, one path keeps it as opacity") {
  const Static s = export_static(R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="40" height="30">
    <g opacity="0.4"><rect width="20" height="20" fill="#f00"/><rect x="10" y="10" width="20" height="20" fill="#00f"/></g>
    <g opacity="0.5"><rect x="30" width="5" height="5"/></g></svg>)svg");
  const auto& L = s.j["layers"];
  REQUIRE(L.size() == 3);
  // Top: the one-path group, faded by its layer's opacity.
  CHECK(L[0]["ks"]["o"]["k"] == 50);
  CHECK(L[0].find("tt") == L[0].end());
  // The two rects: a canvas-wide matte at 40 % above their precomposition at 100 %.
  CHECK(L[1]["td"] == 1);
  CHECK(L[1]["ks"]["o"]["k"] == 40);
  const auto rc = L[1]["shapes"][0]["it"][0];
  CHECK(rc["ty"] == "rc");
  CHECK(rc["s"]["k"] == nlohmann::json::array({42, 32}));
  CHECK(L[2]["tt"] == 1);
  CHECK(L[2]["ks"]["o"]["k"] == 100);
  CHECK(L[2]["ind"].get<int>() == L[1]["ind"].get<int>() + 1);
}

TEST_CASE("lottie: a dashed stroke keeps its dashes, caps and joins (an odd list repeated, in canvas units)") {
  const Static s = export_static(R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="40" height="40" viewBox="0 0 20 20">
    <path d="M2 2 L18 2 L18 18" fill="none" stroke="#000" stroke-dasharray="4, 2 1" stroke-dashoffset="1"
          stroke-linecap="square" stroke-linejoin="round" stroke-miterlimit="7"/></svg>)svg");
  CHECK(s.doc.warnings.empty());
  const auto st = item(s.j["layers"][0], "st");
  CHECK(st["lc"] == 3);
  CHECK(st["lj"] == 2);
  CHECK(st["ml"] == 7);
  const auto& d = st["d"];
  REQUIRE(d.size() == 7);
  const double want[] = {8, 4, 2, 8, 4, 2};
  for (size_t i = 0; i < 6; ++i) {
    CHECK(d[i]["n"] == (i % 2 ? "g" : "d"));
    CHECK(d[i]["v"]["k"] == want[i]);
  }
  CHECK(d[6]["n"] == "o");
  CHECK(d[6]["v"]["k"] == 2);
}

TEST_CASE("lottie: what Lottie cannot draw is named in one warning") {
  const Static s = export_static(R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="40" height="40">
    <filter id="f"><feGaussianBlur stdDeviation="2"/></filter><pattern id="p" width="4" height="4"/>
    <rect id="blurred" width="10" height="10" filter="url(#f)"/><rect id="hatched" x="20" width="10" height="10" fill="url(#p)"/>
    <rect id="solid" y="20" width="10" height="10"/></svg>)svg");
  REQUIRE(s.doc.warnings.size() == 1);
  CHECK(s.doc.warnings[0] == "cannot express in Lottie: filter on <rect id=blurred>, pattern paint on <rect id=hatched>");
}

TEST_CASE("dotlottie: a zip holding manifest.json and animations/animation.json, the same bytes each time") {
  const std::string json = R"({"v":"5.7.0","layers":[]})";
  const std::string z = dotlottie_archive(json, "animation", false);
  CHECK(z == dotlottie_archive(json, "animation", false));
  const auto files = unzip(z);
  REQUIRE(files.size() == 2);
  CHECK(files.at("animations/animation.json") == json);
  const auto manifest = nlohmann::json::parse(files.at("manifest.json"));
  CHECK(manifest["animations"][0]["id"] == "animation");
  CHECK(manifest["animations"][0]["loop"] == false);
  // A large entry is deflated (smaller than its text).
  const std::string big(10000, 'a');
  const std::string zb = zip_archive({{"big.txt", big}});
  CHECK(zb.size() < 1000);
  CHECK(unzip(zb).at("big.txt") == big);
}

}  // TEST_SUITE
