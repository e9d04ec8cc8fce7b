// A portrait's head turned out of the picture's plane (issue 35): "she nods her head", "he shakes
// his head no". A nod is the head pitching forward on its neck (the face dips, down and back
// up), a shake its yawing from side to side; bust_head.h's head turned whole in the picture's
// plane instead, so a nod read as a sideways tilt of the head and a shake as a wobble.
//
// The head is taken as a ball filling its box (an ellipsoid of its half width and half height,
// as deep as it is wide) and drawn as an outline (the large shapes: the face, the hair) with
// features on its front (the small shapes inside it: eyes, brows, nose, mouth). Turned, each
// feature's middle goes where its place on the ball's front goes, seen from the front: it slides
// down (or aside) by the radius times the sine of the turn, less towards the rim (the mouth,
// low on the ball, slides less than the eyes); the feature moves whole, undistorted. The outline
// is the ball's rim and stays a head: a pitch only shortens it by the cosine of the turn about
// the neck (the top of the head comes down, the chin stays on the neck). Pitched point by point
// (each by its own depth) the outline's points near the rim slid less than their handles and
// the face came to a point at the chin (twemoji 1f474). A yaw narrows it by the cosine and
// slides its points by a depth that vanishes smoothly at the rim (a face's outline inside the
// hair slides across it; the rim holds).
//
// The verbs: a nod and a bow pitch; a shake, a look and a turn yaw; anything else (a tilt, a
// lean) turns in the plane as before.
#pragma once

#include <string>
#include <vector>

#include "procedural/part_rig.h"

namespace svgm {

enum class HeadAxis { Plane, Pitch, Yaw };

// The least turn of a nod or a shake, in degrees: at a part's usual swing (20) a feature in the
// middle of the face slides by sin 20 = 0.34 of the radius, at 28 by 0.47.
inline constexpr double kHeadTurnDeg = 28;
// A feature: a path whose box covers at most this share of the head's box (two eyes drawn as
// one path cover about a tenth; a face outline more than half).
inline constexpr double kFeatureShare = 0.2;

// A head's turn for each verb (by the lexicon's canonical name: motion_verbs.cpp), see above.
HeadAxis head_axis_of(const std::string& verb);

// One path of the head: a feature on its front (depth > 0: how far its middle stands out of the
// picture on the ball, 0 .. 1) or part of its outline (depth 0).
struct HeadPath {
  Vec2 middle{0, 0};
  double depth = 0;
};

// Per path box of the head (box `head`): a feature when small (kFeatureShare) with its middle
// inside the ball, else the outline.
std::vector<HeadPath> head_paths(const RigBox& head, const std::vector<RigBox>& boxes);

// Where point q of path `p` of a head of box `head`, turning on its neck at `neck`, goes when it
// turns by `degrees` about `axis` (Pitch: positive dips the face; Yaw: positive turns it to the
// viewer's right). Plane, or no turn: q.
Vec2 head_turn_point(const RigBox& head, Vec2 neck, HeadAxis axis, double degrees, const HeadPath& p, Vec2 q);

}  // namespace svgm
