// recolorer `spherepack` (default): every path gets a colour from a maximin packing in the RGB
// cube with white reserved (engine/src/color/palette.h). Larger paths choose first, each taking
// the free colour farthest from the colours already given to the paths it touches, so
// neighbours are as distinct as the palette allows. Writes recolored.svg (grouped.svg in the
// new colours), recolored.png (its render) and palette.json (path id -> colour), which the
// fitter uses to compare like with like and the export ignores (original colours stay).
#include <algorithm>
#include <cmath>
#include <map>

#include "color/palette.h"
#include "common/plugin_glue.h"
#include "common/stage_files.h"
#include "group/grouped_svg.h"
#include "svgmotion/error.h"
#include "svgmotion/svg_reader.h"

namespace {

struct Box {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  double area() const { return std::max(0.0, x1 - x0) * std::max(0.0, y1 - y0); }
};

nlohmann::json run(const nlohmann::json& req, const svgm_host*) {
  namespace P = svgm::plugin;
  const auto in = P::file(req, "inputs", "svg");
  svgm::Scene scene = svgm::read_svg_file(in);
  const int n = static_cast<int>(scene.paths.size());
  if (n > svgm::kMaxPaletteSize)
    throw svgm::Error(in.string() + ": " + std::to_string(n) + " paths, more than the " +
                      std::to_string(svgm::kMaxPaletteSize) + " distinct colours the recolorer makes");
  const auto palette = svgm::distinct_palette(n);
  std::vector<Box> box(n);
  for (int i = 0; i < n; ++i)
    for (const auto& sp : scene.paths[i].subpaths)
      for (const auto& q : sp.points) {
        box[i].x0 = std::min(box[i].x0, q.x); box[i].y0 = std::min(box[i].y0, q.y);
        box[i].x1 = std::max(box[i].x1, q.x); box[i].y1 = std::max(box[i].y1, q.y);
      }
  const double margin = 0.01 * std::hypot(scene.width, scene.height);
  auto touch = [&](int a, int b) {
    return box[a].x0 <= box[b].x1 + margin && box[b].x0 <= box[a].x1 + margin &&
           box[a].y0 <= box[b].y1 + margin && box[b].y0 <= box[a].y1 + margin;
  };
  std::vector<int> order(n);
  for (int i = 0; i < n; ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return box[a].area() > box[b].area(); });
  std::vector<int> colour(n, -1);
  std::vector<bool> used(palette.size(), false);
  auto dist = [](const svgm::Rgb8& a, const svgm::Rgb8& b) {
    return std::hypot(a.r - b.r, std::hypot(a.g - b.g, a.b - b.b));
  };
  for (int i : order) {
    int best = -1;
    double best_d = -1;
    for (size_t c = 0; c < palette.size(); ++c) {
      if (used[c]) continue;
      double d = 1e300;  // distance to the nearest colour among its assigned neighbours
      for (int j = 0; j < n; ++j)
        if (colour[j] >= 0 && touch(i, j)) d = std::min(d, dist(palette[c], palette[colour[j]]));
      if (d > best_d) { best_d = d; best = static_cast<int>(c); }
    }
    colour[i] = best;
    used[best] = true;
  }
  nlohmann::json colors = nlohmann::json::object();
  std::map<int, std::vector<int>> by_group;
  for (int i = 0; i < n; ++i) {
    const svgm::Rgb8 c = palette[colour[i]];
    const svgm::Rgba rgba{c.r / 255.f, c.g / 255.f, c.b / 255.f, 1.f};
    svgm::Path& p = scene.paths[i];
    p.fill = {rgba.r, rgba.g, rgba.b, p.fill.a};
    p.stroke.color = {rgba.r, rgba.g, rgba.b, p.stroke.color.a};
    colors[p.id] = P::hex_color(rgba);
    by_group[p.group].push_back(i);
  }
  std::vector<std::vector<int>> groups;
  std::vector<std::string> names;  // the grouper's part names travel on to the video stage
  for (auto& [g, members] : by_group) {
    groups.push_back(members);
    names.push_back(g >= 0 && g < static_cast<int>(scene.groups.size()) ? scene.groups[static_cast<size_t>(g)].name : "");
  }
  svgm::write_grouped_svg(in, scene, groups, P::file(req, "outputs", "svg"), names);
  P::render_png(scene, 512, req.value("device", "auto"), P::file(req, "outputs", "png"));
  P::write_json(P::file(req, "outputs", "palette"), {{"colors", colors}});
  return {{"message", std::to_string(n) + " colours"}};
}

}  // namespace

SVGM_DEFINE_PLUGIN("recolorer", "spherepack", "1", "maximally distinct colours (sphere packing)", run)
