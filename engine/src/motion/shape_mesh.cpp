// The lattice mesh of a figure with one copy of a cell per connected group of its pixels, and
// the binding of points to it: see shape_mesh.h for the method and why.
#include "motion/shape_mesh.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <numeric>

#include "motion/shape_pieces.h"
#include "svgmotion/error.h"

namespace svgm {

namespace {

// The smallest cell side, mask pixels: a 1-px cell would make a vertex per pixel corner.
constexpr int kMinCell = 2;
// A thin figure has many boundary cells per interior one; when the count overshoots the
// target by this factor the cell grows by a pixel and the lattice is rebuilt.
constexpr double kOvershoot = 1.5;

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  }
  // The smaller index becomes the root, so the result does not depend on the order of unions.
  void unite(int a, int b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }

// The lattice of cell side h over the labelled pixels (labels from shape_pieces).
ShapeMesh build_lattice(const cv::Mat& labels, int h, double scale) {
  ShapeMesh m;
  m.cell = h;
  m.scale = scale;
  m.width = labels.cols;
  m.height = labels.rows;
  const int W = labels.cols, H = labels.rows;
  const auto label = [&](int x, int y) { return labels.at<int>(y, x); };
  m.pixel_copy.assign(static_cast<size_t>(W) * H, -1);

  // Cell copies: the 4-connected groups of one label's pixels inside each cell, numbered in
  // raster order of cells, then of each group's first pixel.
  std::vector<std::array<int, 2>> copy_cell;
  std::deque<cv::Point> queue;
  for (int y0 = 0; y0 < H; y0 += h)
    for (int x0 = 0; x0 < W; x0 += h) {
      const int x1 = std::min(x0 + h, W), y1 = std::min(y0 + h, H);
      for (int ys = y0; ys < y1; ++ys)
        for (int xs = x0; xs < x1; ++xs) {
          if (label(xs, ys) < 0 || m.pixel_copy[static_cast<size_t>(ys) * W + xs] >= 0) continue;
          const int id = static_cast<int>(copy_cell.size());
          copy_cell.push_back({x0 / h, y0 / h});
          m.pixel_copy[static_cast<size_t>(ys) * W + xs] = id;
          queue.emplace_back(xs, ys);
          while (!queue.empty()) {
            const cv::Point p = queue.front();
            queue.pop_front();
            const cv::Point next[4] = {{p.x + 1, p.y}, {p.x - 1, p.y}, {p.x, p.y + 1}, {p.x, p.y - 1}};
            for (const cv::Point& q : next) {
              if (q.x < x0 || q.y < y0 || q.x >= x1 || q.y >= y1) continue;
              int& owner = m.pixel_copy[static_cast<size_t>(q.y) * W + q.x];
              if (owner >= 0 || label(q.x, q.y) != label(xs, ys)) continue;
              owner = id;
              queue.push_back(q);
            }
          }
        }
    }

  // Corners: slot 4c + k is corner k of copy c (k = 0 top-left, 1 top-right, 2 bottom-left,
  // 3 bottom-right). Two copies share a side's corners when a pixel pair of one label is
  // 4-adjacent across that side.
  const size_t copies = copy_cell.size();
  UnionFind corners(4 * copies);
  const auto copy_at = [&](int x, int y) { return m.pixel_copy[static_cast<size_t>(y) * W + x]; };
  for (int y = 0; y < H; ++y)
    for (int x = h - 1; x + 1 < W; x += h)
      if (label(x, y) >= 0 && label(x, y) == label(x + 1, y)) {
        const int a = copy_at(x, y), b = copy_at(x + 1, y);
        corners.unite(4 * a + 1, 4 * b + 0);
        corners.unite(4 * a + 3, 4 * b + 2);
      }
  for (int y = h - 1; y + 1 < H; y += h)
    for (int x = 0; x < W; ++x)
      if (label(x, y) >= 0 && label(x, y) == label(x, y + 1)) {
        const int a = copy_at(x, y), b = copy_at(x, y + 1);
        corners.unite(4 * a + 2, 4 * b + 0);
        corners.unite(4 * a + 3, 4 * b + 1);
      }
  std::vector<int> vertex_of(4 * copies, -1);
  for (size_t s = 0; s < 4 * copies; ++s) {
    int& v = vertex_of[corners.find(static_cast<int>(s))];
    if (v >= 0) continue;
    v = static_cast<int>(m.vertices.size());
    const auto& c = copy_cell[s / 4];
    const int i = c[0] + static_cast<int>(s & 1), j = c[1] + static_cast<int>((s >> 1) & 1);
    m.vertices.push_back({i * h / scale, j * h / scale});
  }

  // Two triangles per copy, the diagonal alternating like a chessboard so that the lattice has
  // no preferred shear direction; all four orientations have positive signed area.
  m.copy_triangles.resize(copies);
  for (size_t c = 0; c < copies; ++c) {
    int v[4];
    for (int k = 0; k < 4; ++k) v[k] = vertex_of[corners.find(static_cast<int>(4 * c + k))];
    const int first = static_cast<int>(m.triangles.size());
    if ((copy_cell[c][0] + copy_cell[c][1]) % 2 == 0) {
      m.triangles.push_back({v[0], v[1], v[3]});
      m.triangles.push_back({v[0], v[3], v[2]});
    } else {
      m.triangles.push_back({v[0], v[1], v[2]});
      m.triangles.push_back({v[1], v[3], v[2]});
    }
    m.copy_triangles[c] = {first, first + 1};
  }

  // Mesh pieces: connected components through shared vertices, numbered by first vertex.
  UnionFind joined(m.vertices.size());
  for (const auto& t : m.triangles) {
    joined.unite(t[0], t[1]);
    joined.unite(t[0], t[2]);
  }
  std::vector<int> piece_of_root(m.vertices.size(), -1);
  m.vertex_piece.resize(m.vertices.size());
  for (size_t v = 0; v < m.vertices.size(); ++v) {
    int& p = piece_of_root[joined.find(static_cast<int>(v))];
    if (p < 0) p = m.pieces++;
    m.vertex_piece[v] = p;
  }
  for (const auto& t : m.triangles) m.triangle_piece.push_back(m.vertex_piece[t[0]]);

  // The nearest pixel inside the mask, by an 8-connected breadth-first search from all of them
  // (chessboard distance: plenty for choosing which cell an off-shape point extrapolates).
  m.nearest_inside.assign(m.pixel_copy.size(), -1);
  queue.clear();
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      if (copy_at(x, y) >= 0) {
        m.nearest_inside[static_cast<size_t>(y) * W + x] = y * W + x;
        queue.emplace_back(x, y);
      }
  while (!queue.empty()) {
    const cv::Point p = queue.front();
    queue.pop_front();
    const int from = m.nearest_inside[static_cast<size_t>(p.y) * W + p.x];
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int x = p.x + dx, y = p.y + dy;
        if (x < 0 || y < 0 || x >= W || y >= H) continue;
        int& near = m.nearest_inside[static_cast<size_t>(y) * W + x];
        if (near >= 0) continue;
        near = from;
        queue.emplace_back(x, y);
      }
  }
  return m;
}

std::array<double, 3> barycentric(const ShapeMesh& m, int triangle, Vec2 p) {
  const auto& t = m.triangles[triangle];
  const Vec2 a = m.vertices[t[0]], ab = m.vertices[t[1]] - a, ac = m.vertices[t[2]] - a, ap = p - a;
  const double d = cross(ab, ac);
  const double l1 = cross(ap, ac) / d, l2 = cross(ab, ap) / d;
  return {1 - l1 - l2, l1, l2};
}

}  // namespace

ShapeMesh build_shape_mesh(const cv::Mat& mask, double scale, const ShapeMeshOptions& options) {
  if (!(scale > 0)) throw Error("build_shape_mesh: the scale must be positive");
  int pieces = 0;
  const cv::Mat labels = shape_pieces(mask, pieces);
  const double area = cv::countNonZero(labels >= 0);
  if (options.cell > 0) return build_lattice(labels, options.cell, scale);
  const double target = std::max(1, options.target_vertices);
  int h = std::max(kMinCell, static_cast<int>(std::lround(std::sqrt(area / target))));
  ShapeMesh m = build_lattice(labels, h, scale);
  while (m.vertices.size() > kOvershoot * target && h < std::max(mask.cols, mask.rows))
    m = build_lattice(labels, ++h, scale);
  return m;
}

MeshBinding bind_point(const ShapeMesh& m, Vec2 point) {
  MeshBinding b;
  b.rest = point;
  if (m.triangles.empty()) return b;
  const double mx = point.x * m.scale, my = point.y * m.scale;
  // Clamped first, so a point beyond the mask's image (NaN included) still finds a pixel.
  const int px = std::isfinite(mx) ? static_cast<int>(std::clamp(std::floor(mx), 0.0, m.width - 1.0)) : 0;
  const int py = std::isfinite(my) ? static_cast<int>(std::clamp(std::floor(my), 0.0, m.height - 1.0)) : 0;
  int pixel = py * m.width + px;
  if (m.pixel_copy[pixel] < 0) pixel = m.nearest_inside[pixel];
  const auto& two = m.copy_triangles[m.pixel_copy[pixel]];
  // The triangle the point is inside of (or nearer to): the larger smallest barycentric.
  const auto b0 = barycentric(m, two[0], point), b1 = barycentric(m, two[1], point);
  const bool second = std::min({b1[0], b1[1], b1[2]}) > std::min({b0[0], b0[1], b0[2]});
  b.triangle = second ? two[1] : two[0];
  b.bary = second ? b1 : b0;
  return b;
}

std::vector<MeshBinding> bind_points(const ShapeMesh& mesh, const std::vector<Vec2>& points) {
  std::vector<MeshBinding> out;
  out.reserve(points.size());
  for (const Vec2& p : points) out.push_back(bind_point(mesh, p));
  return out;
}

std::vector<Vec2> bound_positions(const ShapeMesh& mesh, const std::vector<MeshBinding>& bindings,
                                  const std::vector<Vec2>& vertices) {
  std::vector<Vec2> out;
  out.reserve(bindings.size());
  for (const MeshBinding& b : bindings) {
    if (b.triangle < 0) {
      out.push_back(b.rest);
      continue;
    }
    const auto& t = mesh.triangles[b.triangle];
    out.push_back(b.bary[0] * vertices[t[0]] + b.bary[1] * vertices[t[1]] + b.bary[2] * vertices[t[2]]);
  }
  return out;
}

}  // namespace svgm
