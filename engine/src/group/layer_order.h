// The painter's order of an SVG's groups from occlusion evidence in a target video (the `layers`
// stage; a simplified version of the paper's layering step).
//
// Method:
//  1. Coverage. Each group's rest-pose coverage is rasterised on the CPU at the target's size
//     (render_size(scene, width)): a pixel is covered by a path when its centre is inside the
//     fill (scanline over cubics flattened into 16 chords each, with the path's fill rule) or
//     within half the stroke width of the stroke's centre line. A group covers the union of its
//     paths. Where two groups A and B both cover a pixel, that pixel is in their overlap.
//  2. Labels. Every foreground pixel of every keyframe (TargetFrames::mask) takes the palette
//     colour nearest to it (Euclidean RGB distance, components in [0, 1]); when that distance is
//     above `color_threshold`, or the colour belongs to paths of more than one group, the pixel
//     has no label. Otherwise its label is the group owning the colour.
//  3. Evidence. For each pair (a, b) of groups with a rest-pose overlap (a is the one painted
//     first, i.e. behind, in the original order): a_pixels = pixels of the overlap labelled a,
//     summed over the keyframes, b_pixels likewise; score = (a_pixels - b_pixels) / (a_pixels +
//     b_pixels), so score > 0 says "a is in front of b" (against the original order).
//     A pair is confident when a_pixels + b_pixels >= min_pixels and |score| > min_score.
//  4. Order. Confident pairs are edges "front over back"; the new order is the topological
//     order of that graph that is lexicographically smallest in the original indices (Kahn with
//     a min-heap: stable, and the original order when there are no edges). Groups in a cycle
//     (a strongly connected component of more than one group) are resolved conservatively: the
//     edges inside the component are dropped (used = false) and its groups keep their original
//     relative order; edges to groups outside it are kept. LayerResult::fallback says so.
//  5. Conservative fallback: a new order is kept only if it hides no group at rest (see
//     max_hidden_share) and the user's document can take it (see run_layers).
//  6. Output. layered.svg is grouped.svg with its top-level elements moved (see
//     write_layered_svg); when the order does not change it is a byte copy.
#pragma once

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "svgmotion/scene.h"
#include "svgmotion/target_video.h"

namespace svgm {

struct LayerOptions {
  int keyframes = 15;            // keyframes sampled from the target (fewer if it has fewer)
  int width = 256;               // analysis width in pixels (height from the SVG's aspect)
  double color_threshold = 0.15; // max RGB distance of a pixel to its nearest palette colour
  long min_pixels = 30;          // min a_pixels + b_pixels (over all keyframes) for a pair
  double min_score = 0.3;        // a pair is used when |score| > this
  // ... and when a + b >= this share of the overlap area times the keyframes analysed.
  double min_evidence_share = 0.1;
  // A new order is dropped when it leaves any group less than (1 - this) of its visible
  // rest-pose pixels.
  double max_hidden_share = 0.5;
};

struct LayerPair {
  int a = -1, b = -1;            // group indices, a < b (a painted first in the original)
  long overlap_pixels = 0;       // rest-pose overlap area in pixels
  long a_pixels = 0, b_pixels = 0;
  double score = 0;              // (a - b) / (a + b); > 0: a is in front of b
  bool confident = false;        // enough evidence and |score| > min_score
  bool used = false;             // an edge of the final order (confident and not in a cycle)
};

struct LayerResult {
  std::vector<std::string> group_ids;  // in the original paint order (back to front)
  std::vector<int> order;              // new paint order (back to front): indices into group_ids
  bool changed = false;
  int keyframes = 0, width = 0, height = 0;  // what was analysed
  std::vector<LayerPair> pairs;
  std::optional<std::string> fallback;  // what was done about cycles / unmappable documents
  int document_moves = 0;  // elements the user's document moves to take the new order
};

// Per-pixel coverage of every group of `scene`: groups.size() masks of width*height bytes
// (1 = covered), `view` mapping canvas space to pixels.
std::vector<std::vector<uint8_t>> group_coverage(const Scene& scene, const Affine& view, int width,
                                                 int height);

// Per-keyframe label maps (K*H*W ints: group index or -1) of `target` (step 2 above).
// `palette` maps path ids to their colour in the target; paths it lacks use their own fill (or
// stroke) colour.
std::vector<int> label_frames(const Scene& scene, const std::map<std::string, Rgba>& palette,
                              const TargetFrames& target, double color_threshold);

// Step 3: the pairs of groups with a rest-pose overlap and their evidence (confident set,
// used left false).
std::vector<LayerPair> overlap_evidence(const std::vector<std::vector<uint8_t>>& coverage,
                                        const std::vector<int>& labels, int keyframes,
                                        const LayerOptions& options);

// Step 4: the new order (back to front, indices into `ids`, the groups in their original order)
// from `pairs`; sets pairs[i].used and returns the fallback note (or nullopt) through
// `fallback`.
std::vector<int> order_groups(const std::vector<std::string>& ids, std::vector<LayerPair>& pairs,
                              std::optional<std::string>* fallback);

// Steps 1-4 on a scene and a loaded target (target size = render_size(scene, target.width)).
LayerResult compute_layer_order(const Scene& scene, const std::map<std::string, Rgba>& palette,
                                const TargetFrames& target, const LayerOptions& options);

// Writes `in` (an SVG whose top-level elements are the groups) to `out` with the groups in
// `order_ids` (back to front). Top-level elements are matched to group ids by their data-group
// attribute, else their id; all elements of one group move together in their original
// relative order into the slots the matched elements occupied; everything else (other
// elements, whitespace, comments) stays where it was. Returns false, writing nothing, when the
// elements cannot be matched to the ids (a drawable top-level element without a known key, or
// an id without an element); the caller then copies the file.
bool write_layered_svg(const std::filesystem::path& in, const std::vector<std::string>& order_ids,
                       const std::filesystem::path& out);

// layers.json for a result.
nlohmann::json layers_json(const LayerResult& result, const LayerOptions& options);

// The whole stage: reads svg, palette and target, writes out_svg and out_json; returns the
// result. The original order is kept (fallback says why) when the groups cannot be mapped,
// when the new order would hide a group at rest, or when `original` (the user's document the
// animation is written into) cannot take the new order by moving elements within their parents.
LayerResult run_layers(const std::filesystem::path& svg, const std::filesystem::path& target,
                       const std::filesystem::path& palette, const std::filesystem::path& out_svg,
                       const std::filesystem::path& out_json, const LayerOptions& options,
                       const std::optional<std::filesystem::path>& original = std::nullopt);

}  // namespace svgm
