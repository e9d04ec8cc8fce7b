// A figure seen from the front: two eyes level with each other and mirrored about the figure's
// middle (a face emoji, an animal facing the viewer).
//
// Seen from the front, a tail is hidden behind the body, and a face drawn alone has none. With no
// tail part and no tail limb, "the puppy wags its tail" bent the far end of the face's box
// instead: on twemoji's dog face and openmoji's tiger face an ear bent, and the wag read as an ear
// twitch, if at all. The wag of a tail not drawn is the whole figure's (motion_plan.cpp). Two eyes
// show it: find_eye (eye_cue.h) reads no side from them, and they are a pair, at the same height
// (within kFacePairLevel of the figure's height), as big as each other (kFacePairSize), their
// middle within kFacePairCentred of the figure's width from its middle, kFacePairApart of its
// width apart. A side view shows one eye, or two close together near one end.
#pragma once

#include <string>

#include "procedural/part_rig.h"

namespace svgm {

constexpr double kFacePairLevel = 0.06;       // |dy| at most this share of the figure's height
constexpr double kFacePairCentred = 0.08;     // the pair's middle this share of the width off the middle
constexpr double kFacePairApartMin = 0.12;    // the eyes at least this share of the width apart
constexpr double kFacePairApartMax = 0.7;     // and at most this share
constexpr double kFacePairSize = 1.6;         // the larger eye's box at most this times the smaller's

struct FrontFace {
  bool seen = false;
  Vec2 left, right;  // the eyes' middles
  std::string why;   // "a pair of eye-like marks level at 0.35,0.40 and 0.65,0.40 of the figure"
};

// The rig's figure seen from the front, from its eye-like elements (eye_like, eye_cue.h; their
// lightness set by apply_eye_cue): of the pairs that meet the bounds, the smallest (the first
// in the elements' order on a tie).
FrontFace front_face(const Rig& rig);

// Why a tail the prompt names is not drawn: the figure is seen from the front and no limb of its
// silhouette is a tail ("no tail drawn: the figure is seen from the front (...)"); "" otherwise.
std::string tail_not_drawn(const Rig& rig);

}  // namespace svgm
