// The as-similar-as-possible first guess of an ARAP solve: see similarity_start.h for the maths.
#include "motion/similarity_start.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include "svgmotion/error.h"

namespace svgm {

struct SimilarityStart::Impl {
  std::vector<int> row;  // vertex -> first of its two rows (x, then y), -1 when not solved
  int rows = 0;
  std::vector<ArapHandle> handles;  // those of solved pieces
  std::vector<size_t> handle_index; // their places in the full list (and its targets)
  std::vector<double> omega;
  Eigen::SparseMatrix<double> a;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
};

SimilarityStart::SimilarityStart(const std::vector<Vec2>& rest, const std::vector<std::array<int, 3>>& triangles,
                                 const std::vector<std::array<double, 3>>& w, const std::vector<bool>& solved,
                                 const std::vector<ArapHandle>& handles, const std::vector<double>& omega)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.row.assign(rest.size(), -1);
  for (size_t v = 0; v < rest.size(); ++v)
    if (solved[v]) m.row[v] = m.rows, m.rows += 2;
  std::vector<Eigen::Triplet<double>> entries;
  for (size_t t = 0; t < triangles.size(); ++t) {
    const auto& tri = triangles[t];
    if (m.row[tri[0]] < 0) continue;
    // g.p = sum w f.e and h.p = sum w e x f, as coefficients on the triangle's six coordinates
    // (vertex k's x at 2k, y at 2k + 1); the Laplacian part sum w |f|^2 edge by edge.
    double g[6] = {}, h[6] = {}, c = 0;
    for (int k = 0; k < 3; ++k) {
      const int a = k, b = (k + 1) % 3, i = tri[a], j = tri[b];
      const Vec2 e = rest[i] - rest[j];
      const double wk = w[t][k];
      c += wk * (e.x * e.x + e.y * e.y);
      g[2 * a] += wk * e.x, g[2 * b] -= wk * e.x, g[2 * a + 1] += wk * e.y, g[2 * b + 1] -= wk * e.y;
      h[2 * a + 1] += wk * e.x, h[2 * b + 1] -= wk * e.x, h[2 * a] -= wk * e.y, h[2 * b] += wk * e.y;
      for (int d = 0; d < 2; ++d) {
        const int ri = m.row[i] + d, rj = m.row[j] + d;
        entries.emplace_back(ri, ri, wk);
        entries.emplace_back(rj, rj, wk);
        entries.emplace_back(ri, rj, -wk);
        entries.emplace_back(rj, ri, -wk);
      }
    }
    if (!(c > 0)) continue;
    for (int u = 0; u < 6; ++u)
      for (int v = 0; v < 6; ++v) {
        const double value = -(g[u] * g[v] + h[u] * h[v]) / c;
        if (value != 0) entries.emplace_back(m.row[tri[u / 2]] + u % 2, m.row[tri[v / 2]] + v % 2, value);
      }
  }
  for (size_t hd = 0; hd < handles.size(); ++hd) {
    if (m.row[handles[hd].vertex[0]] < 0) continue;
    m.handles.push_back(handles[hd]);
    m.handle_index.push_back(hd);
    m.omega.push_back(omega[hd]);
    for (int k = 0; k < 3; ++k)
      for (int l = 0; l < 3; ++l)
        for (int d = 0; d < 2; ++d)
          entries.emplace_back(m.row[handles[hd].vertex[k]] + d, m.row[handles[hd].vertex[l]] + d,
                               omega[hd] * handles[hd].share[k] * handles[hd].share[l]);
  }
  if (m.rows == 0) return;
  m.a.resize(m.rows, m.rows);
  m.a.setFromTriplets(entries.begin(), entries.end());
  m.solver.compute(m.a);
  if (m.solver.info() != Eigen::Success)
    throw Error("ArapDeformer: the similarity start could not be factorised (a handle weight or vertex is not finite)");
}

SimilarityStart::~SimilarityStart() = default;
SimilarityStart::SimilarityStart(SimilarityStart&&) noexcept = default;
SimilarityStart& SimilarityStart::operator=(SimilarityStart&&) noexcept = default;

void SimilarityStart::solve(const std::vector<Vec2>& targets, std::vector<Vec2>& p) const {
  const Impl& m = *impl_;
  if (m.rows == 0) return;
  Eigen::VectorXd b = Eigen::VectorXd::Zero(m.rows), x(m.rows);
  for (size_t h = 0; h < m.handles.size(); ++h) {
    const Vec2 q = targets[m.handle_index[h]];
    for (int k = 0; k < 3; ++k) {
      const double f = m.omega[h] * m.handles[h].share[k];
      b[m.row[m.handles[h].vertex[k]]] += f * q.x;
      b[m.row[m.handles[h].vertex[k]] + 1] += f * q.y;
    }
  }
  for (size_t v = 0; v < p.size(); ++v)
    if (m.row[v] >= 0) x[m.row[v]] = p[v].x, x[m.row[v] + 1] = p[v].y;
  // The correction from the start given (see arap.cpp: exact when the start is the answer).
  const Eigen::VectorXd r = b - m.a * x;
  x += m.solver.solve(r);
  for (size_t v = 0; v < p.size(); ++v)
    if (m.row[v] >= 0) p[v] = {x[m.row[v]], x[m.row[v] + 1]};
}

}  // namespace svgm
