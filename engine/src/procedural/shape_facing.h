// Which way a vehicle faces, from its outline (issue 35): it has no eye (eye_cue.h), and its
// "head" part (the part above its body: a ladder, a trailer) does not say; told to go against
// the way it faces, a lorry or an ambulance drove off backwards.
//
// The figure's side profile: over kProfileBins columns of its box, the highest and lowest point
// of its drawn elements (fills and strokes alike: a line drawing's strokes are its outline). Each
// end is read over its outer kEndShare of the width: how high its top reaches and how thick it is.
//
// Vehicles (the prompt's figure is wheeled): the rear is the tall square end (a van's box, a
// lorry's trailer, a train's cut end), the front the lower end (the bonnet, the cab, the nose
// sloping down to the bumper). The end whose top is lower by kVehicleStep of the figure's height
// is its front. Measured on 40 side views of land vehicles of both emoji sets whose front a
// reader sees (tests/tools/facing_probe): 30 read right, 2 wrong (a kick scooter: its handlebar
// is its high front; a bullet train drawn at a slant), 8 not read (saloons, pickups, a police car
// and a taxi whose bonnet and boot are level, a tractor, a motor scooter). Not for boats (their bow
// rises: two of four read wrong; a boat is no wheeled class) nor creatures: on 78 side views of
// animals of both sets, "the head end is the higher" read 32, 20 right and 12 wrong (a skunk's
// raised tail, a fish's or a whale's fins and flukes, an elephant's or a hippo's low head), where
// the eye cue read 32 with none wrong. An animal drawn without an eye is read by its silhouette
// otherwise (body_facing.h: its head held out beyond its feet and slimmer than its rump).
//
// Only read for a vehicle, and before its eye (limb_qualifiers.h): a locomotive's round window
// was taken for an eye.
#pragma once

#include <string>

#include "motion/lexicon.h"
#include "procedural/part_rig.h"

namespace svgm {

constexpr int kProfileBins = 40;        // columns across the figure's width
constexpr double kEndShare = 0.12;      // an end: this share of the width at each side
constexpr double kVehicleStep = 0.12;   // a vehicle's front is lower than its rear by this share of the height

// One end of the figure's side profile, as shares of the figure's height from its top: how high
// its highest point is (0 the figure's top, 1 its bottom) and how thick it is (top to bottom).
struct EndProfile {
  double top = 1, thick = 0;
};

struct SideProfile {
  EndProfile left, right;
  bool empty = true;
};

// The side profile of the rig's figure (its elements' points and the lines between them).
SideProfile side_profile(const Rig& rig);

// The viewer's side the figure faces from its outline (-1 left, +1 right, 0 not read), for a
// figure of class `figure` (the prompt's); `why` says how. 0 for a class the rules do not cover
// (every class but a wheeled one).
int shape_facing(const Rig& rig, FigureClass figure, std::string* why);

}  // namespace svgm
