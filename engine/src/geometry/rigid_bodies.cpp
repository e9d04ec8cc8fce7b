// Rigid bodies of a procedural motion (see rigid_bodies.h).
#include "geometry/rigid_bodies.h"

#include <Eigen/Dense>
#include <cmath>
#include <optional>

namespace svgm {

std::optional<Affine> least_squares_affine(const Vec2* rest, const Vec2* moved, size_t n) {
  if (n < 3) return std::nullopt;
  Vec2 c{0, 0};
  for (size_t i = 0; i < n; ++i) c = c + rest[i];
  c = (1.0 / static_cast<double>(n)) * c;
  // Normal equations in centred coordinates (well conditioned whatever the canvas offset).
  Eigen::Matrix3d N = Eigen::Matrix3d::Zero();
  Eigen::Vector3d bx = Eigen::Vector3d::Zero(), by = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d v(rest[i].x - c.x, rest[i].y - c.y, 1.0);
    N += v * v.transpose();
    bx += v * moved[i].x;
    by += v * moved[i].y;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> spread(N.topLeftCorner<2, 2>());
  if (!(spread.eigenvalues()(0) / static_cast<double>(n) > 0.25)) return std::nullopt;
  const Eigen::LDLT<Eigen::Matrix3d> ldlt(N);
  const Eigen::Vector3d px = ldlt.solve(bx), py = ldlt.solve(by);
  return Affine{px(0), py(0), px(1), py(1), px(2) - px(0) * c.x - px(1) * c.y, py(2) - py(0) * c.x - py(1) * c.y};
}

RigidBodies rigid_bodies(const Scene& scene, const std::vector<Vec2>& pts, int frames, double tol) {
  const size_t P = scene.paths.size();
  RigidBodies out;
  out.body.assign(P, -1);
  std::vector<int>& body = out.body;
  if (frames < 1 || pts.empty()) return out;
  const size_t per = pts.size() / static_cast<size_t>(frames);
  std::vector<size_t> first(P), count(P);
  for (size_t p = 0, i = 0; p < P; ++p) {
    first[p] = i;
    for (const auto& sp : scene.paths[p].subpaths) i += sp.points.size();
    count[p] = i - first[p];
  }
  // Does the per-frame map `maps` take path p's rest points to where the frames put them?
  auto carries = [&](const std::vector<Affine>& maps, size_t p) {
    for (int f = 0; f < frames; ++f)
      for (size_t k = 0; k < count[p]; ++k) {
        const Vec2 q = maps[static_cast<size_t>(f)].apply(pts[first[p] + k]);
        const Vec2 m = pts[static_cast<size_t>(f) * per + first[p] + k];
        if (!(std::hypot(q.x - m.x, q.y - m.y) <= tol)) return false;
      }
    return true;
  };
  std::vector<std::vector<Affine>>& bodies = out.maps;  // each body's map in every frame
  auto join = [&](size_t p) {
    for (size_t b = 0; b < bodies.size(); ++b)
      if (carries(bodies[b], p)) return static_cast<int>(b);
    return -1;
  };
  // Paths whose own points determine their map found or join a body; then the others (a
  // straight stroke) join one that carries them.
  for (size_t p = 0; p < P; ++p) {
    std::vector<Affine> maps;
    for (int f = 0; f < frames && count[p] > 0; ++f) {
      const auto m = least_squares_affine(&pts[first[p]], &pts[static_cast<size_t>(f) * per + first[p]], count[p]);
      if (!m) break;
      maps.push_back(*m);
    }
    if (maps.size() != static_cast<size_t>(frames) || !carries(maps, p)) continue;  // undetermined, or not rigid
    body[p] = join(p);
    if (body[p] < 0) {
      body[p] = static_cast<int>(bodies.size());
      bodies.push_back(std::move(maps));
    }
  }
  for (size_t p = 0; p < P; ++p)
    if (body[p] < 0 && count[p] > 0) body[p] = join(p);
  return out;
}

}  // namespace svgm
