// A region bend through an as-rigid-as-possible mesh (region_bend.h): the mask of the bent
// paths, the mesh and its handles (once per drawing and action, remembered: fit_plan draws the
// same plan's frames dozens of times at other amplitudes), then a cold solve per frame.
#include "procedural/region_bend.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <mutex>

#include <opencv2/imgproc.hpp>

#include "geometry/curve_samples.h"
#include "motion/arap.h"
#include "motion/shape_mesh.h"
#include "procedural/motion_plan_internal.h"

namespace svgm {

using namespace motion_plan_internal;

namespace {

// The mask's long side in pixels (arap.h: "~256 px on the long side"); the mesh then has about
// ShapeMeshOptions::target_vertices vertices whatever the drawing's size.
constexpr double kWorkingSize = 256;
// A mesh piece with fewer handle vertices than this is held to the closed form everywhere (a
// piece lying in the free band: the solver would only carry it rigidly with the others).
constexpr int kMinPieceHandles = 3;
// How many cells the free band grows each way beyond the closed form's ramp.
constexpr int kBandCells = 2;
// The memo's size: a plan has a few region actions, a run a few drawings.
constexpr size_t kMemoEntries = 32;

// The coverage of `paths` at `scale` mask pixels per canvas unit, its holes filled (a figure
// drawn in outlines bends as the shape they enclose, arap.h), grown by one pixel so that every
// point on an outline lies on the mask.
cv::Mat bent_mask(const Scene& scene, const std::vector<int>& paths, double scale) {
  const int W = static_cast<int>(std::ceil(scene.width * scale)) + 1, H = static_cast<int>(std::ceil(scene.height * scale)) + 1;
  cv::Mat mask(H, W, CV_8U, cv::Scalar(0));
  // Sub-pixel vertices (cv::fillPoly's shift): 8 fractional bits.
  auto px = [&](Vec2 q) { return cv::Point(static_cast<int>(std::lround(q.x * scale * 256)), static_cast<int>(std::lround(q.y * scale * 256))); };
  for (int pi : paths) {
    const Path& p = scene.paths[static_cast<size_t>(pi)];
    const bool fill = p.has_fill && p.fill.a > 0, stroke = p.has_stroke && p.stroke.color.a > 0 && p.stroke.width > 0;
    if (p.opacity <= 0 || !(fill || stroke)) continue;
    std::vector<std::vector<cv::Point>> poly;
    for (const Subpath& sp : p.subpaths) {
      std::vector<Vec2> ring;
      append_curve_samples(sp, 8, true, ring);
      if (ring.size() < 2) continue;
      poly.emplace_back();
      for (const Vec2& q : ring) poly.back().push_back(px(q));
      if (stroke)
        cv::polylines(mask, std::vector<std::vector<cv::Point>>{poly.back()}, sp.closed, cv::Scalar(255),
                      std::max(1, static_cast<int>(std::lround(p.stroke.width * scale))), cv::LINE_8, 8);
    }
    if (fill && !poly.empty()) cv::fillPoly(mask, poly, cv::Scalar(255), cv::LINE_8, 8);
  }
  // Holes: what the border's flood does not reach.
  cv::Mat outside(H + 2, W + 2, CV_8U, cv::Scalar(0));
  mask.copyTo(outside(cv::Rect(1, 1, W, H)));
  cv::floodFill(outside, cv::Point(0, 0), cv::Scalar(128));
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      if (outside.at<uint8_t>(y + 1, x + 1) == 0) mask.at<uint8_t>(y, x) = 255;
  cv::dilate(mask, mask, cv::Mat::ones(3, 3, CV_8U));
  return mask;
}

uint64_t fnv(const void* data, size_t n, uint64_t h = 1469598103934665603ull) {
  const auto* b = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
  return h;
}

}  // namespace

struct RegionBend::Built {
  std::shared_ptr<const ShapeMesh> mesh;
  std::vector<int> handle_vertex;
  std::vector<char> held;  // per vertex: a handle the region holds (its triangles' points stay exactly)
  ArapDeformer deformer;
};

namespace {

// Meshes by mask, deformers by mask and handles: the same inputs build the same bits, so a
// remembered one is the one that would be built.
std::mutex memo_mutex;
std::map<uint64_t, std::shared_ptr<const ShapeMesh>> mesh_memo;
std::map<std::pair<uint64_t, uint64_t>, std::shared_ptr<const RegionBend::Built>> built_memo;

}  // namespace

RegionBend::RegionBend(const Scene& scene, const std::vector<int>& paths, const PlannedAction& a, const RigBox& box)
    : action_(a), box_(box) {
  if (paths.empty() || !(scene.width > 0 && scene.height > 0)) return;
  // A growing part scales about its middle, a rotor's blades turn or squeeze whole about their hub
  // (rotor_blades.h): no shape is cut, nothing to bend.
  if (!a.lobes.empty() && (a.primitive == Primitive::Pulse || a.primitive == Primitive::Spin || a.primitive == Primitive::Stretch)) return;
  // A blaze licks in closed form, which folds at no amplitude (flame_lick.h).
  if (std::any_of(a.lobes.begin(), a.lobes.end(), [](const ArmLobe& l) { return l.kind == LobeKind::Blaze; })) return;
  const double scale = kWorkingSize / std::max(scene.width, scene.height);
  const cv::Mat mask = bent_mask(scene, paths, scale);
  uint64_t key = fnv(mask.data, mask.total());
  key = fnv(&scale, sizeof scale, fnv(&mask.cols, sizeof mask.cols, key));
  std::shared_ptr<const ShapeMesh> mesh;
  {
    std::lock_guard<std::mutex> lock(memo_mutex);
    auto it = mesh_memo.find(key);
    if (it != mesh_memo.end()) mesh = it->second;
  }
  if (!mesh) {
    mesh = std::make_shared<const ShapeMesh>(build_shape_mesh(mask, scale));
    std::lock_guard<std::mutex> lock(memo_mutex);
    if (mesh_memo.size() >= kMemoEntries) mesh_memo.clear();
    mesh_memo[key] = mesh;
  }
  if (mesh->triangles.empty()) return;
  // Each vertex: held (0), turned (1) or free (2) by the closed form's weight; then the pieces
  // with too few handles held to the closed form everywhere (3).
  std::vector<int8_t> kind(mesh->vertices.size());
  std::vector<int> handles_in(static_cast<size_t>(mesh->pieces), 0);
  bool turns = false;
  std::vector<Vec2> pivot(kind.size());
  for (size_t v = 0; v < kind.size(); ++v) {
    const RegionTurn r = region_turn(a, 1, 0, box, mesh->vertices[v]);
    const double w = r.weight;
    pivot[v] = r.pivot;
    kind[v] = static_cast<int8_t>(w <= 0 ? 0 : w >= 1 ? 1 : 2);
    turns = turns || kind[v] != 0;
    if (kind[v] != 2) ++handles_in[static_cast<size_t>(mesh->vertex_piece[v])];
  }
  if (!turns) return;
  // The free band widened by kBandCells cells each way: the closed form's ramp is as narrow as
  // half a limb's base (outline lobes), and a bend that short compresses the inside of the joint
  // to a crease (the test sweater's cuff lying across it: its inner edge at 0.5 of its length).
  std::vector<std::vector<int>> next(kind.size());
  for (const auto& t : mesh->triangles)
    for (int k = 0; k < 3; ++k) next[static_cast<size_t>(t[k])].push_back(t[(k + 1) % 3]), next[static_cast<size_t>(t[(k + 1) % 3])].push_back(t[k]);
  // Where the closed form cuts (a held vertex next to a turned one: a lobe's side; two turned
  // about different pivots: the two legs of a Lower bend where the mask joins them), the mesh
  // tears unless both are free.
  {
    std::vector<int8_t> cut = kind;
    for (const auto& t : mesh->triangles)
      for (int k = 0; k < 3; ++k) {
        const size_t u = static_cast<size_t>(t[k]), w = static_cast<size_t>(t[(k + 1) % 3]);
        const bool apart = (kind[u] == 0 && kind[w] == 1) || (kind[u] == 1 && kind[w] == 0) ||
                           (kind[u] == 1 && kind[w] == 1 && (pivot[u].x != pivot[w].x || pivot[u].y != pivot[w].y));
        if (apart) cut[u] = cut[w] = 2;
      }
    kind.swap(cut);
  }
  for (int step = 0; step < kBandCells; ++step) {
    std::vector<int8_t> grown = kind;
    for (size_t v = 0; v < kind.size(); ++v)
      if (kind[v] == 2)
        for (int u : next[v]) grown[static_cast<size_t>(u)] = 2;
    kind.swap(grown);
  }
  // A limb too thin for the band (every turned vertex freed): nothing would turn it, and the
  // mesh would hold it still; the closed form moves it instead.
  if (std::count(kind.begin(), kind.end(), int8_t{1}) < kMinPieceHandles) return;
  std::fill(handles_in.begin(), handles_in.end(), 0);
  for (size_t v = 0; v < kind.size(); ++v)
    if (kind[v] != 2) ++handles_in[static_cast<size_t>(mesh->vertex_piece[v])];
  for (size_t v = 0; v < kind.size(); ++v)
    if (handles_in[static_cast<size_t>(mesh->vertex_piece[v])] < kMinPieceHandles) kind[v] = 3;
  const std::pair<uint64_t, uint64_t> bkey{key, fnv(kind.data(), kind.size())};
  {
    std::lock_guard<std::mutex> lock(memo_mutex);
    auto it = built_memo.find(bkey);
    if (it != built_memo.end()) built_ = it->second;
  }
  if (built_) return;
  std::vector<int> hv;
  std::vector<ArapHandle> handles;
  for (size_t v = 0; v < kind.size(); ++v)
    if (kind[v] != 2) {
      hv.push_back(static_cast<int>(v));
      handles.push_back(ArapHandle::at_vertex(static_cast<int>(v)));
    }
  std::vector<char> held(kind.size());
  for (size_t v = 0; v < kind.size(); ++v) held[v] = kind[v] == 0;
  auto built = std::make_shared<const Built>(Built{mesh, hv, held, ArapDeformer(*mesh, std::move(handles))});
  std::lock_guard<std::mutex> lock(memo_mutex);
  if (built_memo.size() >= kMemoEntries) built_memo.clear();
  built_memo[bkey] = built;
  built_ = built;
}

std::vector<Vec2> RegionBend::solve(double amp, double t) const {
  const ShapeMesh& m = *built_->mesh;
  std::vector<Vec2> targets;
  targets.reserve(built_->handle_vertex.size());
  bool rest = true;
  for (int v : built_->handle_vertex) {
    const Vec2 p = m.vertices[static_cast<size_t>(v)];
    targets.push_back(bend_region(action_, amp, t, box_, p));
    rest = rest && targets.back().x == p.x && targets.back().y == p.y;
  }
  // At rest (the loop's first and last frames) exactly at rest, not within the solver's error.
  if (rest) return m.vertices;
  return built_->deformer.deform(targets);
}

Vec2 RegionBend::apply(const std::vector<Vec2>& v, Vec2 q) const {
  const ShapeMesh& m = *built_->mesh;
  const MeshBinding b = bind_point(m, q);
  if (b.triangle < 0) return q;
  const auto& t = m.triangles[static_cast<size_t>(b.triangle)];
  // On what the region holds the point stays exactly (not within the solver's error).
  if (built_->held[t[0]] && built_->held[t[1]] && built_->held[t[2]]) return q;
  return b.bary[0] * v[t[0]] + b.bary[1] * v[t[1]] + b.bary[2] * v[t[2]];
}

Vec2 RegionBend::carry(const std::vector<Vec2>& v, Vec2 pivot, Vec2 q) const {
  // The triangle under the pivot maps pivot + d affinely: its image of the x axis is the turn.
  const ShapeMesh& m = *built_->mesh;
  const MeshBinding b = bind_point(m, pivot);
  if (b.triangle < 0) return q;
  const auto& t = m.triangles[static_cast<size_t>(b.triangle)];
  if (built_->held[t[0]] && built_->held[t[1]] && built_->held[t[2]]) return q;
  const double eps = 1.0 / m.scale;  // one mask pixel
  const MeshBinding e{b.triangle, {}, pivot + Vec2{eps, 0}};
  const Vec2 a0 = m.vertices[t[0]], ab = m.vertices[t[1]] - a0, ac = m.vertices[t[2]] - a0, ap = e.rest - a0;
  const double d = ab.x * ac.y - ab.y * ac.x;
  const double l1 = (ap.x * ac.y - ap.y * ac.x) / d, l2 = (ab.x * ap.y - ab.y * ap.x) / d;
  const Vec2 p = b.bary[0] * v[t[0]] + b.bary[1] * v[t[1]] + b.bary[2] * v[t[2]];
  const Vec2 pe = (1 - l1 - l2) * v[t[0]] + l1 * v[t[1]] + l2 * v[t[2]];
  const double ang = std::atan2(pe.y - p.y, pe.x - p.x);
  const double cs = std::cos(ang), sn = std::sin(ang), dx = q.x - pivot.x, dy = q.y - pivot.y;
  return p + Vec2{cs * dx - sn * dy, sn * dx + cs * dy};
}

MeshQuality RegionBend::quality(const std::vector<Vec2>& v) const { return mesh_quality(*built_->mesh, v); }

}  // namespace svgm
