// The backward pass of stroke expansion: the CPU reference against central finite differences
// of ref::stroke, the OpenCL kernel against the CPU reference, and the kernel's determinism.
//
// Cases are built as raster plans directly (no scene): random polylines, open and closed, with
// every join (miter, miter-clip, round, bevel, and cubic-interior vertices), every cap, shallow
// and sharp turns, short segments (the inner join falls back to the pivot), zero-length
// segments (inherited directions) and single-point dots. Random cases within 1e-4 of a branch
// switch of the forward are redrawn (ref::stroke_branches measures the distance).
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "opencl/tuning.h"
#include "raster/raster_plan.h"
#include "raster/raster_ref.h"
#include "raster/stroke_backward_ref.h"
#include "raster_test_support.h"

using namespace svgm;
using namespace svgm::test;

namespace {

struct Poly {
  std::vector<std::array<double, 2>> pts;
  bool closed = false;
  int join = kJoinMiter, cap = kCapButt;
  double h = 2, miter_limit = 4;
  std::vector<uint8_t> kinds;  // per vertex; empty: the path's join everywhere
};

struct Case {
  RasterPlan plan;
  std::vector<double> pts;  // n_pts (x, y) pairs: the vertices, then room for the outlines
};

Case make_case(const std::vector<Poly>& polys) {
  Case c;
  RasterPlan& plan = c.plan;
  plan.width = plan.height = 64;
  int nv = 0;
  for (const Poly& p : polys) nv += static_cast<int>(p.pts.size());
  plan.n_flat = nv;
  int v = 0, out = nv;
  for (const Poly& p : polys) {
    StrokeSubpath s;
    s.first_vertex = v;
    s.vertex_count = static_cast<int>(p.pts.size());
    s.closed = p.closed ? 1 : 0;
    s.cap = p.cap;
    s.join = p.join;
    s.join_points = p.join == kJoinRound ? 4 : p.join == kJoinMiterClip ? 2 : 1;
    s.cap_points = p.cap == kCapRound ? 5 : p.cap == kCapSquare ? 2 : 0;
    s.half_width = static_cast<float>(p.h);
    s.miter_limit = static_cast<float>(p.miter_limit);
    s.first_out = out;
    out += stroke_point_count(s);
    plan.strokes.push_back(s);
    for (size_t i = 0; i < p.pts.size(); ++i)
      plan.vert_join.push_back(p.kinds.empty() ? static_cast<uint8_t>(p.join) : p.kinds[i]);
    v += s.vertex_count;
  }
  plan.n_pts = out;
  c.pts.assign(static_cast<size_t>(out) * 2, 0.0);
  v = 0;
  for (const Poly& p : polys)
    for (const auto& q : p.pts) {
      c.pts[2 * v] = q[0];
      c.pts[2 * v + 1] = q[1];
      ++v;
    }
  return c;
}

// A random polyline: a walk of long, short and zero-length steps with shallow, general and
// sharp turns.
Poly random_poly(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto pick = [&](int n) { return static_cast<int>(u(rng) * n) % n; };
  Poly p;
  const int N = 2 + pick(7);
  p.closed = N >= 3 && u(rng) < 0.5;
  p.join = pick(4);
  p.cap = pick(3);
  p.h = std::array<double, 4>{0.75, 1.5, 2.5, 4.0}[pick(4)];
  p.miter_limit = std::array<double, 4>{1.2, 2.0, 4.0, 10.0}[pick(4)];
  double x = 20 + 24 * u(rng), y = 20 + 24 * u(rng), a = 2 * M_PI * u(rng);
  const double deg = M_PI / 180;
  for (int i = 0; i < N; ++i) {
    p.pts.push_back({x, y});
    const double sign = u(rng) < 0.5 ? -1.0 : 1.0;
    const double r = u(rng);
    a += sign * (r < 0.3 ? (5 + 20 * u(rng)) * deg : r < 0.6 ? (140 + 32 * u(rng)) * deg
                                                              : (30 + 110 * u(rng)) * deg);
    const double l = u(rng);
    const double len = l < 0.12 ? 0.0 : l < 0.45 ? 0.5 + 2.5 * u(rng) : 6 + 14 * u(rng);
    x += len * std::cos(a);
    y += len * std::sin(a);
  }
  for (int i = 0; i < N; ++i)
    p.kinds.push_back(u(rng) < 0.3 ? uint8_t{kJoinInterior} : static_cast<uint8_t>(p.join));
  return p;
}

// Hand-made cases for the corners random walks rarely reach.
std::vector<Poly> special_polys() {
  std::vector<Poly> v;
  auto add = [&](std::vector<std::array<double, 2>> pts, bool closed, int join, int cap,
                 double h = 2.0, double ml = 4.0) {
    Poly p;
    p.pts = std::move(pts);
    p.closed = closed;
    p.join = join;
    p.cap = cap;
    p.h = h;
    p.miter_limit = ml;
    v.push_back(p);
  };
  add({{20, 20}}, false, kJoinMiter, kCapRound, 3);                        // dot, round caps
  add({{30, 22}}, false, kJoinMiter, kCapSquare, 1.5);                     // dot, square caps
  add({{12, 40}, {12, 40}, {12, 40}}, false, kJoinRound, kCapRound);       // all degenerate
  add({{10, 10}, {10, 10}, {30, 12}, {35, 25}}, false, kJoinMiter, kCapSquare);  // leading 0
  add({{10, 50}, {30, 52}, {35, 60}, {35, 60}}, false, kJoinRound, kCapRound);   // trailing 0
  add({{10, 10}, {30, 10}, {30, 30}, {10, 10}}, true, kJoinMiter, kCapButt);     // last 0
  add({{40, 10}, {40, 10}, {60, 10}, {60, 30}}, true, kJoinRound, kCapButt);     // first 0 wraps
  add({{40, 40}, {42, 40}, {42, 42}, {40, 42}}, true, kJoinMiter, kCapButt);     // X -> pivot
  add({{10, 10}, {40, 10}, {40, 40}}, false, kJoinMiterClip, kCapButt, 2, 1.2);  // clipped
  add({{5, 30}, {25, 31}, {6, 33}}, false, kJoinMiterClip, kCapSquare, 1.5, 2);  // sharp clip
  add({{5, 5}, {25, 6}, {6, 8}}, false, kJoinMiter, kCapRound, 1.5, 10);         // long miter
  add({{50, 50}, {60, 50}, {60, 50}, {60, 50}, {50, 58}}, false, kJoinBevel, kCapRound);
  return v;
}

double max_abs(const std::vector<double>& v, size_t n) {
  double m = 0;
  for (size_t i = 0; i < n; ++i) m = std::max(m, std::fabs(v[i]));
  return m;
}

// The source segment of segment i's direction (the forward's search), -1 for none.
int dir_source(const Case& c, const StrokeSubpath& s, int i) {
  const int N = s.vertex_count, S = s.closed ? N : std::max(N - 1, 1);
  auto valid = [&](int j) {
    const int a = s.first_vertex + j, b = s.first_vertex + (j + 1) % N;
    const double dx = c.pts[2 * b] - c.pts[2 * a], dy = c.pts[2 * b + 1] - c.pts[2 * a + 1];
    return dx * dx + dy * dy > 1e-12;
  };
  for (int j = i; j >= 0; --j)
    if (valid(j)) return j;
  if (s.closed) {
    for (int j = S - 1; j > i; --j)
      if (valid(j)) return j;
  } else {
    for (int j = i + 1; j < S; ++j)
      if (valid(j)) return j;
  }
  return -1;
}

// Per point: whether it is a vertex at the end of an exactly zero-length segment.
std::vector<bool> touches_zero_length(const Case& c) {
  std::vector<bool> z(static_cast<size_t>(c.plan.n_pts), false);
  for (const StrokeSubpath& s : c.plan.strokes) {
    const int N = s.vertex_count, S = s.closed ? N : std::max(N - 1, 1);
    for (int j = 0; j < S; ++j) {
      const int a = s.first_vertex + j, b = s.first_vertex + (j + 1) % N;
      if (c.pts[2 * a] == c.pts[2 * b] && c.pts[2 * a + 1] == c.pts[2 * b + 1]) z[a] = z[b] = true;
    }
  }
  return z;
}

// Per point: whether it is one of the J points of a join whose two directions come from the
// same segment (next to a zero-length segment). There the double reference has turn == 0
// exactly (an outer join on both sides), while the OpenCL compiler contracts cross2(d, d) into
// an fma whose rounding residue (~1e-9, either sign) makes one side an inner join (J points on
// the pivot). Both outlines fill the same (a zero-area spike), and each backward is exact for
// its own forward, but they differ at these points, so the kernel comparison leaves them out.
std::vector<bool> straight_join_points(const Case& c) {
  std::vector<bool> m(static_cast<size_t>(c.plan.n_pts), false);
  for (const StrokeSubpath& s : c.plan.strokes) {
    const int N = s.vertex_count, S = s.closed ? N : std::max(N - 1, 1), J = s.join_points;
    auto straight = [&](int v) {
      return dir_source(c, s, (v + S - 1) % S) == dir_source(c, s, v % S);
    };
    int w = s.first_out;
    auto mark = [&](bool on) {
      for (int j = 0; j < J; ++j) m[w + j] = on;
      w += J;
    };
    for (int i = 0; i < S; ++i) {
      w += 2;
      if (i + 1 < S || s.closed) mark(straight(i + 1));
    }
    if (!s.closed) w += s.cap_points;
    for (int i = S - 1; i >= 0; --i) {
      if (s.closed) mark(straight(i + 1));
      w += 2;
      if (i > 0 && !s.closed) mark(straight(i));
    }
  }
  return m;
}

// Outline gradients: uniform in [-1, 1] at the outline points, zero at the vertices.
std::vector<double> random_outline_grad(const Case& c, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> g(c.pts.size(), 0.0);
  for (size_t i = 2 * static_cast<size_t>(c.plan.n_flat); i < g.size(); ++i) g[i] = u(rng);
  return g;
}

// Max relative error of the reference VJP against central differences of ref::stroke, for
// coordinates differenced with the normal step ([0]) and the small one ([1]). Relative to
// max(|analytic|, |differences|, 1e-3 x the largest vertex gradient of the case).
std::array<double, 2> fd_check(const Case& c, std::mt19937& rng) {
  const size_t nv = 2 * static_cast<size_t>(c.plan.n_flat);
  const auto g = random_outline_grad(c, rng);
  auto grad = g;
  ref::stroke_backward(c.plan, c.pts, grad);
  const double scale = max_abs(grad, nv);
  const auto zero = touches_zero_length(c);
  std::array<double, 2> worst{0, 0};
  for (size_t x = 0; x < nv; ++x) {
    // 1e-5 is far below the 1e-4 branch margin; next to a zero-length segment 4e-7 keeps the
    // segment's squared length below the 1e-12 degenerate threshold.
    const double eps = zero[x / 2] ? 4e-7 : 1e-5;
    auto pp = c.pts, pm = c.pts;
    pp[x] += eps;
    pm[x] -= eps;
    ref::stroke(c.plan, pp);
    ref::stroke(c.plan, pm);
    double fd = 0;
    for (size_t k = nv; k < g.size(); ++k) fd += g[k] * (pp[k] - pm[k]);
    fd /= 2 * eps;
    const double rel = std::fabs(grad[x] - fd) /
                       std::max({std::fabs(grad[x]), std::fabs(fd), 1e-3 * scale, 1e-12});
    if (rel > 1e-6)
      MESSAGE("vertex coordinate " << x << ": analytic " << grad[x] << ", differences " << fd);
    double& w = worst[zero[x / 2] ? 1 : 0];
    w = std::max(w, rel);
  }
  return worst;
}

// Random polylines whose forward stays at least 1e-4 away from every branch switch.
Case random_case(std::mt19937& rng, int n_polys) {
  for (;;) {
    std::vector<Poly> polys;
    for (int i = 0; i < n_polys; ++i) polys.push_back(random_poly(rng));
    Case c = make_case(polys);
    if (ref::stroke_branches(c.plan, c.pts).margin > 1e-4) return c;
  }
}

void add_branches(ref::StrokeBranches& t, const ref::StrokeBranches& b) {
  t.inner_x += b.inner_x; t.inner_pivot += b.inner_pivot;
  t.miter += b.miter; t.miter_clip += b.miter_clip; t.miter_over += b.miter_over;
  t.bevel += b.bevel; t.round += b.round; t.straight += b.straight;
  t.square_caps += b.square_caps; t.round_caps += b.round_caps;
  t.inherited += b.inherited; t.dots += b.dots;
  t.margin = std::min(t.margin, b.margin);
}

void check_coverage(const ref::StrokeBranches& t) {
  MESSAGE("branches (join vertex sides / caps / segments): inner X " << t.inner_x << ", inner pivot "
          << t.inner_pivot << ", miter " << t.miter << ", clipped " << t.miter_clip
          << ", over the limit " << t.miter_over << ", bevel " << t.bevel << ", round " << t.round
          << ", straight by inheritance " << t.straight << ", square caps " << t.square_caps
          << ", round caps " << t.round_caps << ", inherited segments " << t.inherited
          << ", dots " << t.dots << "; smallest branch margin " << t.margin);
  CHECK(t.inner_x > 0);
  CHECK(t.inner_pivot > 0);
  CHECK(t.miter > 0);
  CHECK(t.miter_clip > 0);
  CHECK(t.miter_over > 0);
  CHECK(t.bevel > 0);
  CHECK(t.round > 0);
  CHECK(t.straight > 0);
  CHECK(t.square_caps > 0);
  CHECK(t.round_caps > 0);
  CHECK(t.inherited > 0);
  CHECK(t.dots > 0);
}

// The stroke forward and backward kernels, built as the brief of stroke_backward.cl says.
class ClStroke {
 public:
  ClStroke(ClRuntime& rt, const RasterPlan& plan, int frames) : rt_(rt), plan_(plan), K_(frames) {
    cl::Program& prog =
        rt.program({"stroke.cl", "stroke_backward.cl"},
                   kernel_build_options(raster_tuning(rt.info(), plan.width)));
    fwd_ = cl::Kernel(prog, "stroke");
    bwd_ = cl::Kernel(prog, "stroke_backward");
    std::vector<int> a, b;
    std::vector<float> f;
    for (const auto& s : plan.strokes) {
      a.insert(a.end(), {s.first_vertex, s.vertex_count, s.first_out, s.closed});
      b.insert(b.end(), {s.cap, s.join_points, s.cap_points, s.join});
      f.insert(f.end(), {s.half_width, s.miter_limit});
    }
    auto make = [&](size_t bytes, const void* host) {
      if (host) return input_buffer(rt.context(), host, bytes);
      return cl::Buffer(rt.context(), CL_MEM_READ_WRITE, std::max(bytes, kMinBufferBytes));
    };
    sp_a_ = make(a.size() * sizeof(int), a.data());
    sp_b_ = make(b.size() * sizeof(int), b.data());
    sp_f_ = make(f.size() * sizeof(float), f.data());
    vkind_ = make(plan.vert_join.size(), plan.vert_join.data());
    pts_ = make(bytes(), nullptr);
    grad_ = make(bytes(), nullptr);
    const int n_sp = static_cast<int>(plan.strokes.size());
    int i = 0;
    for (const auto& arg : {pts_, sp_a_, sp_b_, sp_f_, vkind_}) fwd_.setArg(i++, arg);
    fwd_.setArg(5, n_sp);
    fwd_.setArg(6, plan.n_pts);
    i = 0;
    for (const auto& arg : {pts_, grad_, sp_a_, sp_b_, sp_f_, vkind_}) bwd_.setArg(i++, arg);
    bwd_.setArg(6, n_sp);
    bwd_.setArg(7, plan.n_pts);
  }

  // Runs the forward on K frames of polylines (K * n_pts pairs); returns the outlines.
  std::vector<float> forward(const std::vector<float>& pts) {
    rt_.queue().enqueueWriteBuffer(pts_, CL_TRUE, 0, bytes(), pts.data());
    rt_.queue().enqueueNDRangeKernel(fwd_, cl::NullRange, range());
    std::vector<float> out(pts.size());
    rt_.queue().enqueueReadBuffer(pts_, CL_TRUE, 0, bytes(), out.data());
    return out;
  }

  // Runs the backward on the polylines of the last forward with gradients `grad` (K * n_pts
  // pairs); returns the gradients after it.
  std::vector<float> backward(const std::vector<float>& grad) {
    rt_.queue().enqueueWriteBuffer(grad_, CL_TRUE, 0, bytes(), grad.data());
    rt_.queue().enqueueNDRangeKernel(bwd_, cl::NullRange, range());
    std::vector<float> out(grad.size());
    rt_.queue().enqueueReadBuffer(grad_, CL_TRUE, 0, bytes(), out.data());
    return out;
  }

 private:
  size_t bytes() const { return static_cast<size_t>(K_) * plan_.n_pts * 2 * sizeof(float); }
  cl::NDRange range() const {
    return cl::NDRange((plan_.strokes.size() + 7) / 8 * 8, static_cast<size_t>(K_));
  }

  ClRuntime& rt_;
  const RasterPlan& plan_;
  int K_;
  cl::Kernel fwd_, bwd_;
  cl::Buffer sp_a_, sp_b_, sp_f_, vkind_, pts_, grad_;
};

// Frame k of a case: k = 0 as is, 1 mirrored in x, 2 rotated a quarter turn (every branch
// margin is invariant under these).
std::vector<double> frame_of(const Case& c, int k) {
  std::vector<double> p = c.pts;
  for (int v = 0; v < c.plan.n_flat; ++v) {
    const double x = p[2 * v], y = p[2 * v + 1];
    if (k == 1) p[2 * v] = 64 - x;
    if (k == 2) { p[2 * v] = 64 - y; p[2 * v + 1] = x; }
  }
  return p;
}

struct KernelResult {
  double max_rel = 0;      // vertex gradients: max |kernel - reference| / gradient scale
  double max_fwd = 0;      // outline points: max |kernel - reference|
  bool same_bits = false;  // two backward runs agree bit for bit
};

KernelResult kernel_check(const Case& c, std::mt19937& rng) {
  const int K = 3;
  const size_t n2 = static_cast<size_t>(c.plan.n_pts) * 2;
  const size_t nv = 2 * static_cast<size_t>(c.plan.n_flat);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const auto straight = straight_join_points(c);
  std::vector<float> pts(K * n2), grad(K * n2);
  for (int k = 0; k < K; ++k) {
    const auto f = frame_of(c, k);
    for (size_t i = 0; i < n2; ++i) {
      pts[k * n2 + i] = i < nv ? static_cast<float>(f[i]) : 0.0f;
      // Vertices get gradients too: the kernel adds to them.
      grad[k * n2 + i] = straight[i / 2] ? 0.0f : static_cast<float>(u(rng));
    }
  }
  ClStroke cs(runtime(), c.plan, K);
  const auto out = cs.forward(pts);
  const auto g1 = cs.backward(grad);
  const auto g2 = cs.backward(grad);
  KernelResult r;
  r.same_bits = std::memcmp(g1.data(), g2.data(), g1.size() * sizeof(float)) == 0;
  for (int k = 0; k < K; ++k) {
    // The reference on the very same (float) geometry and gradients.
    std::vector<double> p(pts.begin() + k * n2, pts.begin() + (k + 1) * n2);
    std::vector<double> g(grad.begin() + k * n2, grad.begin() + (k + 1) * n2);
    std::vector<double> added(n2, 0.0);
    std::copy(g.begin() + nv, g.end(), added.begin() + nv);
    ref::stroke_backward(c.plan, p, added);  // the vertex gradients alone
    const double scale = std::max(max_abs(added, nv), 1e-30);
    for (size_t i = 0; i < nv; ++i) {
      const double want = g[i] + added[i];
      r.max_rel = std::max(r.max_rel, std::fabs(g1[k * n2 + i] - want) / scale);
    }
    for (size_t i = nv; i < n2; ++i) CHECK(g1[k * n2 + i] == grad[k * n2 + i]);  // untouched
    ref::stroke(c.plan, p);
    for (size_t i = nv; i < n2; ++i)
      if (!straight[i / 2]) r.max_fwd = std::max(r.max_fwd, std::fabs(out[k * n2 + i] - p[i]));
  }
  return r;
}

}  // namespace

TEST_SUITE("raster") {

TEST_CASE("stroke backward reference matches finite differences of the forward") {
  std::mt19937 rng(20240601);
  ref::StrokeBranches seen;
  std::array<double, 2> worst{0, 0};
  auto keep = [&](std::array<double, 2> w) {
    worst[0] = std::max(worst[0], w[0]);
    worst[1] = std::max(worst[1], w[1]);
  };
  {
    const Case c = make_case(special_polys());
    const auto b = ref::stroke_branches(c.plan, c.pts);
    REQUIRE(b.margin > 1e-4);
    add_branches(seen, b);
    keep(fd_check(c, rng));
  }
  for (int t = 0; t < 60; ++t) {
    const Case c = random_case(rng, 3);
    add_branches(seen, ref::stroke_branches(c.plan, c.pts));
    keep(fd_check(c, rng));
  }
  MESSAGE("stroke backward vs finite differences: max relative error " << worst[0]
          << " (step 1e-5), " << worst[1] << " (step 4e-7, next to zero-length segments)");
  CHECK(worst[0] < 1e-6);
  CHECK(worst[1] < 1e-6);
  check_coverage(seen);
}

TEST_CASE("stroke backward kernel matches the reference and is deterministic") {
  std::mt19937 rng(7);
  std::vector<Case> cases;
  cases.push_back(make_case(special_polys()));
  for (int t = 0; t < 6; ++t) cases.push_back(random_case(rng, 10));
  ref::StrokeBranches seen;
  double worst = 0, worst_fwd = 0;
  for (const Case& c : cases) {
    add_branches(seen, ref::stroke_branches(c.plan, c.pts));
    const KernelResult r = kernel_check(c, rng);
    CHECK(r.same_bits);
    worst = std::max(worst, r.max_rel);
    worst_fwd = std::max(worst_fwd, r.max_fwd);
  }
  MESSAGE("stroke backward kernel vs reference: max error / gradient scale " << worst
          << "; forward max abs error " << worst_fwd << " px");
  CHECK(worst < 1e-4);
  CHECK(worst_fwd < 1e-3);
  check_coverage(seen);
}

}  // TEST_SUITE
