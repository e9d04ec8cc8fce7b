// Which paths of a procedural motion move as one rigid body: the same affine map in every frame.
//
// The rig carries every part that has no motion of its own with its parent, so an arm's sleeve,
// the hand at its end and the trident the hand holds all move by one map per frame. The fitter
// moves each of its groups by one homography, and the structural grouper cuts such a body into
// many small groups (a trident's head, each of its arrowheads, the fingers of a fist): each then
// has to be found again at every keyframe from its own few pixels. A 1-px prong that moved 15 px
// between keyframes is beyond the blurred loss's reach, and the groups collapsed or tore
// (man_demon: the right hand shrank to a point in keyframes 1-7, the trident's head broke;
// man_boxing: a finger of the punching fist collapsed; both fits rejected by the result gate).
// Knowing the bodies, the fitter moves each as one group (fit/plan/motion_groups.h), as the video did.
#pragma once

#include <optional>
#include <vector>

#include "svgmotion/affine.h"
#include "svgmotion/scene.h"

namespace svgm {

// pts: the control points of every frame (animate_plan's layout: frame-major, the scene's
// paths' subpaths' points in order), `frames` frames. Returns, per path, the index of its rigid
// body (paths sharing one affine map from rest in every frame, to within `tol` canvas units at
// every control point), or -1 for a path that no single affine map moves (a bending region) or
// whose points do not span the plane (a straight line, a point: its map is not determined).
// Bodies are numbered in the order of their first path. A held path is on the body of the
// identity, like every other held path. Each body's map in every frame comes with it: the
// fitter warm-starts a body's group with it (FitOptions::known_motion).
struct RigidBodies {
  std::vector<int> body;                   // per path
  std::vector<std::vector<Affine>> maps;   // per body, per frame: rest -> that frame
};
RigidBodies rigid_bodies(const Scene& scene, const std::vector<Vec2>& pts, int frames, double tol);

// The least-squares affine map taking from[i] to to[i] (i < n), or nothing when the `from`
// points do not span the plane (their spread across the thinnest direction is under half a
// unit).
std::optional<Affine> least_squares_affine(const Vec2* from, const Vec2* to, size_t n);

}  // namespace svgm
