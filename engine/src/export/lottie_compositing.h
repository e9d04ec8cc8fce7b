// SVG compositing (group opacity, clip-path, mask) as Lottie layers: the scene's compositing
// layers (scene.h: Layer, ClipPath, Mask) become precompositions, so that what SVG draws
// offscreen and composites as one is drawn as one in Lottie too.
//
// A compositing layer L is written as a precomposition layer (`ty` 0) of an asset holding L's
// content (its paths' shape layers and its inner compositing layers, in paint order), with
//   - L's group opacity as that layer's opacity (`ks.o`): the content is composited first and
//     faded once, instead of each path being faded on its own;
//   - L's mask as an alpha matte (`tt` 1): the layer right above it (`td` 1) draws the mask's
//     content (a precomposition of its paths, with their paints and layers, limited to the
//     mask's region by a Lottie mask). A luminance mask's content is rewritten so that its alpha
//     is the mask's value (lottie_luma_matte.h), not written as a luma matte (`tt` 3), which
//     lottie-web's canvas renderer cannot draw;
//   - L's clip-path as an alpha matte drawing its shapes in opaque black (each under its
//     clip-rule); a clipPath's own clip-path clips that matte in turn. With both a clip and a
//     mask, the masked content is precomposed once more and clipped.
// Mattes are the layer directly above the matted one (the convention every player reads).
// Paths outside any compositing layer stay in the main composition, as before.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "export/lottie_json.h"
#include "svgmotion/scene.h"

namespace svgm::lottie {

struct CompositionInputs {
  const Scene* scene = nullptr;
  std::vector<int> order;                   // scene path indices, back to front
  std::vector<std::string> path_layers;     // per scene path: its shape layer's JSON object
  std::vector<std::string> group_nulls;     // per scene group: its null layer's JSON, or empty
  std::vector<int> path_group;              // per scene path: the group whose null it names, or -1
  int next_ind = 1;                         // layer numbers from here on are free
  double frames = 1;                        // the timeline's length (`op`)
  int decimals = 3;
};

struct CompositionText {
  std::string layers;  // the main composition's layers, comma-separated, top first
  std::vector<std::string> assets;  // precomposition assets, each a JSON object
};

// The layers of the animation with the scene's compositing layers as precompositions (the
// scene's paths in plain paint order when it has none). What cannot be drawn exactly is added
// to `approximate`.
CompositionText compose_layers(const CompositionInputs& in, std::vector<std::string>& approximate);

}  // namespace svgm::lottie
