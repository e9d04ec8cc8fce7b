// The geometry the part rig (part_rig.h) reads from a line drawing: a sketch drawn as open,
// unfilled strokes, each path one pen stroke (a runner or a galloping horse in a few dozen
// cubics). Areas say nothing there (a stroke encloses nothing; a hairpin's control polygon
// encloses more than a long straight back), and boxes overlap everywhere, so a line drawing's
// rig is built from what the strokes themselves say:
//  - a stroke's size is its curve's length (the root is the longest central stroke);
//  - its extent is its curve's box, not its handles' (a sketch's handles reach far past the
//    curve: a torso stroke's handle stood 35 px above the runner's shoulders);
//  - strokes lying alongside the root (within its extent along its long axis, close across it)
//    are the body with it (a torso drawn as a bundle of hairpins);
//  - a limb stroke turns about its end nearer the body (the end in or nearest the body's box);
//  - a stroke hangs from a longer stroke of the same limb when one of its ends touches that
//    stroke's curve (a foot drawn on from a shin, the strokes of one leg meeting at its foot),
//    else from the root.
#pragma once

#include <array>
#include <vector>

#include "svgmotion/scene.h"
#include "procedural/part_rig.h"

namespace svgm {

// One open subpath, drawn with a stroke and without fill.
bool is_open_stroke(const Path& p);

// A line drawing: at least kMinStrokes paths, every one an open stroke.
bool is_line_drawing(const Scene& scene);

// Points along the curve (each cubic at 16 steps) and the curve's length and box.
std::vector<Vec2> stroke_curve(const Path& p);
double stroke_length(const Path& p);
RigBox stroke_box(const Path& p);

// The stroke's two ends: its endpoints, or, when it folds back on itself (its endpoints closer
// together than kStrokeFold of its reach from their middle: a hairpin, as a sketch draws an
// arm down and back up), the endpoints' middle and the fold's tip.
std::array<Vec2, 2> stroke_ends(const Path& p);

// Of the stroke's ends, the one nearer `body` (its distance to the box, 0 inside), the one
// nearer `joint` when both are as near.
Vec2 stroke_body_end(const Path& p, const RigBox& body, Vec2 joint);

// A stroke drawn as a wheel: an open stroke that winds round once (its curve turns one way
// through most of a full turn, kLoopTurn) about an oval that its curve fills as an ellipse
// fills its box (at least kLoopFill of it), no more than kLoopAspect times longer than wide.
// A sketched bicycle's wheels are such ovals; an S-shaped leg turns both ways (its turns
// cancel) and a hairpin arm turns half a turn.
bool is_loop_stroke(const Path& p);

// The plane a loop stroke's wheel turns in, seen at a slant: the linear map taking a circle
// about the origin to the oval its curve encloses, up to scale (the symmetric square root of
// the enclosed region's second-moment matrix, normalised to determinant 1). A turn R in the
// wheel's own plane is M R M^-1 in the drawing: the oval keeps its outline while the stroke
// runs round it, as a wheel drawn in perspective spins; R alone tumbles the oval about.
Affine loop_plane(const Path& p);

// The distance from q to the curve of p.
double distance_to_stroke(Vec2 q, const Path& p);

// Whether a stroke with curve box `s` lies alongside the root's curve box `root`: at least
// kAlongInside of its extent along the root's long axis within the root's, and its middle
// within `across` of the root's middle across that axis.
bool lies_alongside(const RigBox& s, const RigBox& root, double across);

}  // namespace svgm
