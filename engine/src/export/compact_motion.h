// What the compact exports (SMIL and Lottie) write of one path's motion: nothing when it does
// not move, an affine map of its rest shape per written value (a transform on a wrapping
// group, which an editor can change and whose playback still starts from the rest shape) and,
// only when the shape itself changes beyond the tolerance, the residual shape in that moving
// frame. Keyframes are then reduced in time (keyframe_reduce.h) and numbers rounded to the
// fewest decimals that keep the tolerance.
//
// The tolerance is in canvas pixels (the SVG's size after its viewBox mapping, Lottie's
// coordinates): a quarter of a pixel when the drawing is shown 1024 px across its larger side
// (kCompactTolerance1024). Each stage keeps its own error within it (the affine map's miss
// decides whether a residual is written; the reduction holds every written sample; rounding
// moves a point by at most a quarter of it), so the compact file draws within about twice the
// tolerance of the full per-frame export.
#pragma once

#include <vector>

#include "export/keyframe_reduce.h"
#include "export/group_transform.h"
#include "svgmotion/affine.h"

namespace svgm {

// Pixels at a 1024-px rendering of the drawing's larger side.
constexpr double kCompactTolerance1024 = 0.25;
double compact_tolerance(double canvas_width, double canvas_height);

struct PartMotion {
  bool moves = false;          // false: the document's shape, unanimated
  std::vector<Affine> affine;  // per value: canvas-space map from the rest shape
  bool residual = false;       // the shape changes beyond the affine map: animate `d` too
  double affine_miss_px = 0;   // the affine maps' largest miss of a control point
};

// `rest` holds the document's control points (canvas, n (x, y) pairs); `values` the pass's
// written shapes (values.size() pointers to n pairs each). The affine map is the least-squares
// one (translation only when the points are collinear). `residual_tolerance` (<= 0: `tolerance`)
// is the miss of the affine maps below which no residual shape is written (the residual's own
// tolerance, kResidualScales).
PartMotion analyse_part_motion(const std::vector<double>& rest, const std::vector<const double*>& values,
                               double tolerance, double residual_tolerance = 0);

// How much looser than the transform's the residual shapes' tolerance may be (a multiple of
// the tolerance; the first is the tolerance itself), tried in order by the measured choice
// (tolerance_choice.h). The residual (what a part's shape does beyond its affine motion) is the
// fit's frame-to-frame jitter of a few control points, a fraction of a pixel that moves little
// of the picture, where the transform moves the whole part: on the bench parrot (0.25 canvas
// px) its `d` keys halve at twice the tolerance (156 -> 79 over 12 paths) and fall to a third
// at three times.
inline const std::vector<double> kResidualScales = {1, 2, 3, 4, 6};

// The wrapper group's transform per value (in its parent's user space: `parent_to_canvas` maps
// it to the canvas), as a reducible trajectory of 6 numbers per value (tx, ty, rotate and skewX
// in degrees, sx, sy), unwrapped. The rotation is about the rest shape's centre c (parent
// space), so that a turning part's keys interpolate along its arc, not along a chord swung
// about the document's far origin:
//   SMIL:   translate(tx ty) rotate(r cx cy) skewX(k) scale(sx sy)
//   Lottie: position c + t, anchor c, rotation r, scale s (no skew): T(c + t) R S T(-c)
enum class WrapperForm { Smil, Lottie };
std::vector<double> wrapper_trajectory(const std::vector<Affine>& affine, const Affine& parent_to_canvas, Vec2 centre,
                                       WrapperForm form);
// The map (parent space) that 6 trajectory numbers draw.
Affine wrapper_map(const double* p, Vec2 centre, WrapperForm form);
// The error of an interpolated wrapper transform against value i's: the largest distance in
// canvas pixels it puts any of the rest points (canvas).
SampleError wrapper_error(const std::vector<double>& trajectory, const std::vector<double>& rest,
                          const Affine& parent_to_canvas, Vec2 centre, WrapperForm form);

// A wrapper transform's written keys. Each channel (translation, rotation, skewX, scale) has
// keys of its own, as SMIL's separate animateTransforms and Lottie's p, r and s are keyed
// separately: a position that barely moves is not written at every key the rotation needs.
// Each channel is reduced within a budget of its own error (the other channels exact), and the
// budgets are tightened until the composed transform, every channel as its keys draw it, is
// within `tolerance` of the exact maps on the rest points at every value and checked time
// between (keyframe_reduce.h); a channel a constant holds within its budget keeps one key.
// The kept keys are rounded to decimals measured per channel (translation within a quarter of
// the tolerance, angles and scales an eighth; `decimals` >= 0 fixes the translation's), and
// `drawn` is the canvas map the player draws at each value's time from those rounded keys,
// which a residual shape is computed against. The Lottie form leaves the skew out.
enum WrapperChannel : size_t { kTranslate = 0, kRotate = 1, kSkew = 2, kScale = 3 };
inline constexpr size_t kWrapperChannels = 4;
// The channel's first number in a trajectory's 6 and how many it has.
inline constexpr size_t kChannelAt[kWrapperChannels] = {0, 2, 3, 4}, kChannelSize[kWrapperChannels] = {2, 1, 1, 2};
struct WrapperKeys {
  std::vector<double> trajectory;  // 6 numbers per value; each channel's kept keys rounded
  ReducedKeys channel[kWrapperChannels];  // per channel: its kept values (one: a constant) and easing
  int translate_decimals = 0, rotate_decimals = 0, skew_decimals = 0, scale_decimals = 0;
  std::vector<Affine> drawn;  // per value, canvas space
  size_t key_count() const;   // keys of all channels
};
// `centre`: the rest shape's centre in the parent's space.
WrapperKeys wrapper_keys(const std::vector<Affine>& affine, const Affine& parent_to_canvas, const std::vector<double>& rest,
                         const std::vector<double>& times, double tolerance, int decimals, Vec2 centre, WrapperForm form);
// The 6 numbers the channels' keys draw at time t (a player's interpolation of each channel).
std::vector<double> wrapper_keyed_at(const WrapperKeys& w, const std::vector<double>& times, double t);
// The centre of the rest points (canvas) in the parent's space.
Vec2 rest_centre(const std::vector<double>& rest, const Affine& parent_to_canvas);
// The point (parent space) the part turns about: the one its affine maps (canvas) move least
// over the values (least squares), pulled towards the rest centre where the motion leaves it
// open (a translation) and kept within a few of the rest shape's sizes of it. A part swinging
// about a joint (a forearm about the elbow) then has a still position and only its angle keyed,
// which eases with few keys, where about its own centre its position sweeps an arc (x and y out
// of phase: no one easing fits both).
Vec2 motion_pivot(const std::vector<Affine>& affine, const std::vector<double>& rest, const Affine& parent_to_canvas);

// The fewest decimals (0..max) at which rounding every number of `keys` of `values` (dim per
// value) moves no sample by more than `budget` pixels, per `error`; `first`/`count` select
// which of the dim numbers are rounded (others are kept exact for the measure).
int measured_decimals(const std::vector<double>& values, size_t dim, const std::vector<size_t>& keys,
                      const SampleError& error, double budget, size_t first, size_t count, int max_decimals);

}  // namespace svgm
