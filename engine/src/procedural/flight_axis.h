// The way a launched figure goes: along its own axis, towards its nose (issue 35). A rocket told
// it "blasts off" climbed straight up and shrank towards its top, which on a rocket drawn on a
// slant (an emoji's rocket points up and right) read as going away, not as a launch; a plane
// taking off went up with its nose pointing right. Here the figure's axis and its nose are read
// from its drawn shape.
//
// The shape: the figure's drawn elements on a grid of kAxisGrid cells across its longer side
// (fills by their outlines, each cubic sampled, open strokes along their lines; a ground band it
// stands on, support_band.h, left out: a departing plane's runway). Its axis is
//   - the line it is mirrored about, when the mirror image covers kMirrorCover of it (IoU): a
//     plane, a rocket, a shuttle, an arrow drawn from above are mirrored about their length
//     (measured on renders of both emoji sets: twemoji's and openmoji's airplanes, small
//     airplanes, bows and arrows, openmoji's space shuttle 0.96 to 0.99; side views of
//     departing and arriving planes 0.65 to 0.78);
//   - else its long axis (second moments), when it is kLongAxis times longer than wide (side
//     views of planes, 3.8 and 4.2; a drawn spaceship 3.6);
//   - else none.
// Its nose is the narrower end: each end's mean width over its outer kNoseShare and over half
// that again (a rocket's flame tip at its tail is narrow at the very end, its fins wide over the
// quarter), the narrower by kNoseStep. On the renders above every nose read right, where the
// mirror or the long axis was found (a rocket, planes from above and from the side, arrows).
// A balloon's or a kite's narrow end is its string, a flying saucer's is none: the nose is read
// only for a launch (motion_plan.cpp), and a launch whose nose points down goes straight up; a
// landing comes in along a nose that points level or down (an arriving plane), else straight down.
#pragma once

#include <string>

#include "procedural/part_rig.h"

namespace svgm {

constexpr int kAxisGrid = 48;            // cells across the figure's longer side
constexpr double kMirrorCover = 0.85;    // mirror image's share of the shape (intersection over union)
constexpr double kLongAxis = 1.5;        // long axis: its spread over the cross spread (std deviations)
constexpr double kNoseShare = 0.25;      // an end: this share of the length
constexpr double kNoseStep = 0.9;        // the nose's width is at most this share of the tail's
constexpr double kNoseDown = 0.26;       // a launch's nose points at most this far down (sin 15 degrees)
constexpr double kMinClimb = 30;         // degrees above the level a launch goes at least

struct FlightAxis {
  Vec2 nose{0, 0};    // unit vector from the middle towards the nose (y down); {0, 0} when unread
  bool found = false;
  std::string why;
};

// The rig's figure's axis and nose (see above).
FlightAxis flight_axis(const Rig& rig);

// The same shape's mirror cover (IoU) about the vertical line through its centroid, and its width
// over its height (its cells' box): what depth_travel.h reads a figure seen head-on from.
struct UprightMirror {
  double cover = 0;   // 0 when the shape is too small to read
  double wide = 0;    // width / height of the shape
};
UprightMirror upright_mirror(const Rig& rig);

}  // namespace svgm
