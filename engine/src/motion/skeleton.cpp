// The silhouette skeleton: thinning, spur pruning and graph tracing (skeleton.h).
//
// Thinning. The medial axis of a shape is the set of centres of its maximal inscribed discs;
// on pixels it is approximated by thinning: peel boundary pixels layer by layer, keeping any
// pixel whose removal would split the shape, open a hole or shorten a line. Zhang and Suen's
// two-subiteration rule (CACM 27(3), 1984) does this with a 3x3 test: a pixel P1 with
// neighbours P2..P9 (N, NE, E, ... NW) goes when it has 2..6 neighbours (not an end, not
// interior), exactly one 0->1 transition round P2..P9 (it is a simple boundary point), and it
// lies on a south-east boundary (first subiteration: P2*P4*P6 = P4*P6*P8 = 0) or a north-west
// one (second: P2*P4*P8 = P2*P6*P8 = 0). Alternating the two sides keeps the result centred.
// Zhang-Suen leaves two-pixel "staircase" corners on diagonals; a final sequential pass removes
// a pixel that has two orthogonal 4-neighbours (N and E, ...) when its neighbours stay one
// 8-connected set without it, so every line pixel has exactly two neighbours and the graph
// tracing below can follow lines pixel by pixel.
//
// Pruning. Thinning reaches every convex bump of the outline: a 1-px bump of a rendered edge
// (antialiasing, a stroke's join) grows a branch from the axis out to the bump. Such a spur
// starts at a junction whose inscribed disc has radius r and ends at the outline, so its
// reach (its length plus the radius at its end point, which is how far the figure extends
// beyond the end point: a round end's branch stops at the end disc's centre) is about r plus
// the bump's height h. A real limb sticks out of the body by at least about half the body's
// local half-width; a bump does not. So a terminal branch reaching less than 1.5 r + 2 px is a
// spur (h < r / 2, plus the outline's 1-px steps). A rectangle's corners are
// the same case: their diagonal branches are sqrt(2) r long, so a rectangle's skeleton is its
// mid line. Pruning removes every spur found, closes the pinholes a junction's pixels can leave
// round a background pixel, thins again, and repeats (a spur removed can leave another
// exposed) until none is left.
//
// Graph. Pixels with one neighbour are end points; pixels with three or more are junction
// pixels, clustered 8-connectedly into one junction node. Edges are traced from each node
// along two-neighbour pixels to the next node; a closed loop with no node gets one at its first
// pixel in raster order. The inscribed radius along each edge is the Euclidean distance
// transform of the mask.
#include "motion/skeleton.h"

#include <algorithm>
#include <limits>
#include <array>
#include <cmath>
#include <stdexcept>

#include <opencv2/imgproc.hpp>

namespace svgm::motion {

namespace {

// Neighbour offsets in Zhang-Suen's order: P2 (N), P3 (NE), P4 (E) ... P9 (NW).
constexpr std::array<int, 8> kDx = {0, 1, 1, 1, 0, -1, -1, -1};
constexpr std::array<int, 8> kDy = {-1, -1, 0, 1, 1, 1, 0, -1};

int ring_bits(const cv::Mat& m, int x, int y) {
  int bits = 0;
  for (int k = 0; k < 8; ++k)
    if (m.at<uchar>(y + kDy[k], x + kDx[k])) bits |= 1 << k;
  return bits;
}

// 8-connected components among the set ring positions: consecutive positions touch, and so do
// two 4-neighbours one step apart round the ring (N and E meet at a corner).
int ring_components(int bits) {
  std::array<int, 8> parent{};
  for (int k = 0; k < 8; ++k) parent[k] = k;
  auto find = [&](int k) {
    while (parent[k] != k) k = parent[k];
    return k;
  };
  auto join = [&](int a, int b) {
    if ((bits >> a & 1) && (bits >> b & 1)) parent[find(a)] = find(b);
  };
  for (int k = 0; k < 8; ++k) join(k, (k + 1) % 8);
  for (int k = 0; k < 8; k += 2) join(k, (k + 2) % 8);
  int n = 0;
  for (int k = 0; k < 8; ++k) n += (bits >> k & 1) && find(k) == k;
  return n;
}

// Removes staircase pixels (see the essay): sequential, raster order, until nothing changes.
void clean_staircases(cv::Mat& m) {
  for (bool changed = true; changed;) {
    changed = false;
    for (int y = 1; y < m.rows - 1; ++y)
      for (int x = 1; x < m.cols - 1; ++x) {
        if (!m.at<uchar>(y, x)) continue;
        const int b = ring_bits(m, x, y);
        const bool n = b & 1, e = b & 4, s = b & 16, w = b & 64;
        const bool corner = (n && e) || (e && s) || (s && w) || (w && n);
        if (corner && __builtin_popcount(b) >= 2 && ring_components(b) == 1) {
          m.at<uchar>(y, x) = 0;
          changed = true;
        }
      }
  }
}

int step_count(cv::Mat& m, int sub) {
  std::vector<cv::Point> marked;
  for (int y = 1; y < m.rows - 1; ++y)
    for (int x = 1; x < m.cols - 1; ++x) {
      if (!m.at<uchar>(y, x)) continue;
      const int b = ring_bits(m, x, y);
      const int count = __builtin_popcount(b);
      int transitions = 0;
      for (int k = 0; k < 8; ++k) transitions += !(b >> k & 1) && (b >> ((k + 1) % 8) & 1);
      if (count < 2 || count > 6 || transitions != 1) continue;
      const bool p2 = b & 1, p4 = b & 4, p6 = b & 16, p8 = b & 64;
      const bool ok = sub == 0 ? !(p2 && p4 && p6) && !(p4 && p6 && p8) : !(p2 && p4 && p8) && !(p2 && p6 && p8);
      if (ok) marked.emplace_back(x, y);
    }
  for (const auto& p : marked) m.at<uchar>(p) = 0;
  return static_cast<int>(marked.size());
}

// Padded 0/1 copy of a mask (a one-pixel frame of background so 3x3 tests never leave it).
cv::Mat padded_binary(const cv::Mat& mask) {
  cv::Mat b = (mask != 0) / 255, p;
  cv::copyMakeBorder(b, p, 1, 1, 1, 1, cv::BORDER_CONSTANT, 0);
  return p;
}

struct Trace {
  std::vector<cv::Point> pts;  // padded coordinates
  int a = -1, b = -1;
};

// Traces the graph of a one-pixel-wide padded 0/1 image.
void trace_graph(const cv::Mat& sk, std::vector<std::vector<cv::Point>>& node_pixels, std::vector<Trace>& traces) {
  cv::Mat degree(sk.size(), CV_8U, cv::Scalar(0));
  for (int y = 1; y < sk.rows - 1; ++y)
    for (int x = 1; x < sk.cols - 1; ++x)
      if (sk.at<uchar>(y, x)) degree.at<uchar>(y, x) = static_cast<uchar>(__builtin_popcount(ring_bits(sk, x, y)));
  cv::Mat node_of(sk.size(), CV_32S, cv::Scalar(-1));
  // Junction pixels, clustered 8-connectedly; then ends and lone pixels, each its own node.
  cv::Mat junction = (degree >= 3) & (sk != 0), jl;
  const int nj = cv::connectedComponents(junction, jl, 8, CV_32S);
  std::vector<int> cluster_node(nj, -1);
  for (int y = 0; y < sk.rows; ++y)
    for (int x = 0; x < sk.cols; ++x) {
      if (!sk.at<uchar>(y, x)) continue;
      const int d = degree.at<uchar>(y, x);
      int id = -1;
      if (d >= 3) {
        int& c = cluster_node[jl.at<int>(y, x)];
        if (c < 0) {
          c = static_cast<int>(node_pixels.size());
          node_pixels.emplace_back();
        }
        id = c;
      } else if (d <= 1) {
        id = static_cast<int>(node_pixels.size());
        node_pixels.emplace_back();
      }
      if (id >= 0) {
        node_of.at<int>(y, x) = id;
        node_pixels[id].emplace_back(x, y);
      }
    }
  cv::Mat visited(sk.size(), CV_8U, cv::Scalar(0));
  auto walk = [&](int start, cv::Point from, cv::Point first) {
    Trace t;
    t.a = start;
    t.pts = {from, first};
    cv::Point prev = from, cur = first;
    while (true) {
      const int here = node_of.at<int>(cur);
      if (here >= 0 && !(here == start && t.pts.size() < 4)) {
        t.b = here;
        break;
      }
      visited.at<uchar>(cur) = 1;
      cv::Point next(-1, -1);
      bool next_is_node = false;
      for (int k = 0; k < 8; ++k) {
        const cv::Point q(cur.x + kDx[k], cur.y + kDy[k]);
        if (q == prev || !sk.at<uchar>(q)) continue;
        const int qn = node_of.at<int>(q);
        if (qn == start && t.pts.size() < 4) continue;
        if (qn >= 0 && !next_is_node) {
          next = q;
          next_is_node = true;
        } else if (qn < 0 && next.x < 0 && !visited.at<uchar>(q)) {
          next = q;
        }
      }
      if (next.x < 0) {  // a dead end left by pruning: make it an end node
        t.b = static_cast<int>(node_pixels.size());
        node_pixels.push_back({cur});
        node_of.at<int>(cur) = t.b;
        break;
      }
      prev = cur;
      cur = next;
      t.pts.push_back(cur);
    }
    traces.push_back(std::move(t));
  };
  auto trace_from = [&](int n) {
    for (size_t i = 0; i < node_pixels[n].size(); ++i) {
      const cv::Point p = node_pixels[n][i];
      for (int k = 0; k < 8; ++k) {
        const cv::Point q(p.x + kDx[k], p.y + kDy[k]);
        if (!sk.at<uchar>(q)) continue;
        const int qn = node_of.at<int>(q);
        if (qn == n) continue;
        if (qn >= 0) {  // two nodes touching: one edge per pair, from the lower index
          bool seen = false;
          for (const auto& t : traces) seen |= (t.a == n && t.b == qn) || (t.a == qn && t.b == n);
          if (!seen && n < qn) traces.push_back({{p, q}, n, qn});
          continue;
        }
        if (!visited.at<uchar>(q)) walk(n, p, q);
      }
    }
  };
  for (size_t n = 0; n < node_pixels.size(); ++n) trace_from(static_cast<int>(n));
  // Closed loops without a node: one node at the loop's first pixel in raster order.
  for (int y = 1; y < sk.rows - 1; ++y)
    for (int x = 1; x < sk.cols - 1; ++x)
      if (sk.at<uchar>(y, x) && !visited.at<uchar>(y, x) && node_of.at<int>(y, x) < 0) {
        const int n = static_cast<int>(node_pixels.size());
        node_pixels.push_back({cv::Point(x, y)});
        node_of.at<int>(y, x) = n;
        trace_from(n);
      }
}

// A spur removed at a junction can leave its pixels round one background pixel (a diamond):
// a loop the mask does not have. Filling such pinholes and thinning again closes them.
void close_pinholes(cv::Mat& sk) {
  for (int y = 1; y < sk.rows - 1; ++y)
    for (int x = 1; x < sk.cols - 1; ++x)
      if (!sk.at<uchar>(y, x) && sk.at<uchar>(y - 1, x) && sk.at<uchar>(y + 1, x) && sk.at<uchar>(y, x - 1) &&
          sk.at<uchar>(y, x + 1))
        sk.at<uchar>(y, x) = 1;
}

void fill_small_holes(cv::Mat& mask, int max_area) {
  cv::Mat holes = mask == 0, labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(holes, labels, stats, centroids, 4, CV_32S);
  for (int y = 0; y < mask.rows; ++y)
    for (int x = 0; x < mask.cols; ++x) {
      const int l = labels.at<int>(y, x);
      if (l <= 0 || l >= n || stats.at<int>(l, cv::CC_STAT_AREA) >= max_area) continue;
      const int* s = stats.ptr<int>(l);
      const bool border = s[cv::CC_STAT_LEFT] == 0 || s[cv::CC_STAT_TOP] == 0 ||
                          s[cv::CC_STAT_LEFT] + s[cv::CC_STAT_WIDTH] == mask.cols ||
                          s[cv::CC_STAT_TOP] + s[cv::CC_STAT_HEIGHT] == mask.rows;
      if (!border) mask.at<uchar>(y, x) = 255;
    }
}

}  // namespace

cv::Mat thin(const cv::Mat& mask) {
  cv::Mat m = padded_binary(mask);
  while (step_count(m, 0) + step_count(m, 1) > 0) {
  }
  clean_staircases(m);
  return m(cv::Rect(1, 1, mask.cols, mask.rows)).clone() * 255;
}

Skeleton skeletonise(const cv::Mat& mask_in, const SkeletonOptions& options) {
  if (mask_in.type() != CV_8UC1 || mask_in.empty())
    throw std::invalid_argument("skeletonise: the mask must be a non-empty CV_8U image");
  Skeleton s;
  s.width = mask_in.cols;
  s.height = mask_in.rows;
  cv::Mat mask = (mask_in != 0);
  fill_small_holes(mask, options.min_component_area);
  // Components, dropping specks.
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(mask, labels, stats, centroids, 8, CV_32S);
  std::vector<int> index(n, -1);
  for (int l = 1; l < n; ++l)
    if (stats.at<int>(l, cv::CC_STAT_AREA) >= options.min_component_area) {
      index[l] = static_cast<int>(s.component_area.size());
      s.component_area.push_back(stats.at<int>(l, cv::CC_STAT_AREA));
    }
  s.labels = cv::Mat(mask.size(), CV_32S, cv::Scalar(-1));
  for (int y = 0; y < mask.rows; ++y)
    for (int x = 0; x < mask.cols; ++x) {
      const int c = index[labels.at<int>(y, x)];
      s.labels.at<int>(y, x) = c;
      if (c < 0) mask.at<uchar>(y, x) = 0;
    }
  cv::distanceTransform(mask, s.distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);

  cv::Mat sk = padded_binary(thin(mask));
  auto radius_at = [&](cv::Point p) { return static_cast<double>(s.distance.at<float>(p.y - 1, p.x - 1)); };
  std::vector<std::vector<cv::Point>> node_pixels;
  std::vector<Trace> traces;
  for (int round = 0; round < 64; ++round) {
    node_pixels.clear();
    traces.clear();
    trace_graph(sk, node_pixels, traces);
    std::vector<int> degree(node_pixels.size(), 0);
    for (const auto& t : traces) ++degree[t.a], ++degree[t.b];
    int pruned = 0;
    for (const auto& t : traces) {
      const bool a_end = degree[t.a] == 1, b_end = degree[t.b] == 1;
      if (a_end == b_end || degree[a_end ? t.b : t.a] < 3) continue;
      const int junction = a_end ? t.b : t.a;
      double r = 0;
      for (const auto& p : node_pixels[junction]) r = std::max(r, radius_at(p));
      double length = 0;
      for (size_t i = 1; i < t.pts.size(); ++i) length += cv::norm(t.pts[i] - t.pts[i - 1]);
      const double reach = length + radius_at(a_end ? t.pts.front() : t.pts.back());
      if (reach >= options.spur_ratio * r + options.spur_slack) continue;
      for (const auto& p : t.pts) {
        bool at_junction = false;
        for (const auto& q : node_pixels[junction]) at_junction |= p == q;
        if (!at_junction) sk.at<uchar>(p) = 0;
      }
      ++pruned;
    }
    if (pruned == 0) break;
    s.spurs_pruned += pruned;
    close_pinholes(sk);
    sk = padded_binary(thin(sk(cv::Rect(1, 1, s.width, s.height))));
  }

  s.pixels = sk(cv::Rect(1, 1, s.width, s.height)).clone() * 255;
  for (const auto& px : node_pixels) {
    SkeletonNode node;
    for (const auto& p : px) {
      node.pos = node.pos + Vec2{p.x - 1.0, p.y - 1.0};
      node.radius = std::max(node.radius, radius_at(p));
    }
    node.pos = (1.0 / static_cast<double>(px.size())) * node.pos;
    node.component = s.labels.at<int>(px[0].y - 1, px[0].x - 1);
    s.nodes.push_back(node);
  }
  for (const auto& t : traces) {
    SkeletonEdge e;
    e.a = t.a;
    e.b = t.b;
    e.min_radius = 1e300;
    for (size_t i = 0; i < t.pts.size(); ++i) {
      const cv::Point p = t.pts[i];
      e.points.push_back({p.x - 1.0, p.y - 1.0});
      e.radius.push_back(radius_at(p));
      e.mean_radius += e.radius.back();
      e.min_radius = std::min(e.min_radius, e.radius.back());
      e.max_radius = std::max(e.max_radius, e.radius.back());
      if (i > 0) e.length += cv::norm(t.pts[i] - t.pts[i - 1]);
    }
    e.mean_radius /= static_cast<double>(t.pts.size());
    const size_t k = std::clamp<size_t>(t.pts.size() / 4, 1, 8), last = t.pts.size() - 1;
    auto unit = [](Vec2 v) {
      const double l = std::hypot(v.x, v.y);
      return l > 0 ? (1.0 / l) * v : Vec2{};
    };
    e.dir_a = unit(e.points[std::min(k, last)] - e.points[0]);
    e.dir_b = unit(e.points[last - std::min(k, last)] - e.points[last]);
    const int idx = static_cast<int>(s.edges.size());
    s.nodes[t.a].edges.push_back(idx);
    s.nodes[t.b].edges.push_back(idx);
    s.edges.push_back(std::move(e));
  }
  for (auto& e : s.edges) e.terminal = s.nodes[e.a].end() || s.nodes[e.b].end();
  return s;
}

SkeletonPaths shortest_paths(const Skeleton& s, int from, const std::vector<int>* edges) {
  const double inf = std::numeric_limits<double>::infinity();
  SkeletonPaths p{std::vector<double>(s.nodes.size(), inf), std::vector<int>(s.nodes.size(), -1)};
  std::vector<char> done(s.nodes.size(), 0);
  p.dist[from] = 0;
  for (;;) {
    int u = -1;  // the nearest unsettled node (the lowest index among equals: deterministic)
    for (size_t n = 0; n < s.nodes.size(); ++n)
      if (!done[n] && p.dist[n] < inf && (u < 0 || p.dist[n] < p.dist[u])) u = static_cast<int>(n);
    if (u < 0) break;
    done[u] = 1;
    for (int e : edges ? *edges : s.nodes[u].edges) {
      const auto& E = s.edges[e];
      if (E.a != u && E.b != u) continue;
      const int v = E.a == u ? E.b : E.a;
      if (p.dist[u] + E.length < p.dist[v]) p.dist[v] = p.dist[u] + E.length, p.via[v] = e;
    }
  }
  return p;
}

std::vector<int> SkeletonPaths::edges_to(const Skeleton& s, int to) const {
  std::vector<int> out;
  for (int n = to; via[n] >= 0; n = s.edges[via[n]].a == n ? s.edges[via[n]].b : s.edges[via[n]].a) out.push_back(via[n]);
  std::reverse(out.begin(), out.end());
  return out;
}

}  // namespace svgm::motion
