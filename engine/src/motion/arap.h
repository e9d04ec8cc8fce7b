// As-rigid-as-possible deformation of a figure's mesh (shape_mesh.h), driven by handles: the way
// a procedural motion bends a limb that is not a part of its own instead of cutting through the
// shape at a pivot line (Igarashi, Moscovich and Hughes 2005; the local/global solver of Sorkine
// and Alexa 2007, per triangle as in Liu et al. 2008; see arap.cpp for the maths).
//
// Cost: per mesh and handle set (the constructor), two sparse factorisations: the rigidity
// system (n x n) and the similarity start's (2n x 2n); per frame, the start's solve and K
// local/global iterations, each a closed-form 2x2 rotation per triangle and two triangular
// solves (600 vertices: about 0.4 ms a frame, 10 ms to factorise). Everything is sequential:
// the same inputs give the same bits.
//
// How the planner drives it (procedural/region_bend.cpp does 1-3 for region bends):
//  1. Once per drawing: render the drawing's coverage at a working size (~256 px on the long
//     side), mask = coverage > 0 with the figure's interior holes filled when it is drawn in
//     outlines (a line drawing's mask is its strokes only), build_shape_mesh(mask, scale), and
//     bind_points() every control point of every path, the off-curve Bézier handles included.
//  2. Handles come from the rig, once per set of actions (the set fixes the factorisation; only
//     the targets change from frame to frame):
//     - A bone from joint J to tip E (a limb part's pivot and its far end): the vertices within
//       about one cell of the segment J->E, leaving out those within about the limb's half
//       width of J, so the joint itself bends freely. Target each frame: the bone's transform
//       (its rotation about J composed with its parent's) applied to the handle's rest point.
//       The root (torso) gives handles along its own axis, target the figure's whole motion
//       (identity when the figure stays; a bob's translation when it bobs).
//     - A region swinging about a pivot line (PlannedAction::region, a bat's wing drawn in one
//       silhouette): with d the signed distance from the pivot line (positive on the limb's
//       side) and a band of about the limb's width w, the vertices with d < -w/2 are fixed
//       handles (target: their rest point, or the parent's motion), those with d > w/2 are
//       rotated by the action's angle about the pivot point; the band between has no handles,
//       and the solver bends it (a wider band: a gentler bend). Put the pivot point on the
//       inner side of the bend (the edge the limb folds towards), as a knee's is: a 40x200 bar
//       swung 60 degrees about the middle of that edge keeps its middle line's length to 2 %;
//       about the middle of the bar itself it loses 4-5 % (a hinge on the centre line asks
//       for a kink; a smooth bend there must be shorter).
//     - Every mesh piece the motion should carry needs a handle of its own; a piece with no
//       handle follows the best rigid fit of all handles (so a whole-figure motion still
//       carries it) and is not bent.
//     Weights multiply ArapOptions::stiffness: 1 for ordinary handles (the test bar's far end
//     follows its handles to 1e-5 px); a guide the mesh may pull away from (the tip of a tail
//     following a wave) needs a weight near 1 / stiffness.
//  3. Each frame: v = deform(targets), points = bound_positions(mesh, bindings, v), and
//     mesh_quality(mesh, v) (mesh_quality.h): a frame with a flipped triangle, or an area or
//     edge far from rest, is rejected or its amplitude scaled down before it becomes a candidate.
//     Frames solved cold are independent of each other (any order, in parallel, and a loop's
//     last frame is exactly its first); a warm start (deform(targets, &previous)) pays only when
//     consecutive frames are a degree or two apart.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "motion/shape_mesh.h"
#include "svgmotion/error.h"

namespace svgm {

struct ArapOptions {
  int iterations = 6;  // local/global iterations per deform()
  // A handle's weight relative to the mean diagonal of the rigidity term (soft constraints):
  // large, so a handle is met closely, yet a well-conditioned system.
  double stiffness = 1e4;
  // Start at the as-similar-as-possible solution (similarity_start.h) rather than each piece's
  // rigid fit: on the 60-degree bar of the tests, 6 iterations end 2.4 px from the converged
  // shape instead of 12 px.
  bool similarity_start = true;
};

// A handle: a vertex, or a bound point (a fixed affine combination of a triangle's vertices).
struct ArapHandle {
  std::array<int, 3> vertex{};
  std::array<double, 3> share{1, 0, 0};
  double weight = 1;  // > 0
  static ArapHandle at_vertex(int v, double weight = 1) { return {{v, v, v}, {1, 0, 0}, weight}; }
  static ArapHandle at(const ShapeMesh& mesh, const MeshBinding& b, double weight = 1) {
    if (b.triangle < 0 || static_cast<size_t>(b.triangle) >= mesh.triangles.size())
      throw Error("ArapHandle: the point is not bound to this mesh");
    return {mesh.triangles[static_cast<size_t>(b.triangle)], b.bary, weight};
  }
};

class ArapDeformer {
 public:
  // Builds the system and factorises it. Throws svgm::Error for a handle naming no vertex, a
  // handle weight or a stiffness that is not positive and finite.
  ArapDeformer(const ShapeMesh& mesh, std::vector<ArapHandle> handles, ArapOptions options = {});
  ~ArapDeformer();
  ArapDeformer(ArapDeformer&&) noexcept;
  ArapDeformer& operator=(ArapDeformer&&) noexcept;

  // The handles' rest positions (canvas coordinates).
  const std::vector<Vec2>& handle_rest() const;

  // The vertex positions with each handle near its target (one per handle, in order). The start:
  // each piece of the rest mesh moved by the best rigid fit of its handles to their targets (so
  // handles moved rigidly together give exactly that rigid motion), then the as-similar-as-
  // possible solve (ArapOptions::similarity_start). `warm`: the previous frame's vertices, the
  // start instead (see the planner's notes above for when that helps).
  // `iterations` < 0: ArapOptions::iterations. Throws svgm::Error on a size mismatch.
  std::vector<Vec2> deform(const std::vector<Vec2>& targets, const std::vector<Vec2>* warm = nullptr,
                           int iterations = -1) const;

  // The energy deform() lowers, at these vertex positions (each triangle at its best rotation):
  // the rigidity term plus the handles' soft constraints.
  double energy(const std::vector<Vec2>& vertices, const std::vector<Vec2>& targets) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The local step: the angle of the rotation R minimising sum_k w_k |e'_k - R e_k|^2, given
// M = sum_k w_k e'_k e_k^T (row-major: M[0] = sum w e'x ex, M[1] = sum w e'x ey,
// M[2] = sum w e'y ex, M[3] = sum w e'y ey). Closed form: atan2(M[2] - M[1], M[0] + M[3]).
double best_rotation_angle(const std::array<double, 4>& m);

}  // namespace svgm
