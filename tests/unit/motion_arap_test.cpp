// As-rigid-as-possible deformation (motion/arap.h) on meshes of masks made here: the local
// step's rotation, rigid motions reproduced exactly, a bar bent by 60 degrees about its middle
// without folds or cuts, pieces and legs that move apart, and the energy each iteration lowers.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>

#include "motion/arap.h"
#include "motion/mesh_quality.h"
#include "motion/shape_mesh.h"

#include "error_of.h"
#include "mesh_masks.h"

using namespace svgm;

namespace {

Vec2 rotate_about(Vec2 p, Vec2 c, double deg) {
  const double r = deg * M_PI / 180, cs = std::cos(r), sn = std::sin(r);
  const Vec2 d = p - c;
  return c + Vec2{cs * d.x - sn * d.y, sn * d.x + cs * d.y};
}

double distance(Vec2 a, Vec2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

// The bar's handles: every vertex of its first three lattice columns (x <= 28) and of its last
// three (x >= 212).
std::vector<ArapHandle> bar_end_handles(const ShapeMesh& m, std::vector<int>& left, std::vector<int>& right) {
  std::vector<ArapHandle> h;
  for (int v = 0; v < static_cast<int>(m.vertices.size()); ++v) {
    if (m.vertices[v].x <= 28) left.push_back(static_cast<int>(h.size()));
    else if (m.vertices[v].x >= 212) right.push_back(static_cast<int>(h.size()));
    else continue;
    h.push_back(ArapHandle::at_vertex(v));
  }
  return h;
}

// sum_k w_k |e'_k - R(theta) e_k|^2
double fit_energy(const std::vector<Vec2>& e, const std::vector<Vec2>& f, const std::vector<double>& w, double theta) {
  double s = 0;
  for (size_t k = 0; k < e.size(); ++k) {
    const Vec2 d = f[k] - rotate_about(e[k], {0, 0}, theta * 180 / M_PI);
    s += w[k] * (d.x * d.x + d.y * d.y);
  }
  return s;
}

std::array<double, 4> covariance(const std::vector<Vec2>& e, const std::vector<Vec2>& f, const std::vector<double>& w) {
  std::array<double, 4> m{};
  for (size_t k = 0; k < e.size(); ++k) {
    m[0] += w[k] * f[k].x * e[k].x, m[1] += w[k] * f[k].x * e[k].y;
    m[2] += w[k] * f[k].y * e[k].x, m[3] += w[k] * f[k].y * e[k].y;
  }
  return m;
}

// The bar's middle line (y = 40) after the deformation v: its length, the last sample at 218
// plus the 1.5 px to the bar's end (the far end moves rigidly).
double middle_length(const ShapeMesh& m, const std::vector<Vec2>& v) {
  std::vector<Vec2> middle;
  for (double x = 20; x <= 219.5; x += 2) middle.push_back({x, 40});
  const std::vector<Vec2> mid = bound_positions(m, bind_points(m, middle), v);
  double length = 1.5;
  for (size_t k = 1; k < mid.size(); ++k) length += distance(mid[k], mid[k - 1]);
  return length;
}

double largest_distance(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  double d = 0;
  for (size_t i = 0; i < a.size(); ++i) d = std::max(d, distance(a[i], b[i]));
  return d;
}

}  // namespace

TEST_SUITE("motion") {

TEST_CASE("the local step's rotation: a known similarity recovered, and a stationary minimum of the fit") {
  const std::vector<Vec2> e{{1, 0}, {0, 2}, {-1, 1}};
  const std::vector<double> w{1, 2, 0.5};
  std::vector<Vec2> f;
  for (const Vec2& v : e) f.push_back(1.5 * rotate_about(v, {0, 0}, 35));
  CHECK(best_rotation_angle(covariance(e, f, w)) * 180 / M_PI == doctest::Approx(35).epsilon(1e-12));
  // A general (sheared, not a similarity) deformation: the angle is where the fit's derivative
  // (central differences) vanishes, and it is a minimum.
  const std::vector<Vec2> g{{0.3, 1.1}, {-1.9, 0.4}, {-0.2, 1.7}};
  const double theta = best_rotation_angle(covariance(e, g, w)), h = 1e-5;
  const double slope = (fit_energy(e, g, w, theta + h) - fit_energy(e, g, w, theta - h)) / (2 * h);
  CHECK(std::fabs(slope) < 1e-6);
  CHECK(fit_energy(e, g, w, theta) < fit_energy(e, g, w, theta + 0.05));
  CHECK(fit_energy(e, g, w, theta) < fit_energy(e, g, w, theta - 0.05));
}

TEST_CASE("handles moved by one rigid motion move every vertex and bound point by it; handles at rest leave the mesh at rest") {
  // Two discs touching at a pixel (two pieces) and a bar: each piece gets handles, some at
  // vertices and some at bound points.
  cv::Mat mask(120, 240, CV_8U, cv::Scalar(0));
  test::fill_disc(mask, 30, 30, 20);
  test::fill_disc(mask, 71, 30, 20);
  test::fill_rect(mask, 20, 70, 220, 110);
  const ShapeMesh m = build_shape_mesh(mask, 0.8);  // canvas units: mask pixels / 0.8
  REQUIRE(m.pieces == 3);
  const std::vector<Vec2> anchors{{37.5, 37.5}, {20, 30}, {88.75, 37.5}, {30, 100}, {260, 125}};
  std::vector<ArapHandle> handles;
  for (const Vec2& a : anchors) handles.push_back(ArapHandle::at(m, bind_point(m, a), 2.0));
  handles.push_back(ArapHandle::at_vertex(m.triangles[bind_point(m, {120, 130}).triangle][1]));
  const ArapDeformer arap(m, handles);
  const std::vector<Vec2> points{{40, 40}, {50, 60}, {150, 110}, {275, 137}, {-20, 200}, {300, -40}};
  const std::vector<MeshBinding> bound = bind_points(m, points);
  const double size = 300;  // the figure's extent, for relative errors

  const std::vector<Vec2> still = arap.deform(arap.handle_rest());
  for (size_t v = 0; v < m.vertices.size(); ++v) CHECK(distance(still[v], m.vertices[v]) < 1e-9 * size);

  const Affine rigid = Affine::translate(40, -25) * Affine::rotate_deg(-73);
  std::vector<Vec2> targets;
  for (const Vec2& r : arap.handle_rest()) targets.push_back(rigid.apply(r));
  const std::vector<Vec2> moved = arap.deform(targets);
  double worst = 0;
  for (size_t v = 0; v < m.vertices.size(); ++v) worst = std::max(worst, distance(moved[v], rigid.apply(m.vertices[v])));
  const std::vector<Vec2> got = bound_positions(m, bound, moved);
  for (size_t i = 0; i < points.size(); ++i) worst = std::max(worst, distance(got[i], rigid.apply(points[i])));
  CHECK(worst < 1e-9 * size);
  MESSAGE("rigid motion reproduced to " << worst << " canvas units");
}

TEST_CASE("a 200x40 bar with one end swung 60 degrees about a knee at its middle bends smoothly, without folds, keeping its length") {
  // The knee: the middle of the bar's inner edge (y = 60; +60 degrees turns the far end towards
  // +y). Handles: the first and the last three lattice columns.
  const ShapeMesh m = build_shape_mesh(test::bar_mask(), 1.0);
  std::vector<int> left, right;
  const ArapDeformer arap(m, bar_end_handles(m, left, right));
  const Vec2 knee{120, 60};
  const auto swung = [&](double deg, Vec2 pivot) {
    std::vector<Vec2> t = arap.handle_rest();
    for (int h : right) t[h] = rotate_about(t[h], pivot, deg);
    return t;
  };
  const std::vector<Vec2> v = arap.deform(swung(60, knee));  // 6 iterations, cold

  const MeshQuality q = mesh_quality(m, v);
  CHECK(q.flipped == 0);
  CHECK(q.min_area_ratio > 0.8);
  CHECK(q.max_stretch < 1.25);

  // The far end's points follow the handles' rotation.
  std::vector<Vec2> far;
  for (double x : {212.5, 216.5, 219.5})
    for (double y : {20.5, 40.0, 59.5}) far.push_back({x, y});
  const std::vector<Vec2> far_now = bound_positions(m, bind_points(m, far), v);
  double far_error = 0;
  for (size_t i = 0; i < far.size(); ++i) far_error = std::max(far_error, distance(far_now[i], rotate_about(far[i], knee, 60)));
  CHECK(far_error < 0.05);

  // Cross-sections every 10 px: the angle of each (top to bottom) turns from 0 to 60 degrees
  // with no jump between neighbours (a cut would turn one section by the whole angle).
  std::vector<Vec2> section;
  for (int x = 20; x <= 220; x += 10) {
    const double at = x == 220 ? 219.5 : x;
    section.push_back({at, 20.5});
    section.push_back({at, 59.5});
  }
  const std::vector<Vec2> s = bound_positions(m, bind_points(m, section), v);
  double previous = 0, largest_step = 0;
  for (size_t k = 0; k < s.size(); k += 2) {
    const Vec2 d = s[k + 1] - s[k];
    const double angle = std::atan2(-d.x, d.y) * 180 / M_PI;  // 0 at rest, + when turned like the handles
    if (k > 0) largest_step = std::max(largest_step, std::fabs(angle - previous));
    previous = angle;
  }
  CHECK(previous == doctest::Approx(60).epsilon(0.01));
  CHECK(largest_step < 8);

  const double length = middle_length(m, v);
  CHECK(length == doctest::Approx(199.5).epsilon(0.05));

  // Swung in 24 warm-started steps of 2.5 degrees it reaches the converged shape as nearly.
  const std::vector<Vec2> converged = arap.deform(swung(60, knee), nullptr, 300);
  std::vector<Vec2> w = m.vertices;
  for (int step = 1; step <= 24; ++step) w = arap.deform(swung(2.5 * step, knee), &w);
  CHECK(mesh_quality(m, w).flipped == 0);
  CHECK(largest_distance(w, converged) < 4);
  CHECK(largest_distance(v, converged) < 4);

  // About the middle of the bar itself (a hinge on the centre line) the converged bend is a few
  // per cent short: a smooth bend through that hinge's end positions must be.
  const double hinged = middle_length(m, arap.deform(swung(60, {120, 40}), nullptr, 300));
  CHECK(hinged > 0.95 * 199.5);
  CHECK(hinged < 0.98 * 199.5);
  MESSAGE("60-degree bar: far end within " << far_error << " px, largest step between sections " << largest_step
          << " deg, middle line " << length << " px (hinged on the centre line, converged: " << hinged
          << "), min area ratio " << q.min_area_ratio << ", max stretch " << q.max_stretch << "; from the converged shape: cold "
          << largest_distance(v, converged) << " px, 24 warm steps " << largest_distance(w, converged) << " px");
}

TEST_CASE("the similarity start: six iterations end near the converged bend, where a rigid start is far from it") {
  const ShapeMesh m = build_shape_mesh(test::bar_mask(), 1.0);
  std::vector<int> left, right;
  const std::vector<ArapHandle> handles = bar_end_handles(m, left, right);
  const ArapDeformer similar(m, handles), rigid(m, handles, ArapOptions{6, 1e4, false});
  std::vector<Vec2> t = similar.handle_rest();
  for (int h : right) t[h] = rotate_about(t[h], {120, 60}, 60);
  const std::vector<Vec2> converged = similar.deform(t, nullptr, 300);
  CHECK(largest_distance(rigid.deform(t, nullptr, 300), converged) < 1e-3);  // the same minimum
  const double from_similar = largest_distance(similar.deform(t), converged);
  const double from_rigid = largest_distance(rigid.deform(t), converged);
  CHECK(from_similar < 4);
  CHECK(from_rigid > 3 * from_similar);
  MESSAGE("after 6 iterations, from the converged bend: similarity start " << from_similar << " px, rigid start "
          << from_rigid << " px");
}

TEST_CASE("each local/global iteration lowers the energy, and the same inputs give the same bits") {
  const ShapeMesh m = build_shape_mesh(test::bar_mask(), 1.0);
  std::vector<int> left, right;
  const ArapDeformer arap(m, bar_end_handles(m, left, right));
  std::vector<Vec2> targets = arap.handle_rest();
  for (int h : right) targets[h] = rotate_about(targets[h], {120, 60}, 60);
  double before = arap.energy(arap.deform(targets, nullptr, 0), targets);
  for (int k = 1; k <= 8; ++k) {
    const double e = arap.energy(arap.deform(targets, nullptr, k), targets);
    CHECK_MESSAGE(e <= before * (1 + 1e-12), "iteration " << k);
    before = e;
  }
  const std::vector<Vec2> a = arap.deform(targets), b = arap.deform(targets);
  CHECK(std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec2)) == 0);
}

TEST_CASE("two discs touching at a pixel move apart; legs 1 px apart are not glued") {
  cv::Mat discs(60, 100, CV_8U, cv::Scalar(0));
  test::fill_disc(discs, 30, 30, 20);
  test::fill_disc(discs, 71, 30, 20);
  const ShapeMesh d = build_shape_mesh(discs, 1.0);
  REQUIRE(d.pieces == 2);
  const std::vector<Vec2> anchors{{22, 30}, {38, 30}, {63, 30}, {79, 30}};
  std::vector<ArapHandle> handles;
  for (const Vec2& a : anchors) handles.push_back(ArapHandle::at(d, bind_point(d, a)));
  const ArapDeformer pair(d, handles);
  std::vector<Vec2> t = pair.handle_rest();
  t[2] = t[2] + Vec2{0, 25}, t[3] = t[3] + Vec2{0, 25};  // disc B drops 25 px
  const std::vector<Vec2> v = pair.deform(t);
  const int piece_a = d.triangle_piece[bind_point(d, {30, 30}).triangle];
  for (size_t i = 0; i < v.size(); ++i) {
    if (d.vertex_piece[i] == piece_a) CHECK(distance(v[i], d.vertices[i]) < 1e-9);
    else CHECK(v[i].y - d.vertices[i].y == doctest::Approx(25).epsilon(1e-6));
  }

  // The upside-down U of the mesh test: the top bar and the left foot hold, the right foot
  // steps 15 px outwards. The left leg's inner edge, 1 px from the right leg's, stays put.
  cv::Mat u(160, 140, CV_8U, cv::Scalar(0));
  test::fill_rect(u, 20, 20, 120, 40);
  test::fill_rect(u, 20, 40, 69, 140);
  test::fill_rect(u, 70, 40, 120, 140);
  const ShapeMesh m = build_shape_mesh(u, 1.0);
  std::vector<ArapHandle> hu;
  std::vector<int> right_foot;
  for (int i = 0; i < static_cast<int>(m.vertices.size()); ++i) {
    const Vec2 p = m.vertices[i];
    if (p.y > 24 && p.y < 132) continue;
    if (p.y >= 132 && p.x > 69) right_foot.push_back(static_cast<int>(hu.size()));
    hu.push_back(ArapHandle::at_vertex(i));
  }
  const ArapDeformer legs(m, hu);
  std::vector<Vec2> tu = legs.handle_rest();
  for (int h : right_foot) tu[h] = tu[h] + Vec2{15, 0};
  const std::vector<Vec2> vu = legs.deform(tu);
  const std::vector<Vec2> inner{{68.5, 100}, {70.5, 100}};
  const std::vector<Vec2> moved = bound_positions(m, bind_points(m, inner), vu);
  CHECK(distance(moved[0], inner[0]) < 1);
  CHECK(distance(moved[1], inner[1]) > 5);
  CHECK(mesh_quality(m, vu).flipped == 0);
  MESSAGE("legs: left inner edge moved " << distance(moved[0], inner[0]) << " px, right " << distance(moved[1], inner[1]));
}

TEST_CASE("a piece without handles follows the handles' best rigid fit; bad handles and targets are one error line") {
  cv::Mat mask(60, 100, CV_8U, cv::Scalar(0));
  test::fill_disc(mask, 30, 30, 20);
  test::fill_disc(mask, 75, 30, 15);
  const ShapeMesh m = build_shape_mesh(mask, 1.0);
  REQUIRE(m.pieces == 2);
  const std::vector<ArapHandle> h{ArapHandle::at(m, bind_point(m, {20, 30})), ArapHandle::at(m, bind_point(m, {40, 30}))};
  const ArapDeformer arap(m, h);
  const Affine rigid = Affine::translate(5, 3) * Affine::rotate_deg(20);
  const std::vector<Vec2> v = arap.deform({rigid.apply(arap.handle_rest()[0]), rigid.apply(arap.handle_rest()[1])});
  for (size_t i = 0; i < v.size(); ++i) CHECK(distance(v[i], rigid.apply(m.vertices[i])) < 1e-9 * 100);

  CHECK(test::error_of([&] { ArapDeformer(m, {ArapHandle::at_vertex(0, 0.0)}); }) ==
        "ArapDeformer: a handle's weight must be positive and finite");
  CHECK(test::error_of([&] { ArapDeformer(m, {ArapHandle::at_vertex(static_cast<int>(m.vertices.size()))}); }) ==
        "ArapDeformer: a handle names no vertex of the mesh");
  CHECK(test::error_of([&] { ArapDeformer(m, {}, ArapOptions{6, 0.0, true}); }) ==
        "ArapDeformer: the stiffness must be positive and finite");
  CHECK(test::error_of([&] { ArapHandle::at(m, MeshBinding{}); }) == "ArapHandle: the point is not bound to this mesh");
  CHECK(test::error_of([&] { arap.deform({}); }) == "ArapDeformer::deform: one target per handle is needed");
  const std::vector<Vec2> short_warm(3);
  CHECK(test::error_of([&] { arap.deform(arap.handle_rest(), &short_warm); }) ==
        "ArapDeformer::deform: the warm start must have one position per vertex");
}

}  // TEST_SUITE
