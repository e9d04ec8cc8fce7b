// Bench tool: how well the silhouette skeleton classifies real drawings (motion/figure_class.h).
//   figure_class_probe LIST.tsv [--size 256] [--mask all|fills] [--dump DIR]
// LIST.tsv rows: true_class <tab> set <tab> svg path <tab> annotation [<tab> anything]. For each
// drawing it renders the figure's mask on the CPU (raster/layer_compositor.h) without its
// backdrops (scene/backdrop.h), classifies it from the shape alone and with the annotation as
// the document's name, prints one line per drawing and then both confusion tables (rows: the
// true class, columns: the predicted). Mask modes: `all` is every painted pixel (fills and
// strokes: an outlined drawing's silhouette); `fills` drops strokes (an openmoji drawing's
// colour regions without its dark outline) and closes the gaps the outlines leave. --dump
// writes each mask with its skeleton over it (red) and the limbs' tips (green) as PNGs.
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "motion/figure_class.h"
#include "raster/layer_compositor.h"
#include "scene/backdrop.h"
#include "svgmotion/render_size.h"
#include "svgmotion/svg_reader.h"

using namespace svgm;
using namespace svgm::motion;

namespace {

struct Row {
  std::string truth, set, path, annotation;
};

std::vector<Row> read_list(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file + ": cannot be read");
  std::vector<Row> rows;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    Row r;
    std::getline(ls, r.truth, '\t');
    std::getline(ls, r.set, '\t');
    std::getline(ls, r.path, '\t');
    std::getline(ls, r.annotation, '\t');
    if (!figure_class_from_name(r.truth)) throw std::runtime_error(file + ": unknown class '" + r.truth + "'");
    rows.push_back(r);
  }
  return rows;
}

// The figure's mask: every path but the backdrops, drawn opaque, alpha thresholded at half.
cv::Mat figure_mask(const std::string& svg, int size, bool fills_only) {
  Scene scene = read_svg_file(svg);
  const size_t n = scene.paths.size();
  std::vector<Path> kept;
  for (size_t i = 0; i < n; ++i) {
    Path p = scene.paths[i];
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (const auto& sp : p.subpaths)
      for (const auto& q : sp.points) x0 = std::min(x0, q.x), y0 = std::min(y0, q.y), x1 = std::max(x1, q.x), y1 = std::max(y1, q.y);
    // A backdrop by the rig's rule that also fills its box (a sky, a ground band): emoji have
    // none, and a twemoji animal's body spans the canvas as the rule's backdrops do.
    double area = 0, box = (x1 - x0) * (y1 - y0);
    for (const auto& sp : p.subpaths)
      for (size_t k = 0; k + 1 < sp.points.size(); ++k)
        area += sp.points[k].x * sp.points[k + 1].y - sp.points[k + 1].x * sp.points[k].y;
    if (is_backdrop(x0, y0, x1, y1, static_cast<double>(i) / n, scene.width, scene.height) &&
        std::fabs(0.5 * area) >= 0.8 * box)
      continue;
    if (fills_only) {
      p.has_stroke = false;
      p.stroke_gradient = -1;
      if (!p.has_fill) continue;
    }
    kept.push_back(std::move(p));
  }
  scene.paths = std::move(kept);
  scene.groups.clear();
  const RenderSize rs = render_size(scene, size);
  const RgbaImage img = render_layers(scene, rs, true);
  cv::Mat mask(img.height, img.width, CV_8U);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) mask.at<uchar>(y, x) = img.rgba[4 * (static_cast<size_t>(y) * img.width + x) + 3] > 127 ? 255 : 0;
  if (fills_only) {  // the outlines' gaps between colour regions: about a stroke's width
    const int r = std::max(1, size / 96);
    cv::morphologyEx(mask, mask, cv::MORPH_CLOSE, cv::getStructuringElement(cv::MORPH_ELLIPSE, {2 * r + 1, 2 * r + 1}));
  }
  return mask;
}

void dump(const std::string& dir, const std::string& name, const cv::Mat& mask, const Skeleton& s, const Figure& f) {
  cv::Mat vis;
  cv::cvtColor(mask, vis, cv::COLOR_GRAY2BGR);
  vis *= 0.35;
  vis.setTo(cv::Scalar(0, 0, 255), s.pixels);
  for (const auto& L : f.limbs) {
    const cv::Scalar colour = L.kind == LimbKind::Head ? cv::Scalar(255, 255, 0)
                              : L.kind == LimbKind::Leg ? cv::Scalar(0, 255, 0)
                              : L.kind == LimbKind::Arm ? cv::Scalar(255, 0, 255)
                                                        : cv::Scalar(0, 200, 255);
    cv::circle(vis, {static_cast<int>(L.tip_pos.x), static_cast<int>(L.tip_pos.y)}, 4, colour, 2);
  }
  cv::imwrite(dir + "/" + name + ".png", vis);
}

void print_table(const char* title, const std::map<std::string, std::map<std::string, int>>& t) {
  std::vector<std::string> cols;
  for (int c = 0; c <= static_cast<int>(FigureClass::Scene); ++c) cols.push_back(figure_class_name(static_cast<FigureClass>(c)));
  std::printf("\n%s (rows: true class, columns: predicted)\n%-10s", title, "");
  for (const auto& c : cols) std::printf(" %5.5s", c.c_str());
  std::printf("  right\n");
  for (const auto& [truth, row] : t) {
    int total = 0, right = 0;
    std::printf("%-10s", truth.c_str());
    for (const auto& c : cols) {
      const auto it = row.find(c);
      const int k = it == row.end() ? 0 : it->second;
      total += k;
      if (c == truth) right = k;
      std::printf(" %5d", k);
    }
    std::printf("  %d/%d\n", right, total);
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: figure_class_probe LIST.tsv [--size 256] [--mask all|fills] [--dump DIR]\n");
    return 2;
  }
  int size = 256;
  std::string mode = "all", dump_dir;
  for (int i = 2; i + 1 < argc; i += 2) {
    const std::string k = argv[i], v = argv[i + 1];
    if (k == "--size") size = std::stoi(v);
    else if (k == "--mask") mode = v;
    else if (k == "--dump") dump_dir = v;
    else {
      std::fprintf(stderr, "figure_class_probe: unknown option %s\n", k.c_str());
      return 2;
    }
  }
  if (mode != "all" && mode != "fills") {
    std::fprintf(stderr, "figure_class_probe: --mask wants all or fills\n");
    return 2;
  }
  try {
    if (!dump_dir.empty()) std::filesystem::create_directories(dump_dir);
    std::map<std::string, std::map<std::string, int>> shape_table, hinted_table;
    for (const Row& r : read_list(argv[1])) {
      const cv::Mat mask = figure_mask(r.path, size, mode == "fills");
      const Skeleton s = skeletonise(mask);
      const Figure f = find_limbs(s);
      const FigureVerdict shape = classify_figure(mask, s, f);
      const FigureVerdict hinted = classify_figure(mask, s, f, std::nullopt, {r.annotation});
      ++shape_table[r.truth][figure_class_name(shape.cls)];
      ++hinted_table[r.truth][figure_class_name(hinted.cls)];
      std::string limbs;
      for (const auto& L : f.limbs) {
        limbs += std::string(limb_kind_name(L.kind)).substr(0, 1);
        if (L.kind == LimbKind::Leg) limbs += std::to_string(static_cast<int>(100 * L.relative_length));
      }
      std::printf("%-10s %-13s %-13s limbs=%-14s %-8s %-28.28s %s\n", r.truth.c_str(), figure_class_name(shape.cls),
                  figure_class_name(hinted.cls), limbs.c_str(), r.set.c_str(), r.annotation.c_str(),
                  shape.shape_reason.c_str());
      if (!dump_dir.empty()) {
        std::string name = r.set + "_" + std::filesystem::path(r.path).stem().string();
        dump(dump_dir, name, mask, s, f);
      }
    }
    print_table("shape only", shape_table);
    print_table("with the annotation as the document's name", hinted_table);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "figure_class_probe: %s\n", e.what());
    return 1;
  }
  return 0;
}
