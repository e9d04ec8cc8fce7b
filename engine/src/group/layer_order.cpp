// The painter's order of groups from occlusion evidence (see layer_order.h).
#include "group/layer_order.h"
#include "svgmotion/atomic_file.h"


#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <pugixml.hpp>
#include <queue>
#include <set>
#include <sstream>
#include <string_view>

#include "color/palette_json.h"
#include "svg/document_order.h"
#include "svgmotion/error.h"
#include "svgmotion/render_size.h"
#include "svgmotion/svg_reader.h"
#include "svgmotion/utf8_text.h"

namespace svgm {

namespace fs = std::filesystem;

namespace {

constexpr int kChords = 16;  // chords per cubic when flattening for coverage

// The subpath's cubics as a polyline in pixel space (first point repeated at the end when
// `close`).
std::vector<Vec2> flatten(const Subpath& s, const Affine& view, bool close) {
  std::vector<Vec2> out;
  if (s.points.empty()) return out;
  out.push_back(view.apply(s.points[0]));
  for (size_t k = 0; k < s.segment_count(); ++k) {
    const Vec2 p0 = s.points[3 * k], p1 = s.points[3 * k + 1], p2 = s.points[3 * k + 2],
               p3 = s.points[3 * k + 3];
    for (int i = 1; i <= kChords; ++i) {
      const double t = static_cast<double>(i) / kChords, u = 1 - t;
      const Vec2 p = (u * u * u) * p0 + (3 * u * u * t) * p1 + (3 * u * t * t) * p2 + (t * t * t) * p3;
      out.push_back(view.apply(p));
    }
  }
  if (close && out.size() > 1 && !(out.front() == out.back())) out.push_back(out.front());
  return out;
}

// Marks the pixels whose centre is inside the fill of `polys` (closed polylines) under `rule`.
void fill_coverage(const std::vector<std::vector<Vec2>>& polys, FillRule rule, int w, int h,
                   std::vector<uint8_t>& mask) {
  double ymin = 1e300, ymax = -1e300;
  for (const auto& poly : polys)
    for (const Vec2& p : poly) ymin = std::min(ymin, p.y), ymax = std::max(ymax, p.y);
  if (ymin > ymax) return;
  const int r0 = std::max(0, static_cast<int>(std::floor(ymin - 0.5)));
  const int r1 = std::min(h - 1, static_cast<int>(std::ceil(ymax - 0.5)));
  std::vector<std::pair<double, int>> xs;
  for (int row = r0; row <= r1; ++row) {
    const double yc = row + 0.5;
    xs.clear();
    for (const auto& poly : polys)
      for (size_t i = 0; i + 1 < poly.size(); ++i) {
        const Vec2 a = poly[i], b = poly[i + 1];
        if ((a.y <= yc && yc < b.y) || (b.y <= yc && yc < a.y)) {
          const double x = a.x + (yc - a.y) * (b.x - a.x) / (b.y - a.y);
          xs.push_back({x, b.y > a.y ? 1 : -1});
        }
      }
    std::sort(xs.begin(), xs.end());
    int wind = 0;
    for (size_t i = 0; i + 1 < xs.size(); ++i) {
      wind += xs[i].second;
      const bool inside = rule == FillRule::EvenOdd ? (wind & 1) != 0 : wind != 0;
      if (!inside) continue;
      // pixel centres col + 0.5 in [x_i, x_{i+1})
      const int c0 = std::max(0, static_cast<int>(std::ceil(xs[i].first - 0.5)));
      const int c1 = std::min(w - 1, static_cast<int>(std::ceil(xs[i + 1].first - 0.5)) - 1);
      for (int c = c0; c <= c1; ++c) mask[static_cast<size_t>(row) * w + c] = 1;
    }
  }
}

// Marks the pixels whose centre is within `hw` of a segment of `poly`.
void stroke_coverage(const std::vector<Vec2>& poly, double hw, int w, int h,
                     std::vector<uint8_t>& mask) {
  for (size_t i = 0; i < poly.size(); ++i) {
    const Vec2 a = poly[i], b = i + 1 < poly.size() ? poly[i + 1] : poly[i];
    if (i + 1 == poly.size() && poly.size() > 1) break;  // single points only when alone
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min(a.x, b.x) - hw)));
    const int x1 = std::min(w - 1, static_cast<int>(std::ceil(std::max(a.x, b.x) + hw)));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min(a.y, b.y) - hw)));
    const int y1 = std::min(h - 1, static_cast<int>(std::ceil(std::max(a.y, b.y) + hw)));
    const Vec2 d = b - a;
    const double dd = d.x * d.x + d.y * d.y;
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const Vec2 p{x + 0.5, y + 0.5};
        const Vec2 ap = p - a;
        const double t = dd > 0 ? std::clamp((ap.x * d.x + ap.y * d.y) / dd, 0.0, 1.0) : 0.0;
        const Vec2 q = ap - t * d;
        if (q.x * q.x + q.y * q.y <= hw * hw) mask[static_cast<size_t>(y) * w + x] = 1;
      }
  }
}

std::string_view local_name(const char* name) {
  std::string_view s = name;
  const size_t colon = s.find(':');
  return colon == std::string_view::npos ? s : s.substr(colon + 1);
}

bool drawable(std::string_view tag) {
  static const std::set<std::string_view> tags = {"g",        "path",    "rect",    "circle", "ellipse",
                                                  "line",     "polyline", "polygon", "use"};
  return tags.count(tag) != 0;
}

// The end (one past '>') of the element whose start tag opens at text[begin] == '<', in
// well-formed XML; npos when the text ends first.
size_t element_end(const std::string& text, size_t begin) {
  constexpr size_t npos = std::string::npos;
  int depth = 0;
  size_t pos = begin;
  auto skip_past = [&](size_t from, std::string_view what) {
    const size_t k = text.find(what, from);
    return k == npos ? npos : k + what.size();
  };
  while (pos != npos && pos < text.size()) {
    pos = text.find('<', pos);
    if (pos == npos) return npos;
    if (text.compare(pos, 4, "<!--") == 0) {
      pos = skip_past(pos + 4, "-->");
    } else if (text.compare(pos, 9, "<![CDATA[") == 0) {
      pos = skip_past(pos + 9, "]]>");
    } else if (text.compare(pos, 2, "<?") == 0) {
      pos = skip_past(pos + 2, "?>");
    } else if (text.compare(pos, 2, "</") == 0) {
      pos = skip_past(pos + 2, ">");
      if (--depth == 0) return pos;
    } else {  // a start tag: find its '>' outside quoted attribute values
      char quote = 0;
      size_t k = pos + 1;
      for (; k < text.size(); ++k) {
        const char ch = text[k];
        if (quote) {
          if (ch == quote) quote = 0;
        } else if (ch == '"' || ch == '\'') {
          quote = ch;
        } else if (ch == '>') {
          break;
        }
      }
      if (k >= text.size()) return npos;
      const bool empty = text[k - 1] == '/';
      pos = k + 1;
      if (!empty) ++depth;
      else if (depth == 0) return pos;
    }
  }
  return npos;
}

void copy_atomic(const fs::path& from, const fs::path& to) {
  std::ifstream f(from, std::ios::binary);
  if (!f) throw Error(from.string() + ": cannot open: " + std::strerror(errno));
  std::ostringstream s;
  s << f.rdbuf();
  write_file_atomic(to, s.str());
}

}  // namespace

std::vector<std::vector<uint8_t>> group_coverage(const Scene& scene, const Affine& view, int width,
                                                 int height) {
  const size_t npx = static_cast<size_t>(width) * height;
  std::vector<std::vector<uint8_t>> cov(scene.groups.size(), std::vector<uint8_t>(npx, 0));
  const double scale = view.mean_scale();
  for (size_t g = 0; g < scene.groups.size(); ++g)
    for (int pi : scene.groups[g].paths) {
      const Path& p = scene.paths[static_cast<size_t>(pi)];
      if (p.opacity <= 0) continue;
      if (p.has_fill && p.fill.a > 0) {
        std::vector<std::vector<Vec2>> polys;
        for (const Subpath& s : p.subpaths) polys.push_back(flatten(s, view, true));
        fill_coverage(polys, p.fill_rule, width, height, cov[g]);
      }
      if (p.has_stroke && p.stroke.color.a > 0 && p.stroke.width > 0)
        for (const Subpath& s : p.subpaths)
          stroke_coverage(flatten(s, view, s.closed), 0.5 * p.stroke.width * scale, width, height,
                          cov[g]);
    }
  return cov;
}

std::vector<int> label_frames(const Scene& scene, const std::map<std::string, Rgba>& palette,
                              const TargetFrames& target, double color_threshold) {
  // Palette colours (as 8-bit triples, so equal hex colours merge) -> owning group, or -2 when
  // shared by several groups.
  std::map<std::array<int, 3>, int> owner;
  auto key = [](const Rgba& c) {
    auto v = [](float x) { return static_cast<int>(std::lround(std::clamp(x, 0.f, 1.f) * 255)); };
    return std::array<int, 3>{v(c.r), v(c.g), v(c.b)};
  };
  for (const Path& p : scene.paths) {
    if (p.group < 0) continue;
    const auto it = palette.find(p.id);
    const Rgba c = it != palette.end() ? it->second : p.has_fill ? p.fill : p.stroke.color;
    const auto [o, fresh] = owner.emplace(key(c), p.group);
    if (!fresh && o->second != p.group) o->second = -2;
  }
  std::vector<std::array<float, 3>> colors;
  std::vector<int> groups;
  for (const auto& [k, g] : owner) {
    colors.push_back({k[0] / 255.f, k[1] / 255.f, k[2] / 255.f});
    groups.push_back(g);
  }
  const size_t npx = static_cast<size_t>(target.width) * target.height;
  const size_t total = npx * static_cast<size_t>(target.keyframes);
  std::vector<int> labels(total, -1);
  const float t2 = static_cast<float>(color_threshold * color_threshold);
  for (size_t i = 0; i < total; ++i) {
    if (!target.mask[i]) continue;
    const float* px = &target.rgba[4 * i];
    float best = 1e30f;
    int label = -1;
    for (size_t c = 0; c < colors.size(); ++c) {
      const float dr = px[0] - colors[c][0], dg = px[1] - colors[c][1], db = px[2] - colors[c][2];
      const float d = dr * dr + dg * dg + db * db;
      if (d < best) best = d, label = groups[c];
    }
    if (best <= t2 && label >= 0) labels[i] = label;
  }
  return labels;
}

std::vector<LayerPair> overlap_evidence(const std::vector<std::vector<uint8_t>>& coverage,
                                        const std::vector<int>& labels, int keyframes,
                                        const LayerOptions& options) {
  const size_t n = coverage.size();
  if (n < 2) return {};
  const size_t npx = coverage[0].size();
  // counts[x * n + y]: overlap pixels of (x, y) labelled x; overlap[x * n + y]: overlap area.
  std::vector<long> counts(n * n, 0), overlap(n * n, 0);
  std::vector<int> cover;
  for (size_t i = 0; i < npx; ++i) {
    cover.clear();
    for (size_t g = 0; g < n; ++g)
      if (coverage[g][i]) cover.push_back(static_cast<int>(g));
    if (cover.size() < 2) continue;
    for (int x : cover)
      for (int y : cover)
        if (x != y) ++overlap[static_cast<size_t>(x) * n + y];
    for (int k = 0; k < keyframes; ++k) {
      const int l = labels[static_cast<size_t>(k) * npx + i];
      if (l < 0 || std::find(cover.begin(), cover.end(), l) == cover.end()) continue;
      for (int y : cover)
        if (y != l) ++counts[static_cast<size_t>(l) * n + y];
    }
  }
  std::vector<LayerPair> pairs;
  for (size_t a = 0; a < n; ++a)
    for (size_t b = a + 1; b < n; ++b) {
      if (overlap[a * n + b] == 0) continue;
      LayerPair p;
      p.a = static_cast<int>(a);
      p.b = static_cast<int>(b);
      p.overlap_pixels = overlap[a * n + b];
      p.a_pixels = counts[a * n + b];
      p.b_pixels = counts[b * n + a];
      const long sum = p.a_pixels + p.b_pixels;
      p.score = sum > 0 ? static_cast<double>(p.a_pixels - p.b_pixels) / static_cast<double>(sum) : 0.0;
      // Strong evidence only: enough labelled pixels in absolute terms and as a share of what
      // the overlap offers over the keyframes (dolphin2's eye: 8 pixels of a 15-keyframe
      // overlap are noise, not occlusion).
      const double offered = static_cast<double>(p.overlap_pixels) * std::max(1, keyframes);
      p.confident = sum >= options.min_pixels && sum >= options.min_evidence_share * offered &&
                    std::fabs(p.score) > options.min_score;
      pairs.push_back(p);
    }
  return pairs;
}

std::vector<int> order_groups(const std::vector<std::string>& ids, std::vector<LayerPair>& pairs,
                              std::optional<std::string>* fallback) {
  const size_t N = ids.size();
  // Edge back -> front: `back` must be painted before `front`.
  auto back_front = [](const LayerPair& p) {
    return p.score > 0 ? std::pair{p.b, p.a} : std::pair{p.a, p.b};
  };
  std::vector<std::vector<int>> adj(N);
  for (const LayerPair& p : pairs)
    if (p.confident) {
      const auto [u, v] = back_front(p);
      adj[static_cast<size_t>(u)].push_back(v);
    }
  // Reachability (n is small: a drawing's parts).
  std::vector<std::vector<uint8_t>> reach(N, std::vector<uint8_t>(N, 0));
  for (size_t s = 0; s < N; ++s) {
    std::vector<int> stack = {static_cast<int>(s)};
    while (!stack.empty()) {
      const int u = stack.back();
      stack.pop_back();
      for (int v : adj[static_cast<size_t>(u)])
        if (!reach[s][static_cast<size_t>(v)]) reach[s][static_cast<size_t>(v)] = 1, stack.push_back(v);
    }
  }
  // Strongly connected components with a cycle: comp[i] = smallest member, or -1 when acyclic.
  std::vector<int> comp(N, -1);
  for (size_t i = 0; i < N; ++i)
    for (size_t j = 0; j < N; ++j)
      if (reach[i][j] && reach[j][i]) {
        comp[i] = static_cast<int>(j);
        break;
      }
  std::vector<std::vector<int>> edges(N);
  std::map<int, std::vector<int>> cycles;
  for (size_t i = 0; i < N; ++i)
    if (comp[i] >= 0) cycles[comp[i]].push_back(static_cast<int>(i));
  for (LayerPair& p : pairs) {
    p.used = false;
    if (!p.confident) continue;
    const auto [u, v] = back_front(p);
    if (comp[static_cast<size_t>(u)] >= 0 && comp[static_cast<size_t>(u)] == comp[static_cast<size_t>(v)])
      continue;  // inside a cycle: dropped
    edges[static_cast<size_t>(u)].push_back(v);
    p.used = true;
  }
  for (const auto& [c, members] : cycles) {
    // members are in increasing (original) order: chain them so they keep it.
    for (size_t k = 0; k + 1 < members.size(); ++k)
      edges[static_cast<size_t>(members[k])].push_back(members[k + 1]);
  }
  std::vector<int> indeg(N, 0);
  for (const auto& e : edges)
    for (int v : e) ++indeg[static_cast<size_t>(v)];
  std::priority_queue<int, std::vector<int>, std::greater<int>> ready;
  for (size_t i = 0; i < N; ++i)
    if (indeg[i] == 0) ready.push(static_cast<int>(i));
  std::vector<int> order;
  while (!ready.empty()) {
    const int u = ready.top();
    ready.pop();
    order.push_back(u);
    for (int v : edges[static_cast<size_t>(u)])
      if (--indeg[static_cast<size_t>(v)] == 0) ready.push(v);
  }
  if (order.size() != N) {  // cannot happen (the condensation is acyclic); be safe
    order.resize(N);
    for (size_t i = 0; i < N; ++i) order[i] = static_cast<int>(i);
    for (LayerPair& p : pairs) p.used = false;
    *fallback = "internal: the constraints stayed cyclic; original order kept";
    return order;
  }
  if (!cycles.empty()) {
    std::string s = "cyclic evidence: ";
    bool first = true;
    for (const auto& [c, members] : cycles) {
      s += first ? "" : "; ";
      first = false;
      s += "groups";
      for (int m : members) s += " " + ids[static_cast<size_t>(m)];
      s += " keep their original relative order (the evidence among them was dropped)";
    }
    *fallback = s;
  } else {
    fallback->reset();
  }
  return order;
}

LayerResult compute_layer_order(const Scene& scene, const std::map<std::string, Rgba>& palette,
                                const TargetFrames& target, const LayerOptions& options) {
  LayerResult r;
  const int n = static_cast<int>(scene.groups.size());
  for (const Group& g : scene.groups) r.group_ids.push_back(g.id);
  const RenderSize size = render_size(scene, target.width);
  if (size.width != target.width || size.height != target.height)
    throw Error("layers: target is " + std::to_string(target.width) + "x" +
                std::to_string(target.height) + " but the SVG renders at " +
                std::to_string(size.width) + "x" + std::to_string(size.height));
  r.keyframes = target.keyframes;
  r.width = size.width;
  r.height = size.height;
  const auto cov = group_coverage(scene, size.view, size.width, size.height);
  const auto labels = label_frames(scene, palette, target, options.color_threshold);
  r.pairs = overlap_evidence(cov, labels, target.keyframes, options);
  r.order = order_groups(r.group_ids, r.pairs, &r.fallback);
  for (int i = 0; i < n; ++i) r.changed = r.changed || r.order[static_cast<size_t>(i)] != i;
  return r;
}

bool write_layered_svg(const fs::path& in, const std::vector<std::string>& order_ids,
                       const fs::path& out) {
  std::ifstream f(in, std::ios::binary);
  if (!f) throw Error(in.string() + ": cannot open: " + std::strerror(errno));
  const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  pugi::xml_document doc;
  const pugi::xml_parse_result res =
      doc.load_buffer(text.data(), text.size(), pugi::parse_default, pugi::encoding_utf8);
  if (!res) throw Error(in.string() + ": cannot parse: " + res.description());
  pugi::xml_node root = doc.document_element();
  std::map<std::string, size_t> rank;
  for (size_t i = 0; i < order_ids.size(); ++i) rank[order_ids[i]] = i;
  struct Span {
    size_t begin = 0, end = 0;
  };
  std::vector<Span> slots;  // matched elements' text, in document order
  std::vector<std::vector<Span>> by_group(order_ids.size());
  for (pugi::xml_node c = root.first_child(); c; c = c.next_sibling()) {
    if (c.type() != pugi::node_element || !drawable(local_name(c.name()))) continue;
    std::string key = local_name(c.name()) == "g" ? c.attribute("data-group").value() : "";
    if (key.empty()) key = c.attribute("id").value();
    const auto it = rank.find(key);
    if (it == rank.end()) continue;  // not a group of the scene (e.g. empty): stays in place
    const ptrdiff_t name_at = c.offset_debug();
    const std::string_view name = c.name();
    if (name_at < 1 || text.compare(static_cast<size_t>(name_at), name.size(), name) != 0 ||
        text[static_cast<size_t>(name_at) - 1] != '<')
      return false;
    const Span span{static_cast<size_t>(name_at) - 1, element_end(text, static_cast<size_t>(name_at) - 1)};
    if (span.end == std::string::npos || (!slots.empty() && span.begin < slots.back().end)) return false;
    slots.push_back(span);
    by_group[it->second].push_back(span);
  }
  for (const auto& g : by_group)
    if (g.empty()) return false;
  std::vector<Span> placed;
  for (const auto& g : by_group) placed.insert(placed.end(), g.begin(), g.end());
  // The original text with slot i replaced by the text of placed[i].
  std::string result;
  result.reserve(text.size());
  size_t at = 0;
  for (size_t i = 0; i < slots.size(); ++i) {
    result.append(text, at, slots[i].begin - at);
    result.append(text, placed[i].begin, placed[i].end - placed[i].begin);
    at = slots[i].end;
  }
  result.append(text, at, std::string::npos);
  write_file_atomic(out, result);
  return true;
}

nlohmann::json layers_json(const LayerResult& r, const LayerOptions& o) {
  nlohmann::json order = nlohmann::json::array(), original = nlohmann::json::array(),
                 pairs = nlohmann::json::array();
  for (int i : r.order) order.push_back(r.group_ids[static_cast<size_t>(i)]);
  for (const std::string& id : r.group_ids) original.push_back(id);
  for (const LayerPair& p : r.pairs) {
    const std::string& a = r.group_ids[static_cast<size_t>(p.a)];
    const std::string& b = r.group_ids[static_cast<size_t>(p.b)];
    nlohmann::json j = {{"a", a},
                        {"b", b},
                        {"overlap_pixels", p.overlap_pixels},
                        {"a_pixels", p.a_pixels},
                        {"b_pixels", p.b_pixels},
                        {"score", p.score},
                        {"confident", p.confident},
                        {"used", p.used}};
    if (p.confident) j["front"] = p.score > 0 ? a : b;
    pairs.push_back(j);
  }
  return {{"order", order},
          {"order_direction", "back_to_front"},
          {"original_order", original},
          {"changed", r.changed},
          {"pairs", pairs},
          {"analysed", {{"keyframes", r.keyframes}, {"width", r.width}, {"height", r.height}}},
          {"fallback", r.fallback ? nlohmann::json(*r.fallback) : nlohmann::json(nullptr)},
          {"document_moves", r.document_moves},
          {"method",
           "pair (a, b), a painted first originally: pixels of the rest-pose overlap of a and b "
           "labelled a / b (nearest palette colour) over the keyframes; score = (a - b) / (a + b), "
           "> 0: a in front; used when a + b >= min_pixels, a + b >= min_evidence_share * overlap * "
           "keyframes and |score| > min_score; order = stable topological sort, groups in a cycle "
           "keep their original relative order; a new order is kept only when no group loses more "
           "than max_hidden_share of its visible rest-pose pixels and the user's document can take "
           "it by moving elements within their parents (document_moves = elements moved)"},
          {"options",
           {{"keyframes", o.keyframes},
            {"width", o.width},
            {"color_threshold", o.color_threshold},
            {"min_pixels", o.min_pixels},
            {"min_score", o.min_score},
            {"min_evidence_share", o.min_evidence_share},
            {"max_hidden_share", o.max_hidden_share}}}};
}

// Pixels of each group visible at rest (on top of every other group covering them) when the
// groups are painted in `order` (back to front).
std::vector<long> visible_at_rest(const std::vector<std::vector<uint8_t>>& cov, const std::vector<int>& order) {
  std::vector<long> vis(cov.size(), 0);
  if (cov.empty()) return vis;
  for (size_t i = 0; i < cov[0].size(); ++i)
    for (size_t t = order.size(); t-- > 0;)
      if (cov[static_cast<size_t>(order[t])][i]) {
        ++vis[static_cast<size_t>(order[t])];
        break;
      }
  return vis;
}

LayerResult run_layers(const fs::path& svg, const fs::path& target, const fs::path& palette_file,
                       const fs::path& out_svg, const fs::path& out_json, const LayerOptions& options,
                       const std::optional<fs::path>& original) {
  const Scene scene = read_svg_file(svg);
  const std::map<std::string, Rgba> palette = read_palette(palette_file);
  const RenderSize size = render_size(scene, options.width);
  const TargetInfo info = probe_target(target);
  TargetOptions to;
  to.keyframes = std::max(1, std::min(options.keyframes, info.frames));
  to.dilate_px = 0;  // labels, not a loose mask
  const TargetFrames frames = load_target(target, size.width, size.height, to);
  LayerResult r = compute_layer_order(scene, palette, frames, options);
  auto keep_original = [&](const std::string& why) {
    r.order.clear();
    for (size_t i = 0; i < r.group_ids.size(); ++i) r.order.push_back(static_cast<int>(i));
    r.changed = false;
    for (LayerPair& p : r.pairs) p.used = false;
    r.fallback = (r.fallback ? *r.fallback + "; " : std::string()) + why + ": original order kept";
  };
  // The paper's conservative fallback: a new order must not hide what the drawing shows at rest.
  if (r.changed) {
    const auto cov = group_coverage(scene, size.view, size.width, size.height);
    std::vector<int> identity(r.group_ids.size());
    for (size_t i = 0; i < identity.size(); ++i) identity[i] = static_cast<int>(i);
    const auto before = visible_at_rest(cov, identity), after = visible_at_rest(cov, r.order);
    for (size_t g = 0; g < before.size() && r.changed; ++g)
      if (before[g] >= 4 && after[g] < (1 - options.max_hidden_share) * before[g])
        keep_original("the new order would hide " + r.group_ids[g] + " at rest (" + std::to_string(after[g]) +
                      " of its " + std::to_string(before[g]) + " visible pixels left)");
  }
  bool written = false;
  if (r.changed) {
    std::vector<std::string> ids;
    for (int i : r.order) ids.push_back(r.group_ids[static_cast<size_t>(i)]);
    written = write_layered_svg(svg, ids, out_svg);
    if (!written) keep_original("the document's top-level elements do not match its groups");
  }
  // The order must also be one the user's own document can take by moving elements within
  // their parents (document_order.h); the fitter applies it there the same way.
  if (written && original) {
    std::ifstream f(*original, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    const Scene orig = read_svg_string(text, original->string());
    const Scene layered = read_svg_file(out_svg);
    const ReorderResult rr = reorder_document_text(text, original->string(), orig,
                                                   match_paths(layered, orig, out_svg.string()), nullptr);
    if (rr.refused) {
      keep_original("the new order cannot be applied to the original document (" + *rr.refused + ")");
      written = false;
    } else {
      r.document_moves = rr.moved;
    }
  }
  if (!written) copy_atomic(svg, out_svg);
  write_file_atomic(out_json, json_text(layers_json(r, options), 2) + "\n");
  return r;
}

}  // namespace svgm
