// As-rigid-as-possible deformation of a triangle mesh by handles (see arap.h for its use).
//
// The energy. Each triangle t maps linearly from rest x to deformed p, with Jacobian J_t; the
// deformation is as rigid as possible when every J_t is close to a rotation R_t:
//     E_rigid = sum_t A_t |J_t - R_t|_F^2
//             = sum_t sum_{edges ij of t} w_ij |(p_i - p_j) - R_t (x_i - x_j)|^2,
// with w_ij = cot(theta_ij) / 2, theta_ij the angle of t opposite the edge (the cotangent formula
// of the Dirichlet energy of the piecewise-linear map p - R_t x, Pinkall and Polthier 1993). This
// is the per-triangle form of Sorkine and Alexa's 2007 energy, as Liu et al. 2008 use it for
// parametrisation; Igarashi et al. 2005 is the 2-D shape-manipulation idea it serves. On our
// lattice the legs of each right triangle weigh 1/2 and the diagonal 0.
// The handles add soft constraints: handle h is a fixed combination sum_k s_hk p_k of up to
// three vertices (a vertex, or a bound point's barycentrics) with a target q_h,
//     E = E_rigid + sum_h omega_h |sum_k s_hk p_k - q_h|^2,
// omega_h = weight_h * stiffness * (mean diagonal of the rigidity term), so the stiffness is a
// ratio that does not depend on the mesh's size or units.
//
// The local step (p fixed): each R_t minimises its own term alone. With M = sum w e' e^T (e the
// rest edge, e' the deformed one) and R the rotation by theta,
//     sum w |e' - R e|^2 = const - 2 (cos theta (M00 + M11) + sin theta (M10 - M01)),
// which is least at theta = atan2(M10 - M01, M00 + M11): no SVD is needed in 2-D. (When M is
// zero, a collapsed triangle, atan2(0, 0) = 0 keeps it deterministic.)
//
// The global step (R fixed): E is quadratic in p, and its normal equations are
//     (L + H) p = b_rigid(R) + b_handles(q),
// L the cotangent Laplacian (L_ii = sum w, L_ij = -w), H_kl = sum_h omega_h s_hk s_hl,
// b_rigid_i = sum over the edges ij of every t: w R_t (x_i - x_j), b_handles_k = sum_h omega_h
// s_hk q_h. The matrix does not depend on R or q: it is factorised once (SimplicialLDLT, AMD
// ordering) and each step is two triangular solves per coordinate. Each step solves for the
// correction from the current p ((L + H) d = b - (L + H) p): the same solution, but when p is right
// already (handles moved rigidly) the correction is rounding-sized, not the answer's rounding.
// Each step lowers E (or leaves it), so warm-started iterations converge.
//
// Constraint treatment: soft, not hard by elimination, because a handle may be a bound point
// (three vertices at once) and because a planner's handles need not agree exactly (a bone's
// handles and a region's overlap). With stiffness 1e4 a handle misses its target by about
// (the mesh's pull) / 1e4: on the 60-degree bar of the tests, 1e-5 px.
//
// Pieces: a connected piece of the mesh with no handle would make L + H singular (it could
// translate freely). Its vertices are left out of the system and follow the rigid fit of all
// the handles (the start below).
//
// The start: each piece of the rest mesh moved by the weighted least-squares rigid map of its
// handles' rest points to their targets (2-D Procrustes, its rotation by the same closed form);
// a piece whose handles fix no rotation (a single handle) takes the rotation of all handles' fit,
// a piece with none that whole fit. Then, for the pieces whose handles fix a rotation and a
// scale, the as-similar-as-possible solve (similarity_start.h, Igarashi et al.'s first step),
// which gets the rotations right everywhere in one linear solve: the local/global iterations
// carry a rotation from the handles inwards only slowly (a 40x200 bar bent by 60 degrees: 12 px
// from the converged shape after 6 iterations from the rigid start, 2.4 px from this one; the
// rest is the bar's length settling, a slow mode too). When the handles move rigidly together
// both starts are the exact answer, so the result is that rigid map to rounding. A warm start
// (the previous frame) replaces them: better when frames are a degree or two apart, worse after
// a larger step, and a loop's last frame no longer returns exactly to rest.
#include "motion/arap.h"

#include <cmath>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include "motion/similarity_start.h"
#include "svgmotion/error.h"

namespace svgm {

namespace {

struct Rigid {
  double c = 1, s = 0;
  Vec2 t;
  Vec2 apply(Vec2 p) const { return {c * p.x - s * p.y + t.x, s * p.x + c * p.y + t.y}; }
};

}  // namespace

double best_rotation_angle(const std::array<double, 4>& m) { return std::atan2(m[2] - m[1], m[0] + m[3]); }

struct ArapDeformer::Impl {
  std::vector<Vec2> rest;
  std::vector<std::array<int, 3>> triangles;  // of pieces with a handle
  std::vector<std::array<double, 3>> w;       // w[t][k]: edge (t[k], t[k+1 mod 3])
  std::vector<int> row;                       // vertex -> system row, -1: piece without handle
  int rows = 0;
  std::vector<int> vertex_piece;
  int pieces = 0;
  std::vector<ArapHandle> handles;
  std::vector<int> handle_piece;
  std::vector<double> omega;
  std::vector<Vec2> handle_rest;
  Eigen::SparseMatrix<double> a;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
  std::unique_ptr<SimilarityStart> similar;  // the cold start's as-similar-as-possible solve
  int iterations = 6;

  Vec2 handle_point(size_t h, const std::vector<Vec2>& p) const {
    const ArapHandle& hd = handles[h];
    return hd.share[0] * p[hd.vertex[0]] + hd.share[1] * p[hd.vertex[1]] + hd.share[2] * p[hd.vertex[2]];
  }

  // The weighted least-squares rotation and translation of the handles' rest points onto their
  // targets: of all handles (piece -1), or of one piece's. When the piece's handles do not fix a
  // rotation (one handle, or all at one rest point) it takes `fallback`'s rotation, translated
  // onto its handles.
  Rigid fit(const std::vector<Vec2>& targets, int piece, const Rigid& fallback) const {
    double total = 0;
    Vec2 cr, ct;
    for (size_t h = 0; h < handles.size(); ++h) {
      if (piece >= 0 && handle_piece[h] != piece) continue;
      total += handles[h].weight;
      cr = cr + handles[h].weight * handle_rest[h];
      ct = ct + handles[h].weight * targets[h];
    }
    if (total <= 0) return fallback;
    cr = (1 / total) * cr;
    ct = (1 / total) * ct;
    std::array<double, 4> m{};
    double spread = 0;
    for (size_t h = 0; h < handles.size(); ++h) {
      if (piece >= 0 && handle_piece[h] != piece) continue;
      const Vec2 e = handle_rest[h] - cr, f = targets[h] - ct;
      const double wt = handles[h].weight;
      m[0] += wt * f.x * e.x, m[1] += wt * f.x * e.y, m[2] += wt * f.y * e.x, m[3] += wt * f.y * e.y;
      spread += wt * (e.x * e.x + e.y * e.y);
    }
    Rigid r = fallback;
    if (spread > 0) {
      const double theta = best_rotation_angle(m);
      r.c = std::cos(theta), r.s = std::sin(theta);
    }
    r.t = ct - Vec2{r.c * cr.x - r.s * cr.y, r.s * cr.x + r.c * cr.y};
    return r;
  }

  // The rotation (cos, sin) of every triangle that best fits the positions p.
  std::vector<std::array<double, 2>> local_step(const std::vector<Vec2>& p) const {
    std::vector<std::array<double, 2>> rot(triangles.size());
    for (size_t t = 0; t < triangles.size(); ++t) {
      std::array<double, 4> m{};
      for (int k = 0; k < 3; ++k) {
        const int i = triangles[t][k], j = triangles[t][(k + 1) % 3];
        const Vec2 e = rest[i] - rest[j], f = p[i] - p[j];
        const double wk = w[t][k];
        m[0] += wk * f.x * e.x, m[1] += wk * f.x * e.y, m[2] += wk * f.y * e.x, m[3] += wk * f.y * e.y;
      }
      const double theta = best_rotation_angle(m);
      rot[t] = {std::cos(theta), std::sin(theta)};
    }
    return rot;
  }

  double energy(const std::vector<Vec2>& p, const std::vector<Vec2>& targets) const {
    const auto rot = local_step(p);
    double e = 0;
    for (size_t t = 0; t < triangles.size(); ++t)
      for (int k = 0; k < 3; ++k) {
        const int i = triangles[t][k], j = triangles[t][(k + 1) % 3];
        const Vec2 r = rest[i] - rest[j], f = p[i] - p[j];
        const Vec2 d = f - Vec2{rot[t][0] * r.x - rot[t][1] * r.y, rot[t][1] * r.x + rot[t][0] * r.y};
        e += w[t][k] * (d.x * d.x + d.y * d.y);
      }
    for (size_t h = 0; h < handles.size(); ++h) {
      const Vec2 d = handle_point(h, p) - targets[h];
      e += omega[h] * (d.x * d.x + d.y * d.y);
    }
    return e;
  }

  // One global step: p (all vertices) moves to the minimiser for the rotations rot.
  void global_step(const std::vector<std::array<double, 2>>& rot, const std::vector<Vec2>& targets,
                   std::vector<Vec2>& p) const {
    Eigen::VectorXd bx = Eigen::VectorXd::Zero(rows), by = Eigen::VectorXd::Zero(rows);
    for (size_t t = 0; t < triangles.size(); ++t)
      for (int k = 0; k < 3; ++k) {
        const int i = triangles[t][k], j = triangles[t][(k + 1) % 3];
        const Vec2 e = rest[i] - rest[j];
        const double gx = w[t][k] * (rot[t][0] * e.x - rot[t][1] * e.y);
        const double gy = w[t][k] * (rot[t][1] * e.x + rot[t][0] * e.y);
        bx[row[i]] += gx, by[row[i]] += gy;
        bx[row[j]] -= gx, by[row[j]] -= gy;
      }
    for (size_t h = 0; h < handles.size(); ++h)
      for (int k = 0; k < 3; ++k) {
        const double f = omega[h] * handles[h].share[k];
        bx[row[handles[h].vertex[k]]] += f * targets[h].x;
        by[row[handles[h].vertex[k]]] += f * targets[h].y;
      }
    Eigen::VectorXd px(rows), py(rows);
    for (size_t v = 0; v < p.size(); ++v)
      if (row[v] >= 0) px[row[v]] = p[v].x, py[row[v]] = p[v].y;
    const Eigen::VectorXd rx = bx - a * px, ry = by - a * py;
    px += solver.solve(rx);
    py += solver.solve(ry);
    for (size_t v = 0; v < p.size(); ++v)
      if (row[v] >= 0) p[v] = {px[row[v]], py[row[v]]};
  }
};

ArapDeformer::ArapDeformer(const ShapeMesh& mesh, std::vector<ArapHandle> handles, ArapOptions options)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.rest = mesh.vertices;
  m.vertex_piece = mesh.vertex_piece;
  m.pieces = mesh.pieces;
  m.iterations = options.iterations;
  if (!(options.stiffness > 0) || !std::isfinite(options.stiffness))
    throw Error("ArapDeformer: the stiffness must be positive and finite");
  const int n = static_cast<int>(mesh.vertices.size());
  std::vector<bool> piece_held(static_cast<size_t>(mesh.pieces), false);
  for (const ArapHandle& h : handles) {
    if (!(h.weight > 0) || !std::isfinite(h.weight))
      throw Error("ArapDeformer: a handle's weight must be positive and finite");
    for (int v : h.vertex) {
      if (v < 0 || v >= n) throw Error("ArapDeformer: a handle names no vertex of the mesh");
      piece_held[static_cast<size_t>(mesh.vertex_piece[v])] = true;
    }
    m.handle_piece.push_back(mesh.vertex_piece[h.vertex[0]]);
    m.handle_rest.push_back(h.share[0] * m.rest[h.vertex[0]] + h.share[1] * m.rest[h.vertex[1]] +
                            h.share[2] * m.rest[h.vertex[2]]);
  }
  m.handles = std::move(handles);
  m.row.assign(static_cast<size_t>(n), -1);
  for (int v = 0; v < n; ++v)
    if (piece_held[static_cast<size_t>(mesh.vertex_piece[v])]) m.row[v] = m.rows++;

  // Cotangent weights of the held pieces' triangles, and the rigidity term's matrix.
  std::vector<Eigen::Triplet<double>> entries;
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    if (m.row[tri[0]] < 0) continue;
    std::array<double, 3> wt{};
    for (int k = 0; k < 3; ++k) {
      const Vec2 o = m.rest[tri[(k + 2) % 3]];
      const Vec2 u = m.rest[tri[k]] - o, v = m.rest[tri[(k + 1) % 3]] - o;
      const double area2 = std::fabs(u.x * v.y - u.y * v.x);
      wt[k] = area2 > 0 ? 0.5 * (u.x * v.x + u.y * v.y) / area2 : 0;  // cot = dot / |cross|
      const int i = m.row[tri[k]], j = m.row[tri[(k + 1) % 3]];
      entries.emplace_back(i, i, wt[k]);
      entries.emplace_back(j, j, wt[k]);
      entries.emplace_back(i, j, -wt[k]);
      entries.emplace_back(j, i, -wt[k]);
    }
    m.triangles.push_back(tri);
    m.w.push_back(wt);
  }
  double diagonal = 0;
  for (const auto& e : entries)
    if (e.row() == e.col()) diagonal += e.value();
  const double unit = m.rows > 0 && diagonal > 0 ? diagonal / m.rows : 1;
  for (const ArapHandle& h : m.handles) {
    const double om = h.weight * options.stiffness * unit;
    m.omega.push_back(om);
    for (int k = 0; k < 3; ++k)
      for (int l = 0; l < 3; ++l)
        entries.emplace_back(m.row[h.vertex[k]], m.row[h.vertex[l]], om * h.share[k] * h.share[l]);
  }
  m.a.resize(m.rows, m.rows);
  m.a.setFromTriplets(entries.begin(), entries.end());  // duplicates are summed
  if (m.rows > 0) {
    m.solver.compute(m.a);
    if (m.solver.info() != Eigen::Success)
      throw Error("ArapDeformer: the system could not be factorised (a handle weight or vertex is not finite)");
  }

  // The similarity start solves the pieces whose handles fix a rotation and a scale: their rest
  // points spread (weighted RMS about their centroid) over more than kSpread of an edge.
  constexpr double kSpread = 0.05;  // of the mean rest edge length; below it, as good as one point
  double edges = 0;
  for (const auto& wt : m.triangles)
    for (int k = 0; k < 3; ++k) edges += std::hypot(m.rest[wt[k]].x - m.rest[wt[(k + 1) % 3]].x, m.rest[wt[k]].y - m.rest[wt[(k + 1) % 3]].y);
  const double mean_edge = m.triangles.empty() ? 0 : edges / (3.0 * m.triangles.size());
  std::vector<double> total(static_cast<size_t>(m.pieces), 0), spread(static_cast<size_t>(m.pieces), 0);
  std::vector<Vec2> centre(static_cast<size_t>(m.pieces));
  for (size_t h = 0; h < m.handles.size(); ++h) {
    total[m.handle_piece[h]] += m.handles[h].weight;
    centre[m.handle_piece[h]] = centre[m.handle_piece[h]] + m.handles[h].weight * m.handle_rest[h];
  }
  for (size_t h = 0; h < m.handles.size(); ++h) {
    const int piece = m.handle_piece[h];
    const Vec2 d = m.handle_rest[h] - (1 / total[piece]) * centre[piece];
    spread[piece] += m.handles[h].weight * (d.x * d.x + d.y * d.y) / total[piece];
  }
  std::vector<bool> solved(static_cast<size_t>(n));
  for (int v = 0; v < n; ++v) solved[v] = spread[mesh.vertex_piece[v]] > kSpread * kSpread * mean_edge * mean_edge;
  if (options.similarity_start) m.similar = std::make_unique<SimilarityStart>(m.rest, m.triangles, m.w, solved, m.handles, m.omega);
}

ArapDeformer::~ArapDeformer() = default;
ArapDeformer::ArapDeformer(ArapDeformer&&) noexcept = default;
ArapDeformer& ArapDeformer::operator=(ArapDeformer&&) noexcept = default;

const std::vector<Vec2>& ArapDeformer::handle_rest() const { return impl_->handle_rest; }

std::vector<Vec2> ArapDeformer::deform(const std::vector<Vec2>& targets, const std::vector<Vec2>* warm,
                                       int iterations) const {
  const Impl& m = *impl_;
  if (targets.size() != m.handles.size())
    throw Error("ArapDeformer::deform: one target per handle is needed");
  if (warm && warm->size() != m.rest.size())
    throw Error("ArapDeformer::deform: the warm start must have one position per vertex");
  const Rigid all = m.fit(targets, -1, Rigid{});
  std::vector<Rigid> start(static_cast<size_t>(m.pieces));
  for (int piece = 0; piece < m.pieces; ++piece) start[piece] = m.fit(targets, piece, all);
  std::vector<Vec2> p(m.rest.size());
  for (size_t v = 0; v < p.size(); ++v)
    p[v] = warm && m.row[v] >= 0 ? (*warm)[v] : start[m.vertex_piece[v]].apply(m.rest[v]);
  if (!warm && m.similar) m.similar->solve(targets, p);
  if (m.rows == 0) return p;
  for (int k = 0, K = iterations >= 0 ? iterations : m.iterations; k < K; ++k) m.global_step(m.local_step(p), targets, p);
  return p;
}

double ArapDeformer::energy(const std::vector<Vec2>& vertices, const std::vector<Vec2>& targets) const {
  if (targets.size() != impl_->handles.size() || vertices.size() != impl_->rest.size())
    throw Error("ArapDeformer::energy: one target per handle and one position per vertex are needed");
  return impl_->energy(vertices, targets);
}

}  // namespace svgm
