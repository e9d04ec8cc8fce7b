// A bird's wing drawn over its body: the shape a side-view bird (a dodo, a crow, a parrot, a
// duck) folds on its flank, drawn inside the body's outline and not apart from it.
//
// "The dodo flaps its stubby wings" found no part for the wings (the wing is a detail inside the
// root) and no arm in the silhouette's skeleton (the wing adds nothing to the silhouette), so
// the body's sides bent as arms: the head and the tail swung and the wing stayed put. The wing
// is the largest element drawn inside the body's box that is not the head: at least
// kWingMinShare of the body's box and at most kWingMaxShare, its middle not below
// kWingLow of the body's height (a belly patch is lower), its middle on the silhouette's core
// and in none of its limbs (Rig::limbs: a cheek patch lies in the head's), and away from the
// eye. It turns about its shoulder: its point nearest the head (the drawn eye, eye_cue.h, else
// the rig's head parts, else the tips of the silhouette's head limbs), else nearest the body's
// middle; only its own paths (and those drawn on it) move, the body under it holds. A front
// view's wings come in mirrored pairs: a shape with a twin across the middle is none.
#pragma once

#include <string>

#include "procedural/motion_plan.h"
#include "procedural/part_locator.h"

namespace svgm {

constexpr double kWingMinShare = 0.03;  // of the body element's box: a wing's box at least (the
                                        // openmoji dodo's stubby wing: 0.05)
constexpr double kWingMaxShare = 0.45;  // and at most (a larger inner shape is a second body colour)
constexpr double kWingLow = 0.75;       // its middle above this share of the body's height from its top
constexpr double kWingFromEye = 0.2;    // its middle at least this share of the figure's longer side from the eye
// A side view's wing has no twin: none of like size (areas within kTwinSize of each other)
// lies mirrored across the figure's middle within kTwinNear of its width (a front-view bat's
// wing panels do: one panel turned alone tore its wing).
constexpr double kTwinSize = 0.3;
constexpr double kTwinNear = 0.1;

// The wing drawn over the body of the rig's figure; lobes empty when none fits.
LocatedPart wing_on_body(const Rig& rig);

// Action `a` turns the wing `wing` instead of bending its host's sides; `note` says so.
void beat_drawn_wing(const Rig& rig, PlannedAction& a, const LocatedPart& wing, std::string& note);

}  // namespace svgm
