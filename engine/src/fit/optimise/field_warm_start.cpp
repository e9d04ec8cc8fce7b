// The least-squares field increment of a keyframe's warm start (see field_warm_start.h).
#include "fit/optimise/field_warm_start.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

namespace svgm {

std::optional<std::vector<Vec2>> fit_field_increment(const FitPlan& plan, const FieldTargets& t, double lambda, double mu) {
  const int n = plan.n_nodes;
  std::vector<Vec2> out(static_cast<size_t>(n));
  if (n == 0 || t.point.empty()) return out;
  std::vector<Eigen::Triplet<double>> a;
  a.reserve(t.point.size() * 81 + static_cast<size_t>(n) * 19);
  Eigen::VectorXd bx = Eigen::VectorXd::Zero(n), by = Eigen::VectorXd::Zero(n);
  // Data: w ‖Σ W_b c_b − d‖² adds w W_a W_b to A(a, b) and w W_b d to the right-hand side.
  for (size_t j = 0; j < t.point.size(); ++j) {
    const int i = t.point[j];
    const double w = t.weight[j];
    for (int e = plan.cp_node_first[i]; e < plan.cp_node_first[i + 1]; ++e) {
      const int na = plan.cp_node[e];
      const double wa = plan.cp_node_w[e];
      bx[na] += w * wa * t.offset[j].x;
      by[na] += w * wa * t.offset[j].y;
      for (int f = plan.cp_node_first[i]; f < plan.cp_node_first[i + 1]; ++f)
        a.emplace_back(na, plan.cp_node[f], w * wa * plan.cp_node_w[f]);
    }
  }
  // Bending: each triple (L, b, R) with coefficients (1, −2, 1), once, from its middle node.
  for (int b = 0; b < n; ++b) {
    a.emplace_back(b, b, mu);
    for (int axis = 0; axis < 2; ++axis) {
      const int L = plan.node_bend[4 * static_cast<size_t>(b) + 2 * axis];
      const int R = plan.node_bend[4 * static_cast<size_t>(b) + 2 * axis + 1];
      if (L < 0 || R < 0) continue;
      const int idx[3] = {L, b, R};
      const double coef[3] = {1, -2, 1};
      for (int u = 0; u < 3; ++u)
        for (int v = 0; v < 3; ++v) a.emplace_back(idx[u], idx[v], lambda * coef[u] * coef[v]);
    }
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(a.begin(), a.end());  // duplicates are summed
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(A);
  if (solver.info() != Eigen::Success) return std::nullopt;
  const Eigen::VectorXd cx = solver.solve(bx), cy = solver.solve(by);
  if (solver.info() != Eigen::Success || !cx.allFinite() || !cy.allFinite()) return std::nullopt;
  for (int b = 0; b < n; ++b) out[static_cast<size_t>(b)] = {cx[b], cy[b]};
  return out;
}

}  // namespace svgm
