// A region bend (PlannedAction::region: a bat's wing, a raised arm or a tail drawn as part of
// one shape) moved through an as-rigid-as-possible mesh of the shapes it bends (motion/arap.h,
// the way arap.h's notes describe), instead of point by point: bent by the closed form each
// point turns by its own weight, so two points of one stroke on either side of the ramp part
// (a notch, a cut), and the inner side of a steep bend folds over itself. Through the mesh, every
// control point of the bent paths (the off-curve handles included) takes the deformation of the
// triangle under it: a shape lying across the joint bends with it, a stroke stays joined.
//
// The handles come from the closed form's weight (region_turn): mesh vertices the region holds
// (weight 0) keep their place, those beyond the ramp (weight 1) turn rigidly about the pivot by
// the frame's angle, and the band between has no handle: the solver bends it. A mesh piece with
// fewer than kMinPieceHandles such vertices (a piece lying wholly in the band) has every vertex
// held to the closed form's target: there the mesh has nothing of its own to keep.
//
// Where ARAP does not apply, the closed form stays (motion_frames.cpp): a growing located part
// (pulse: a scaling keeps every shape whole), a bend whose paths leave no mask at the working
// size, or one whose mesh keeps fewer than kMinPieceHandles vertices that turn once the band is
// widened (a limb two cells thin: held still by the mesh, it did not move at all).
#pragma once

#include <memory>
#include <vector>

#include "motion/mesh_quality.h"
#include "procedural/motion_plan.h"

namespace svgm {

class RegionBend {
 public:
  // `paths`: the scene's paths whose points action `a` bends (their coverage is the mesh's
  // mask), `box` the bent part's box. empty() when ARAP does not apply.
  RegionBend(const Scene& scene, const std::vector<int>& paths, const PlannedAction& a, const RigBox& box);
  bool empty() const { return built_ == nullptr; }

  // The mesh's vertices at amplitude `amp` and time t (a cold solve: any frame alone, the same
  // bits every time; the rest mesh exactly where every target is at rest).
  std::vector<Vec2> solve(double amp, double t) const;
  // A point of a bent path moved as the mesh (its vertices `v`) moves it.
  Vec2 apply(const std::vector<Vec2>& v, Vec2 q) const;
  // A point q of a part hanging at `pivot` (motion_frames.cpp's carried_by_bend): moved whole as
  // the mesh moves the pivot, turned as the mesh turns there.
  Vec2 carry(const std::vector<Vec2>& v, Vec2 pivot, Vec2 q) const;
  MeshQuality quality(const std::vector<Vec2>& v) const;

  struct Built;

 private:
  std::shared_ptr<const Built> built_;
  PlannedAction action_;
  RigBox box_;
};

}  // namespace svgm
