// Compositing layers as Lottie precompositions and track mattes (see lottie_compositing.h).
#include "export/lottie_compositing.h"

#include <algorithm>

#include "export/lottie_luma_matte.h"
#include "export/lottie_paint.h"

namespace svgm::lottie {

namespace {

// Layer `ty` codes and matte modes.
constexpr int kPrecompLayer = 0, kShapeLayer = 4;
constexpr int kAlphaMatte = 1, kInvertedAlphaMatte = 2;

class Composer {
 public:
  Composer(const CompositionInputs& in, std::vector<std::string>& approximate)
      : in_(in), scene_(*in.scene), approximate_(approximate), next_ind_(in.next_ind) {}

  CompositionText run() {
    CompositionText out;
    out.layers = join(paths_in_layers(in_.order, /*scene paths*/ nullptr, /*with_nulls*/ true));
    out.assets = std::move(assets_);
    return out;
  }

 private:
  // A tree of compositing layers over paths in paint order: each node is one instance of a
  // layer (a layer whose paths are not contiguous in the paint order gets one per run).
  struct Node {
    int layer = -1;
    std::vector<int> items;  // >= 0: a path index; < 0: -(child node + 1)
  };

  // Paths drawn from outside the scene's list (a mask's content) with the gradients they index.
  struct PathSource {
    const std::vector<Path>* paths;
    const std::vector<Gradient>* gradients;
  };

  // The layers (top first) drawing `paths` (back to front) of the scene's paths (`source`
  // null) or of a mask's content, with their compositing layers as precompositions.
  std::vector<std::string> paths_in_layers(const std::vector<int>& paths, const PathSource* source, bool with_nulls) {
    const std::vector<Path>& all = source ? *source->paths : scene_.paths;
    std::vector<Node> nodes(1);  // nodes[0]: the composition itself
    std::vector<int> open = {0};  // node indices, outermost first
    for (const int p : paths) {
      std::vector<int> chain;  // the path's layers, outermost first
      for (int l = all[static_cast<size_t>(p)].layer; l >= 0; l = scene_.layers[static_cast<size_t>(l)].parent)
        chain.insert(chain.begin(), l);
      size_t keep = 1;  // open nodes that are a prefix of the chain
      while (keep < open.size() && keep - 1 < chain.size() && nodes[static_cast<size_t>(open[keep])].layer == chain[keep - 1])
        ++keep;
      open.resize(keep);
      for (size_t c = keep - 1; c < chain.size(); ++c) {
        nodes.push_back({chain[c], {}});
        const int child = static_cast<int>(nodes.size()) - 1;
        nodes[static_cast<size_t>(open.back())].items.push_back(-(child + 1));
        open.push_back(child);
      }
      nodes[static_cast<size_t>(open.back())].items.push_back(p);
    }
    return node_layers(nodes, 0, source, with_nulls);
  }

  std::vector<std::string> node_layers(const std::vector<Node>& nodes, int n, const PathSource* source, bool with_nulls) {
    std::vector<std::string> out;
    std::vector<bool> groups(scene_.groups.size(), false);
    const Node& node = nodes[static_cast<size_t>(n)];
    for (auto it = node.items.rbegin(); it != node.items.rend(); ++it) {
      if (*it >= 0) {
        if (source) {
          out.push_back(static_path_layer((*source->paths)[static_cast<size_t>(*it)], next_ind_++, *source->gradients, false));
        } else {
          out.push_back(in_.path_layers[static_cast<size_t>(*it)]);
          const int g = in_.path_group[static_cast<size_t>(*it)];
          if (g >= 0) groups[static_cast<size_t>(g)] = true;
        }
        continue;
      }
      const int child = -*it - 1;
      const std::string content = asset(node_layers(nodes, child, source, with_nulls));
      const int layer = nodes[static_cast<size_t>(child)].layer;
      for (std::string& l : layer_instance(scene_.layers[static_cast<size_t>(layer)], content, layer, paths_below(nodes, child) > 1))
        out.push_back(std::move(l));
    }
    // A group's null layer (a handle with the identity transform) beside its paths, in each
    // composition that holds some: a layer's parent must be in its own composition.
    if (with_nulls)
      for (size_t g = 0; g < groups.size(); ++g)
        if (groups[g] && !in_.group_nulls[g].empty()) out.push_back(in_.group_nulls[g]);
    return out;
  }

  // The paths drawn by node `n` and the nodes inside it.
  static int paths_below(const std::vector<Node>& nodes, int n) {
    int count = 0;
    for (const int i : nodes[static_cast<size_t>(n)].items) count += i >= 0 ? 1 : paths_below(nodes, -i - 1);
    return count;
  }

  // The layers (top first) drawing compositing layer `l` whose content is asset `content`.
  //
  // Its group opacity is the outermost layer's opacity, except over content of more than one
  // path: lottie-web's canvas renderer fades each path of a precomposition on its own (its
  // globalAlpha), so overlapping paths would show through each other. There the content is
  // taken through an alpha matte of the whole canvas at that opacity, which every player
  // composites offscreen (the svg renderers and librlottie, ThorVG, fade a precomposition as
  // one either way).
  std::vector<std::string> layer_instance(const Layer& l, const std::string& content, int index, bool many_paths) {
    const std::string name = "layer " + std::to_string(index);
    const bool fade_by_matte = many_paths && l.opacity < 1;
    const float opacity = fade_by_matte ? 1.0f : l.opacity;
    std::vector<std::string> out;
    if (l.clip < 0 && l.mask < 0) {
      out = {precomp_layer(name, content, opacity, 0, false, {})};
    } else {
      std::string masked = content;
      if (l.mask >= 0) {
        out = {mask_matte(l.mask), precomp_layer(name, content, l.clip < 0 ? opacity : 1.0f, kAlphaMatte, false, {})};
        if (l.clip >= 0) masked = asset(out);
      }
      if (l.clip >= 0) out = {clip_matte(l.clip), precomp_layer(name, masked, opacity, kAlphaMatte, false, {})};
    }
    if (!fade_by_matte) return out;
    const std::string faded = out.size() == 1 ? content : asset(out);
    return {opacity_matte(l.opacity), precomp_layer(name, faded, 1, kAlphaMatte, false, {})};
  }

  // A matte (`td` 1) of opacity `o` over the whole canvas: a rectangle one pixel larger on
  // every side, filled opaque, its layer at opacity o.
  std::string opacity_matte(float o) {
    JsonText j(in_.decimals);
    begin_layer(j, next_ind_++, "group opacity", kShapeLayer, o, 0, true);
    const double w = std::max(1.0, scene_.width), h = std::max(1.0, scene_.height);
    j.raw(",\"shapes\":[{\"ty\":\"gr\",\"it\":[{\"ty\":\"rc\",\"p\":{\"a\":0,\"k\":[").coord(w / 2).raw(",");
    j.coord(h / 2).raw("]},\"s\":{\"a\":0,\"k\":[").coord(w + 2).raw(",").coord(h + 2);
    j.raw("]},\"r\":{\"a\":0,\"k\":0}},{\"ty\":\"fl\",\"c\":{\"a\":0,\"k\":[0,0,0,1]},\"o\":{\"a\":0,\"k\":100},\"r\":1,\"bm\":0},");
    j.raw(kGroupTransform).raw("]}]");
    end_layer(j);
    return j.text();
  }

  // The matte layer (`td` 1) of mask `m`, an alpha matte: its content (a luminance mask's
  // rewritten so that alpha is its value) in a precomposition limited to its region.
  std::string mask_matte(int m) {
    const Mask& mask = scene_.masks[static_cast<size_t>(m)];
    std::string content;
    if (mask.luminance) {
      content = luminance_content(mask);
    } else {
      std::vector<int> paths;
      for (size_t i = 0; i < mask.paths.size(); ++i) paths.push_back(static_cast<int>(i));
      const PathSource source = {&mask.paths, &scene_.gradients};
      content = asset(paths_in_layers(paths, &source, false));
    }
    if (mask.mask >= 0)
      content = asset({mask_matte(mask.mask), precomp_layer("mask content", content, 1, kAlphaMatte, false, {})});
    if (mask.region.empty()) content = asset({});  // an empty region: the mask hides everything
    return precomp_layer("mask " + std::to_string(m), content, 1, 0, true, mask.region);
  }

  // A luminance mask's content as an asset whose alpha is the mask's value (lottie_luma_matte.h):
  // its paths white at alpha L a, each black path over earlier ones cutting them as an inverted
  // alpha matte.
  std::string luminance_content(const Mask& mask) {
    const AlphaMatteContent white = luminance_as_alpha(mask, scene_.gradients);
    if (!white.exact) approximate_.push_back("luminance mask of grey shapes over each other drawn as their alpha");
    const PathSource source = {&white.paths, &white.gradients};
    std::vector<std::string> below;  // the layers (top first) of the content so far
    std::vector<int> run;            // paths drawn over `below` since the last cut
    for (size_t i = 0; i <= white.paths.size(); ++i) {
      if (i < white.paths.size() && !white.cut[i]) {
        run.push_back(static_cast<int>(i));
        continue;
      }
      std::vector<std::string> layers = paths_in_layers(run, &source, false);
      layers.insert(layers.end(), below.begin(), below.end());
      below = std::move(layers);
      run.clear();
      if (i == white.paths.size()) break;
      const std::string so_far = asset(below);
      below = {static_path_layer(white.paths[i], next_ind_++, white.gradients, true),
               precomp_layer("cut by " + white.paths[i].id, so_far, 1, kInvertedAlphaMatte, false, {})};
    }
    return asset(below);
  }

  // The matte layer (`td` 1) of clip `c`: its shapes in opaque black.
  std::string clip_matte(int c) {
    const ClipPath& clip = scene_.clips[static_cast<size_t>(c)];
    if (clip.clip < 0) return clip_shapes_layer(clip, true);
    const std::string nested = clip_matte(clip.clip);
    const std::string content = asset({nested, retag_matte(clip_shapes_layer(clip, false), kAlphaMatte)});
    return precomp_layer("clip " + std::to_string(c), content, 1, 0, true, {});
  }

  // A shape layer with `tt` inserted after its "ty" (a layer written by this file).
  static std::string retag_matte(std::string layer, int tt) {
    const size_t at = layer.find(",\"ty\":");
    if (at != std::string::npos) layer.insert(at, ",\"tt\":" + std::to_string(tt));
    return layer;
  }

  std::string clip_shapes_layer(const ClipPath& clip, bool matte) {
    JsonText j(in_.decimals);
    begin_layer(j, next_ind_++, "clip shapes", kShapeLayer, 1, 0, matte);
    j.raw(",\"shapes\":[");
    bool first = true;
    for (const Path& p : clip.paths) {
      const size_t begin = j.text().size();
      j.raw(first ? "" : ",").raw("{\"ty\":\"gr\",\"it\":[");
      if (!write_shapes(j, p)) {
        j.text().resize(begin);
        continue;
      }
      j.raw(",{\"ty\":\"fl\",\"c\":{\"a\":0,\"k\":[0,0,0,1]},\"o\":{\"a\":0,\"k\":100},\"r\":");
      j.raw(p.fill_rule == FillRule::EvenOdd ? "2" : "1").raw(",\"bm\":0},").raw(kGroupTransform).raw("]}");
      first = false;
    }
    j.raw("]");
    end_layer(j);
    return j.text();
  }

  // A static path (a mask's content) as a shape layer with its paints (`gradients` indexed by
  // its gradient indices); a matte (`td` 1) when `matte`.
  std::string static_path_layer(const Path& p, int ind, const std::vector<Gradient>& gradients, bool matte) {
    JsonText j(in_.decimals);
    begin_layer(j, ind, p.id, kShapeLayer, p.layer >= 0 ? p.local_opacity : p.opacity, 0, matte);
    j.raw(",\"shapes\":[{\"ty\":\"gr\",\"nm\":").str(p.id).raw(",\"it\":[");
    const size_t shapes_begin = j.text().size();
    write_shapes(j, p);
    std::vector<double> rest;
    for (const Subpath& sp : p.subpaths)
      for (const Vec2& q : sp.points) rest.push_back(q.x), rest.push_back(q.y);
    PaintInputs paint;
    paint.points = {rest.data()};
    if (p.fill_gradient >= 0) paint.fill = {{&gradients[static_cast<size_t>(p.fill_gradient)]}, {0}};
    if (p.stroke_gradient >= 0) paint.stroke = {{&gradients[static_cast<size_t>(p.stroke_gradient)]}, {0}};
    write_paint_items(j, shapes_begin, p, paint, approximate_);
    j.raw(j.text().size() == shapes_begin ? "" : ",").raw(kGroupTransform).raw("]}]");
    end_layer(j);
    return j.text();
  }

  // The path's subpaths as static `sh` items; false when none has an outline.
  bool write_shapes(JsonText& j, const Path& p) {
    bool any = false;
    std::vector<double> xy;
    for (const Subpath& sp : p.subpaths) {
      if (sp.points.size() < 4) continue;
      xy.clear();
      for (const Vec2& q : sp.points) xy.push_back(q.x), xy.push_back(q.y);
      j.raw(any ? "," : "").raw("{\"ty\":\"sh\",\"ks\":{\"a\":0,\"k\":");
      write_bezier(j, xy.data(), sp.points.size(), sp.closed, returns_to_start(xy.data(), sp.points.size(), sp.closed));
      j.raw("}}");
      any = true;
    }
    return any;
  }

  void begin_layer(JsonText& j, int ind, const std::string& name, int type, float opacity, int tt, bool td) {
    j.raw("{\"ind\":").num(ind, 1).raw(",\"ty\":").num(type, 1).raw(",\"nm\":").str(name);
    j.raw(",\"ks\":{\"o\":").fixed(opacity * 100.0, kOpacityScale).raw(kLayerTransformAfterOpacity);
    if (tt) j.raw(",\"tt\":").num(tt, 1);
    if (td) j.raw(",\"td\":1");
  }

  void end_layer(JsonText& j) { j.raw(",\"ip\":0,\"op\":").num(in_.frames, kFrameScale).raw(",\"st\":0,\"bm\":0}"); }

  // A precomposition layer showing asset `ref` over the whole canvas; `region` (when given)
  // limits it by Lottie masks (their union).
  std::string precomp_layer(const std::string& name, const std::string& ref, float opacity, int tt, bool td,
                            const std::vector<Subpath>& region) {
    JsonText j(in_.decimals);
    begin_layer(j, next_ind_++, name, kPrecompLayer, opacity, tt, td);
    j.raw(",\"refId\":").str(ref).raw(",\"w\":").num(std::max(1.0, std::round(scene_.width)), 1);
    j.raw(",\"h\":").num(std::max(1.0, std::round(scene_.height)), 1);
    if (!region.empty()) {
      j.raw(",\"hasMask\":true,\"masksProperties\":[");
      bool first = true;
      std::vector<double> xy;
      for (const Subpath& sp : region) {
        if (sp.points.size() < 4) continue;
        xy.clear();
        for (const Vec2& q : sp.points) xy.push_back(q.x), xy.push_back(q.y);
        j.raw(first ? "" : ",").raw("{\"inv\":false,\"mode\":\"a\",\"pt\":{\"a\":0,\"k\":");
        write_bezier(j, xy.data(), sp.points.size(), true, returns_to_start(xy.data(), sp.points.size(), true));
        j.raw("},\"o\":{\"a\":0,\"k\":100},\"x\":{\"a\":0,\"k\":0}}");
        first = false;
      }
      j.raw("]");
    }
    end_layer(j);
    return j.text();
  }

  // A new precomposition asset holding `layers` (top first); its id.
  std::string asset(const std::vector<std::string>& layers) {
    const std::string id = "comp_" + std::to_string(assets_.size());
    assets_.push_back("{\"id\":\"" + id + "\",\"layers\":[" + join(layers) + "]}");
    return id;
  }

  static std::string join(const std::vector<std::string>& parts) {
    std::string s;
    for (const std::string& p : parts) s += (s.empty() ? "" : ",") + p;
    return s;
  }

  const CompositionInputs& in_;
  const Scene& scene_;
  std::vector<std::string>& approximate_;
  int next_ind_;
  std::vector<std::string> assets_;
};

}  // namespace

CompositionText compose_layers(const CompositionInputs& in, std::vector<std::string>& approximate) {
  return Composer(in, approximate).run();
}

}  // namespace svgm::lottie
