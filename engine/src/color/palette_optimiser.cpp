// Maximin packing of points in the unit cube: the optimiser behind distinct_palette.
//
// Problem. Place n points in [0,1]^3 (plus, for palettes, a point pinned at white (1,1,1))
// so that the smallest pairwise distance d is as large as possible. This is the "spreading
// points" form of packing n+1 equal spheres in a cube (Schaer 1966; Gensane 2004, "Dense
// packings of equal spheres in a cube", Electron. J. Combin. 11 #R33; Pfoertner's and Specht's
// (Packomania) tables of best known packings).
//
// Method, in three layers, all deterministic for a seed:
//
//  1. Soft-sphere relaxation at a target distance t ("overlap minimisation"): minimise
//     U(x) = sum over pairs with d_ij < t of (t - d_ij)^2 over the box, with FIRE (Bitzek et
//     al. 2006, "Structural relaxation made simple", PRL 97) and projection onto the box.
//     U = 0 means every distance is at least t; a jammed local minimum with U > 0 means t is
//     too large for this arrangement. This is the penalty form used by packing codes such as
//     the PBH / compression approaches for circle packing, and a finite-stiffness version of
//     Lubachevsky-Stillinger compression. Pairs come from a Verlet neighbour list (cell grid,
//     skin 0.35 t) so large N stays near-linear per step.
//
//  2. Squeeze (the maximin polish): from an arrangement with minimum distance d, relax at
//     t = d (1 + delta). If the result's true minimum distance beats d it becomes the
//     incumbent, else delta shrinks; stop when delta < 1e-6. Relaxing slightly above the
//     current minimum spreads the "overlap" over all the critical contacts at once, which is
//     what iterated push-the-closest-pair-apart does one pair at a time, without its
//     zig-zagging.
//
//  3. Global search: random starts mixed with monotonic basin hopping from the best packing
//     found (Addis, Locatelli & Schoen 2008, "Disk packing in a square: a new global
//     optimization approach", INFORMS J. Comput. 20): perturb the incumbent (re-place 1-3
//     points at random, or jitter every point by up to a quarter of d), squeeze, and keep the
//     result only if it is better. The search runs until a work budget (pair evaluations, not
//     wall time) is spent, so the result depends on the seed and the budget only.
//
// Quantisation to 8 bits then loses up to sqrt(3)/255 per pair in the worst case (both
// endpoints rounded half a step the wrong way in every coordinate); a grid local search
// (quantise_packing) wins most of that back by moving each colour to the neighbouring grid
// point that is farthest from its nearest neighbour.
#include "color/palette_optimiser.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace svgm::color {
namespace {

// SplitMix64: small, fast, and the same sequence everywhere (std:: distributions are not).
struct Rng {
  uint64_t s;
  uint64_t next() {
    uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  int below(int n) { return std::min(n - 1, static_cast<int>(uniform() * n)); }
};

// A rough guess of the maximin distance of m points in the unit cube, from a packing fraction
// of about 0.6 for spheres of diameter d in the cube of side 1 + d.
double guess_distance(int m) {
  const double k = std::cbrt(m * M_PI / (6.0 * 0.6));
  return k > 1.0 + 1.0 / std::sqrt(3.0) ? 1.0 / (k - 1.0) : std::sqrt(3.0);
}

class Packer {
 public:
  Packer(int free_points, bool pin_white, double budget)
      : m_(free_points + (pin_white ? 1 : 0)), first_free_(pin_white ? 1 : 0), budget_(budget) {
    f_.resize(3 * m_);
    v_.resize(3 * m_);
    built_at_.resize(3 * m_);
  }

  int m() const { return m_; }
  int first_free() const { return first_free_; }
  bool spent() const { return work_ >= budget_; }

  // The smallest pairwise distance (counting the pinned point).
  double min_distance(const std::vector<double>& x) {
    if (m_ < 2) return std::numeric_limits<double>::infinity();
    // Candidate pairs within a generous cutoff from the cell grid; everything else is farther.
    const double cut = 1.2 * guess_distance(m_);
    build_pairs(x, cut);
    double best2 = cut * cut;
    bool found = false;
    for (const auto& p : pairs_) {
      const double d2 = dist2(x, p[0], p[1]);
      if (d2 < best2) best2 = d2, found = true;
    }
    if (found) return std::sqrt(best2);
    work_ += 0.5 * m_ * m_;
    best2 = std::numeric_limits<double>::infinity();
    for (int i = 0; i < m_; ++i)
      for (int j = i + 1; j < m_; ++j) best2 = std::min(best2, dist2(x, i, j));
    return std::sqrt(best2);
  }

  // FIRE minimisation of the overlap energy at target distance t, in place.
  void relax(std::vector<double>& x, double t, int max_steps) {
    const double skin = 0.35 * t;
    build_pairs(x, t + skin);
    built_at_ = x;
    std::fill(v_.begin(), v_.end(), 0.0);
    double dt = 0.02, alpha = 0.1;
    constexpr double kDtMax = 0.2;
    int positive = 0;
    double max_overlap = 0;
    double energy = forces(x, t, &max_overlap);
    const int lo = 3 * first_free_, hi = 3 * m_;
    for (int step = 0; step < max_steps && !spent(); ++step) {
      if (energy == 0 || max_overlap < 1e-10 * t) break;  // feasible at t
      double p = 0, vv = 0, ff = 0, fmax = 0;
      for (int k = lo; k < hi; ++k) {
        p += f_[k] * v_[k];
        vv += v_[k] * v_[k];
        ff += f_[k] * f_[k];
        fmax = std::max(fmax, std::fabs(f_[k]));
      }
      if (fmax < 1e-4 * max_overlap) break;  // jammed: forces balanced against the overlaps
      if (p > 0) {
        const double s = ff > 0 ? alpha * std::sqrt(vv / ff) : 0.0;
        for (int k = lo; k < hi; ++k) v_[k] = (1 - alpha) * v_[k] + s * f_[k];
        if (++positive > 5) {
          dt = std::min(dt * 1.1, kDtMax);
          alpha *= 0.99;
        }
      } else {
        std::fill(v_.begin(), v_.end(), 0.0);
        dt *= 0.5;
        alpha = 0.1;
        positive = 0;
      }
      double moved2 = 0;
      for (int k = lo; k < hi; ++k) {
        v_[k] += dt * f_[k];
        x[k] += dt * v_[k];
        if (x[k] < 0) x[k] = 0, v_[k] = 0;
        if (x[k] > 1) x[k] = 1, v_[k] = 0;
      }
      for (int i = first_free_; i < m_; ++i) {
        double d2 = 0;
        for (int c = 0; c < 3; ++c) d2 += (x[3 * i + c] - built_at_[3 * i + c]) * (x[3 * i + c] - built_at_[3 * i + c]);
        moved2 = std::max(moved2, d2);
      }
      if (moved2 > 0.25 * skin * skin) {  // a point moved more than skin / 2: pairs may be missing
        build_pairs(x, t + skin);
        built_at_ = x;
      }
      energy = forces(x, t, &max_overlap);
    }
  }

  // Polish x by squeezing (see the essay); returns its minimum distance, x the best found.
  double squeeze(std::vector<double>& x, double t_start, int max_steps) {
    relax(x, t_start, max_steps);
    double best = min_distance(x);
    std::vector<double> y;
    for (double delta = 0.03; delta > 1e-6 && !spent();) {
      y = x;
      relax(y, best * (1 + delta), max_steps);
      const double d = min_distance(y);
      if (d > best) {
        best = d;
        x.swap(y);
      } else {
        delta *= 0.35;
      }
    }
    return best;
  }

 private:
  double dist2(const std::vector<double>& x, int i, int j) const {
    const double a = x[3 * i] - x[3 * j], b = x[3 * i + 1] - x[3 * j + 1], c = x[3 * i + 2] - x[3 * j + 2];
    return a * a + b * b + c * c;
  }

  // All pairs closer than cutoff, through a cell grid of cell size >= cutoff.
  void build_pairs(const std::vector<double>& x, double cutoff) {
    pairs_.clear();
    const double c2 = cutoff * cutoff;
    const int g = std::clamp(static_cast<int>(1.0 / cutoff), 1, 64);
    if (g < 3 || m_ < 64) {
      work_ += 0.5 * m_ * m_;
      for (int i = 0; i < m_; ++i)
        for (int j = i + 1; j < m_; ++j)
          if (dist2(x, i, j) < c2) pairs_.push_back({i, j});
      return;
    }
    const int cells = g * g * g;
    cell_of_.resize(m_);
    start_.assign(cells + 1, 0);
    order_.resize(m_);
    auto coord = [&](double u) { return std::clamp(static_cast<int>(u * g), 0, g - 1); };
    for (int i = 0; i < m_; ++i) {
      const int c = (coord(x[3 * i]) * g + coord(x[3 * i + 1])) * g + coord(x[3 * i + 2]);
      cell_of_[i] = c;
      ++start_[c + 1];
    }
    for (int c = 0; c < cells; ++c) start_[c + 1] += start_[c];
    fill_.assign(start_.begin(), start_.end() - 1);
    for (int i = 0; i < m_; ++i) order_[fill_[cell_of_[i]]++] = i;
    double checked = 0;
    for (int i = 0; i < m_; ++i) {
      const int c = cell_of_[i], cx = c / (g * g), cy = (c / g) % g, cz = c % g;
      for (int ax = std::max(cx - 1, 0); ax <= std::min(cx + 1, g - 1); ++ax)
        for (int ay = std::max(cy - 1, 0); ay <= std::min(cy + 1, g - 1); ++ay)
          for (int az = std::max(cz - 1, 0); az <= std::min(cz + 1, g - 1); ++az) {
            const int n = (ax * g + ay) * g + az;
            for (int k = start_[n]; k < start_[n + 1]; ++k) {
              const int j = order_[k];
              ++checked;
              if (j > i && dist2(x, i, j) < c2) pairs_.push_back({i, j});
            }
          }
    }
    work_ += checked;
  }

  // Forces (minus the gradient of the overlap energy, projected onto the box) and the energy.
  double forces(const std::vector<double>& x, double t, double* max_overlap) {
    std::fill(f_.begin(), f_.end(), 0.0);
    const double t2 = t * t;
    double energy = 0, worst = 0;
    for (const auto& p : pairs_) {
      const int i = p[0], j = p[1];
      double dx[3];
      for (int c = 0; c < 3; ++c) dx[c] = x[3 * i + c] - x[3 * j + c];
      const double d2 = dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2];
      if (d2 >= t2) continue;
      double d = std::sqrt(d2);
      if (d < 1e-15) {  // coincident points: push apart along a fixed direction
        dx[0] = 1e-15, dx[1] = dx[2] = 0, d = 1e-15;
      }
      const double ov = t - d;
      energy += ov * ov;
      worst = std::max(worst, ov);
      const double s = 2 * ov / d;
      for (int c = 0; c < 3; ++c) {
        f_[3 * i + c] += s * dx[c];
        f_[3 * j + c] -= s * dx[c];
      }
    }
    work_ += static_cast<double>(pairs_.size());
    for (int k = 0; k < 3 * first_free_; ++k) f_[k] = 0;
    for (int k = 3 * first_free_; k < 3 * m_; ++k)
      if ((x[k] <= 0 && f_[k] < 0) || (x[k] >= 1 && f_[k] > 0)) f_[k] = 0;
    *max_overlap = worst;
    return energy;
  }

  int m_, first_free_;
  double budget_, work_ = 0;
  std::vector<double> f_, v_, built_at_;
  std::vector<std::array<int, 2>> pairs_;
  std::vector<int> cell_of_, start_, fill_, order_;
};

// Lattice starts: the best packings for many n are pieces of the simple cubic, body-centred or
// face-centred cubic lattice fitted to the cube (27 points: 3x3x3; 32 and 63: FCC; 57..62: the
// 63-point FCC piece with points removed). These give every such lattice piece, possibly
// stretched (kx, ky, kz cells per axis), with at least m points and containing white when
// pinned, best nominal distance first.
struct LatticeStart {
  double nominal;  // nearest-neighbour distance of the full piece
  int type, kx, ky, kz, parity;  // type 0: SC, 1: BCC, 2: FCC (points with i+j+l = parity mod 2)
};

std::vector<LatticeStart> lattice_starts(int m, bool pin) {
  std::vector<LatticeStart> out;
  for (int kx = 1; kx <= 16; ++kx)
    for (int ky = kx; ky <= 16; ++ky)
      for (int kz = ky; kz <= 16; ++kz) {
        const double hx = 1.0 / kx, hy = 1.0 / ky, hz = 1.0 / kz;
        const long sc = static_cast<long>(kx + 1) * (ky + 1) * (kz + 1);
        const long bcc = sc + static_cast<long>(kx) * ky * kz;
        const long limit = m + m / 4 + 4;
        if (sc >= m && sc <= limit) out.push_back({hz, 0, kx, ky, kz, 0});
        if (bcc >= m && bcc <= limit)
          out.push_back({std::min(hz, 0.5 * std::sqrt(hx * hx + hy * hy + hz * hz)), 1, kx, ky, kz, 0});
        const double fcc = std::min({std::sqrt(hy * hy + hz * hz), 2 * hz});
        for (int parity = 0; parity < 2; ++parity) {
          if (pin && parity != (kx + ky + kz) % 2) continue;
          const long count = parity == 0 ? (sc + 1) / 2 : sc / 2;
          if (count >= m && count <= limit) out.push_back({fcc, 2, kx, ky, kz, parity});
        }
      }
  std::stable_sort(out.begin(), out.end(),
                   [](const LatticeStart& a, const LatticeStart& b) { return a.nominal > b.nominal; });
  if (out.size() > 6) out.resize(6);
  return out;
}

// The points of a lattice piece (axes permuted at random, so stretched pieces vary), white
// first when pinned, then m points in random order with the extras dropped.
void lattice_points(const LatticeStart& l, int m, bool pin, Rng& rng, std::vector<double>& x) {
  std::vector<Point3> pts;
  for (int i = 0; i <= l.kx; ++i)
    for (int j = 0; j <= l.ky; ++j)
      for (int k = 0; k <= l.kz; ++k) {
        if (l.type == 2 && (i + j + k) % 2 != l.parity) continue;
        pts.push_back({double(i) / l.kx, double(j) / l.ky, double(k) / l.kz});
        if (l.type == 1 && i < l.kx && j < l.ky && k < l.kz)
          pts.push_back({(i + 0.5) / l.kx, (j + 0.5) / l.ky, (k + 0.5) / l.kz});
      }
  int perm[3] = {0, 1, 2};
  for (int a = 2; a > 0; --a) std::swap(perm[a], perm[rng.below(a + 1)]);
  for (auto& p : pts) p = {p[perm[0]], p[perm[1]], p[perm[2]]};
  for (size_t a = pts.size() - 1; a > 0; --a) std::swap(pts[a], pts[rng.below(static_cast<int>(a) + 1)]);
  if (pin) {  // white first
    for (size_t a = 0; a < pts.size(); ++a)
      if (pts[a][0] == 1.0 && pts[a][1] == 1.0 && pts[a][2] == 1.0) std::swap(pts[0], pts[a]);
  }
  for (int i = 0; i < m; ++i)
    for (int c = 0; c < 3; ++c)
      x[3 * i + c] = std::clamp(pts[i][c] + (pin && i == 0 ? 0.0 : 1e-4 * (2 * rng.uniform() - 1)), 0.0, 1.0);
}

}  // namespace

double packing_min_distance(const std::vector<Point3>& points, bool pin_white) {
  std::vector<Point3> all = points;
  if (pin_white) all.push_back({1.0, 1.0, 1.0});
  double best2 = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < all.size(); ++i)
    for (size_t j = i + 1; j < all.size(); ++j) {
      double d2 = 0;
      for (int c = 0; c < 3; ++c) d2 += (all[i][c] - all[j][c]) * (all[i][c] - all[j][c]);
      best2 = std::min(best2, d2);
    }
  return std::sqrt(best2);
}

Packing pack_points(int n, const PackOptions& opt) {
  if (n < 0) throw std::invalid_argument("pack_points: negative point count");
  Packing out;
  if (n == 0) return out;
  Packer packer(n, opt.pin_white, opt.work);
  const int m = packer.m(), ff = packer.first_free();
  Rng rng{opt.seed * 0x2545F4914F6CDD1Dull + 0x1234567ull};
  // Step caps per relaxation: enough for FIRE to converge for any m here.
  const int steps = 4000;

  std::vector<double> x(3 * m), best_x;
  double best = -1;
  for (int k = 0; k < 3 * ff; ++k) x[k] = 1.0;  // white

  auto consider = [&](const std::vector<double>& y, double d) {
    if (d > best) best = d, best_x = y;
  };
  if (opt.start) {
    if (static_cast<int>(opt.start->size()) != n)
      throw std::invalid_argument("pack_points: start has the wrong number of points");
    for (int i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) x[3 * (ff + i) + c] = std::clamp((*opt.start)[i][c], 0.0, 1.0);
    const double d0 = packer.min_distance(x);
    const double d = packer.squeeze(x, d0 * 1.001, steps);
    consider(x, d);
  }
  const double guess = guess_distance(m);
  const auto lattices = lattice_starts(m, opt.pin_white);
  int round = 0, fresh_count = 0;
  do {
    const bool fresh = best < 0 || round % 3 == 0 || round < static_cast<int>(lattices.size());
    double t0;
    if (fresh) {
      // Every lattice piece once, then alternate random starts with lattice pieces.
      const int f = fresh_count++;
      const int lat = f < static_cast<int>(lattices.size()) ? f : (f % 2 == 0 ? -1 : (f / 2) % static_cast<int>(std::max<size_t>(lattices.size(), 1)));
      if (lat >= 0 && !lattices.empty()) {
        lattice_points(lattices[lat], m, opt.pin_white, rng, x);
        t0 = lattices[lat].nominal;
      } else {
        for (int k = 3 * ff; k < 3 * m; ++k) x[k] = rng.uniform();
        t0 = std::min(std::sqrt(3.0), guess * 1.1);
      }
    } else {
      x = best_x;
      if (rng.uniform() < 0.5) {
        const int moves = 1 + rng.below(3);
        for (int k = 0; k < moves && m > ff; ++k) {
          const int i = ff + rng.below(m - ff);
          for (int c = 0; c < 3; ++c) x[3 * i + c] = rng.uniform();
        }
      } else {
        const double a = 0.25 * best;
        for (int k = 3 * ff; k < 3 * m; ++k)
          x[k] = std::clamp(x[k] + a * (2 * rng.uniform() - 1), 0.0, 1.0);
      }
      t0 = best * 1.02;
    }
    const double d = packer.squeeze(x, t0, steps);
    consider(x, d);
    ++round;
  } while (!packer.spent());

  out.min_distance = best;
  out.points.resize(n);
  for (int i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) out.points[i][c] = best_x[3 * (ff + i) + c];
  return out;
}

namespace {

using Grid = std::vector<std::array<int, 3>>;

int grid_d2(const std::array<int, 3>& a, const std::array<int, 3>& b) {
  const int x = a[0] - b[0], y = a[1] - b[1], z = a[2] - b[2];
  return x * x + y * y + z * z;
}

int grid_min(const Grid& q) {
  int best = std::numeric_limits<int>::max();
  for (size_t i = 0; i < q.size(); ++i)
    for (size_t j = i + 1; j < q.size(); ++j) best = std::min(best, grid_d2(q[i], q[j]));
  return best;
}

// Greedy grid search: move each colour (q[0], white, stays) to the grid point within a few steps
// that is farthest from its nearest neighbour, while that distance grows. Every accepted move
// raises the sorted list of pair distances lexicographically, so it never lowers the minimum
// and it terminates.
void grid_search(Grid& q) {
  const int m = static_cast<int>(q.size());
  constexpr int kSteps[] = {8, 4, 2, 1};
  constexpr int kMaxMove2 = 3 * 8 * 8;  // a point moves at most this far (squared) per pass
  std::vector<std::vector<int>> near(m);
  for (int pass = 0; pass < 64 && m > 1; ++pass) {
    // Neighbour lists within `radius`; a colour outside the list cannot come closer than
    // `cap` during the pass (both ends move at most once), so nearest() may stop there.
    const double radius = 2.0 * std::sqrt(static_cast<double>(grid_min(q))) + 4.0 * std::sqrt(kMaxMove2);
    const double cap_len = radius - 2.0 * std::sqrt(kMaxMove2);
    const int cap = static_cast<int>(cap_len * cap_len);
    for (int i = 0; i < m; ++i) near[i].clear();
    for (int i = 0; i < m; ++i)
      for (int j = i + 1; j < m; ++j)
        if (grid_d2(q[i], q[j]) < radius * radius) near[i].push_back(j), near[j].push_back(i);
    auto nearest = [&](int i, const std::array<int, 3>& at) {
      int best = cap;
      for (int j : near[i]) best = std::min(best, grid_d2(at, q[j]));
      return best;
    };
    bool changed = false;
    for (int i = 1; i < m; ++i) {
      int cur = nearest(i, q[i]);
      std::array<int, 3> pick = q[i];
      for (int s : kSteps)
        for (int dx = -1; dx <= 1; ++dx)
          for (int dy = -1; dy <= 1; ++dy)
            for (int dz = -1; dz <= 1; ++dz) {
              const std::array<int, 3> c = {q[i][0] + s * dx, q[i][1] + s * dy, q[i][2] + s * dz};
              if (c[0] < 0 || c[0] > 255 || c[1] < 0 || c[1] > 255 || c[2] < 0 || c[2] > 255) continue;
              const int v = nearest(i, c);
              if (v > cur) cur = v, pick = c;
            }
      if (pick != q[i]) q[i] = pick, changed = true;
    }
    if (!changed) break;
  }
}

}  // namespace

std::vector<Rgb8> quantise_packing(const std::vector<Point3>& points) {
  const int n = static_cast<int>(points.size()), m = n + 1;  // index 0: white, fixed
  // Several roundings: to nearest, then with a per-axis offset (points sharing a coordinate
  // level, as in lattice pieces, still round alike), each followed by the grid search; the
  // one with the largest minimum wins. Fewer trials for large palettes (cost ~ m^2 each).
  const int trials = m <= 300 ? 12 : (m <= 1200 ? 3 : 1);
  Rng rng{0x9A1E77Eull};
  Grid best;
  int best_min = -1;
  for (int t = 0; t < trials; ++t) {
    double off[3] = {0.5, 0.5, 0.5};
    if (t > 0)
      for (double& o : off) o = rng.uniform();
    Grid q(m, {255, 255, 255});
    for (int i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c)
        q[i + 1][c] = std::clamp(static_cast<int>(std::floor(std::clamp(points[i][c], 0.0, 1.0) * 255.0 + off[c])), 0, 255);
    grid_search(q);
    const int d = m > 1 ? grid_min(q) : 0;
    if (d > best_min) best_min = d, best = q;
  }
  std::vector<Rgb8> out(n);
  for (int i = 0; i < n; ++i)
    out[i] = {static_cast<uint8_t>(best[i + 1][0]), static_cast<uint8_t>(best[i + 1][1]),
              static_cast<uint8_t>(best[i + 1][2])};
  return out;
}

}  // namespace svgm::color
