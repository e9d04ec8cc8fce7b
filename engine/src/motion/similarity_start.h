// The first guess of an as-rigid-as-possible solve (arap.h): the as-similar-as-possible
// deformation, step one of Igarashi, Moscovich and Hughes 2005 in per-triangle form. Each
// triangle may rotate and scale uniformly at no cost, so the energy is quadratic in the vertex
// positions and one linear solve gives a globally consistent field of rotations: a bar whose end
// is swung by 60 degrees comes out bent along its whole length (thicker on the outside, thinner
// on the inside), where the local/global iterations alone, from a rigid start, need some fifty
// iterations to carry the rotation from the handles to the middle. The iterations then only
// have to even out the scale, which is local and quick.
//
// For triangle t with edge weights w, rest edges e and deformed edges f (linear in p):
//     E_t = min over similarities S of sum w |f - S e|^2
//         = sum w |f|^2 - ((sum w f.e)^2 + (sum w e x f)^2) / (sum w |e|^2),
// a quadratic form in the 2n coordinates; with the handles' soft constraints it is factorised
// once. A piece whose handles do not fix a rotation and a scale (fewer than two distinct handle
// points) would leave the system singular: its vertices are left out and keep the start given.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "motion/arap.h"

namespace svgm {

class SimilarityStart {
 public:
  // rest: every vertex; triangles and w: those of the solved pieces with their edge weights
  // (w[t][k] for edge t[k] -> t[k+1 mod 3]); solved[v]: the vertex's piece has two distinct
  // handle points; omega: each handle's soft-constraint weight.
  SimilarityStart(const std::vector<Vec2>& rest, const std::vector<std::array<int, 3>>& triangles,
                  const std::vector<std::array<double, 3>>& w, const std::vector<bool>& solved,
                  const std::vector<ArapHandle>& handles, const std::vector<double>& omega);
  ~SimilarityStart();
  SimilarityStart(SimilarityStart&&) noexcept;
  SimilarityStart& operator=(SimilarityStart&&) noexcept;

  // Moves the solved vertices of p (a start, e.g. each piece's rigid fit) to the minimiser.
  void solve(const std::vector<Vec2>& targets, std::vector<Vec2>& p) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace svgm
