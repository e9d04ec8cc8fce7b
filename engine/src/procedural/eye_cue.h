// Which end of an animal seen from the side is its head, from its eye.
//
// The silhouette skeleton (motion/limbs.h) tells a lying body's head from its tail by their
// tips (the head has the larger tip disc, else the higher tip), and the rig's head parts exist
// only when the drawing's groups say so. A squirrel's bushy tail has a larger tip than its
// snout, a dog's raised tail is higher than its head: the tail was read as the head, and "the
// dog wags its tail" moved the head, "its ears" the tail. A drawn eye says it plainly: a small
// dark roundish filled element (a pupil, or a dot for an eye) in the figure's upper part, near
// one end. The eye's side is the head's: the tail is at the other end, the ears above the eye.
//
// An eye counts only when every such element lies on one side of the figure's middle, at least
// kEyeOffCentre of its width off it: a face seen from the front (two eyes), or dark spots all
// over a body (a ladybird's), show no end. A long tail puts the middle near the eye: twemoji's
// shark's and dolphin's eyes are 0.125 and 0.14 of the width off it (the bound was 0.15), and a
// fish's round eye 0.11 of its size (the bound was 0.1): none was read, and told the other way
// they swam backwards. A person's eye must be farther off to show a facing (limb_qualifiers.h).
#pragma once

#include <string>

#include "procedural/part_rig.h"

namespace svgm {

constexpr double kEyeMaxSize = 0.12;    // an eye's box at most this share of the figure's longer side
constexpr double kEyeMinSize = 0.008;   // and at least this share (a speck of shine is no eye)
constexpr double kEyeDark = 0.35;       // its fill's luma at most this (0 black, 1 white)
constexpr double kEyeRound = 0.5;       // its box's short side at least this share of its long side
constexpr double kEyeFilled = 0.5;      // its area at least this share of its box's (a disc: 0.79)
constexpr double kEyeHigh = 0.6;        // its middle above this share of the figure's height
constexpr double kEyeOffCentre = 0.1;   // its middle this share of the figure's width off the middle

struct EyeCue {
  int side = 0;         // the head's side as the viewer sees it: -1 left, +1 right, 0 no eye seen
  Vec2 at;              // the eye's middle (of the eyes found, by area)
  int count = 0;        // the dark round elements that make it
  std::string why;      // what was found, for notes
};

// Whether a drawn element looks like an eye of the figure boxed by F: small, dark, round,
// filled and in its upper part (the bounds above; its lightness set by apply_eye_cue).
bool eye_like(const RigElement& e, const RigBox& F);

// The eye cue of the rig's figure, from its drawn elements (Rig::elements, their fill's luma).
EyeCue find_eye(const Rig& rig);

// The eye cue read with the colours of `paint` (the user's drawing: the scene the rig was built
// from may be recoloured, its fills false colours a palette gave each colour): each element's
// lightness from the path of `paint` with its path's id (-1 when none has it), then the eye
// found (Rig::eye_side, eye, eye_why) and the limbs relabelled by it. Returns the cue.
EyeCue apply_eye_cue(Rig& rig, const Scene& scene, const Scene& paint);

// The silhouette limbs (Rig::limbs) labelled against the eye, relabelled: a head limb that
// belongs to the side away from the eye is the tail, a tail limb that belongs to the eye's side
// the head (beyond kEyeOffCentre of the figure's width from its middle, both). A limb belongs to
// the side its base (pivot) lies on, when that is off the middle (a shrimp's antennae leave its
// head and sweep back past its tail), else to its tip's. Returns how many changed. Nothing
// changes without an eye.
int relabel_by_eye(Rig& rig, const EyeCue& eye);

}  // namespace svgm
