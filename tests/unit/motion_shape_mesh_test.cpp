// The deformation mesh of a figure's mask (motion/shape_mesh.h, motion/shape_pieces.h) and the
// fold check (motion/mesh_quality.h), on masks made here: which pixels form one piece, that the
// mesh covers the mask, that shapes sharing a cell are not glued, and that a bound point (on
// the shape or off it) moves exactly with any affine motion of the mesh.
#include <doctest/doctest.h>

#include <cmath>
#include <set>

#include "motion/mesh_quality.h"
#include "motion/shape_mesh.h"
#include "motion/shape_pieces.h"

#include "error_of.h"
#include "mesh_masks.h"

using namespace svgm;

namespace {

double signed_area2(const ShapeMesh& m, int t) {
  const Vec2 a = m.vertices[m.triangles[t][0]], u = m.vertices[m.triangles[t][1]] - a,
             v = m.vertices[m.triangles[t][2]] - a;
  return u.x * v.y - u.y * v.x;
}

std::set<int> triangle_vertices(const ShapeMesh& m, const MeshBinding& b) {
  return {m.triangles[b.triangle][0], m.triangles[b.triangle][1], m.triangles[b.triangle][2]};
}

}  // namespace

TEST_SUITE("motion") {

TEST_CASE("the bar's mesh: one piece of about 600 vertices, positive triangles, covering every pixel of the mask") {
  const cv::Mat mask = test::bar_mask();
  const double scale = 0.5;  // mask pixels per canvas unit: the canvas is twice the mask's size
  const ShapeMesh m = build_shape_mesh(mask, scale);
  CHECK(m.pieces == 1);
  CHECK(m.cell == 4);  // sqrt(8000 / 600) = 3.65, rounded
  CHECK(m.vertices.size() == 51 * 11);
  CHECK(m.triangles.size() == 2 * 50 * 10);
  for (size_t t = 0; t < m.triangles.size(); ++t) CHECK(signed_area2(m, static_cast<int>(t)) > 0);
  // Every pixel's corners (canvas units) lie in their triangle: barycentrics in [0, 1].
  double worst = 0;
  for (int y = 20; y < 60; y += 3)
    for (int x = 20; x < 220; x += 3)
      for (const Vec2 p : {Vec2{x + 0.0, y + 0.0}, Vec2{x + 1.0, y + 1.0}, Vec2{x + 0.5, y + 0.5}}) {
        const MeshBinding b = bind_point(m, (1 / scale) * p);
        for (double w : b.bary) worst = std::min(worst, w);
      }
  CHECK(worst > -1e-12);
}

TEST_CASE("two discs touching at one pixel are two pieces; joined by a 4-px neck they are one") {
  // Disc A's right-most column is the one pixel (50, 30); disc B's left-most is (51, 30).
  cv::Mat touching(60, 100, CV_8U, cv::Scalar(0));
  test::fill_disc(touching, 30, 30, 20);
  test::fill_disc(touching, 71, 30, 20);
  int pieces = 0;
  const cv::Mat labels = shape_pieces(touching, pieces);
  CHECK(pieces == 2);
  CHECK(labels.at<int>(30, 50) == labels.at<int>(30, 30));  // the contact pixels go with their discs
  CHECK(labels.at<int>(30, 51) == labels.at<int>(30, 71));
  CHECK(labels.at<int>(30, 30) != labels.at<int>(30, 71));

  const ShapeMesh m = build_shape_mesh(touching, 1.0);
  REQUIRE(m.pieces == 2);
  const MeshBinding a = bind_point(m, {30, 30}), b = bind_point(m, {71, 30});
  CHECK(m.triangle_piece[a.triangle] != m.triangle_piece[b.triangle]);
  // No vertex is shared: every vertex of a piece lies on its own disc's side (a cell beyond it).
  for (size_t v = 0; v < m.vertices.size(); ++v) {
    if (m.vertex_piece[v] == m.triangle_piece[a.triangle]) CHECK(m.vertices[v].x <= 50 + m.cell);
    else CHECK(m.vertices[v].x >= 51 - m.cell);
  }

  cv::Mat necked = touching.clone();
  test::fill_rect(necked, 45, 28, 56, 32);  // a neck 4 px tall between the discs
  CHECK(build_shape_mesh(necked, 1.0).pieces == 1);
}

TEST_CASE("a hairline alone is a piece of its own; a 2-px whisker on a disc is the disc's") {
  cv::Mat mask(60, 120, CV_8U, cv::Scalar(0));
  test::fill_disc(mask, 30, 30, 15);
  test::fill_rect(mask, 45, 29, 70, 31);   // whisker, 2 px thick, from the disc's edge
  test::fill_rect(mask, 80, 10, 81, 50);   // a 1-px line on its own
  int pieces = 0;
  const cv::Mat labels = shape_pieces(mask, pieces);
  CHECK(pieces == 2);
  CHECK(labels.at<int>(30, 69) == labels.at<int>(30, 30));
  CHECK(labels.at<int>(20, 80) >= 0);
  CHECK(labels.at<int>(20, 80) != labels.at<int>(30, 30));
  CHECK(build_shape_mesh(mask, 1.0).pieces == 2);
}

TEST_CASE("legs 1 px apart inside one cell are separate cell copies sharing no vertex") {
  // An upside-down U: a top bar and two legs with a 1-px gap at column 69 (cell side 4: the
  // cell 68..71 holds pixels of both legs).
  cv::Mat mask(160, 140, CV_8U, cv::Scalar(0));
  test::fill_rect(mask, 20, 20, 120, 40);
  test::fill_rect(mask, 20, 40, 69, 140);
  test::fill_rect(mask, 70, 40, 120, 140);
  const ShapeMesh m = build_shape_mesh(mask, 1.0);
  REQUIRE(m.cell == 4);
  CHECK(m.pieces == 1);  // joined through the top bar
  for (double y : {60.5, 100.5, 139.5}) {
    const MeshBinding left = bind_point(m, {68.5, y}), right = bind_point(m, {70.5, y});
    std::set<int> shared;
    for (int v : triangle_vertices(m, left))
      if (triangle_vertices(m, right).count(v)) shared.insert(v);
    CHECK_MESSAGE(shared.empty(), "at y = " << y);
  }
}

TEST_CASE("a bound point, on the shape or off it, follows an affine motion of the mesh exactly") {
  const ShapeMesh m = build_shape_mesh(test::bar_mask(), 1.0);
  const std::vector<Vec2> points{{100.3, 40.7}, {20, 20}, {219.9, 59.9}, {250, 75}, {120, -30}, {-15, 41}, {1e3, 1e3}};
  const std::vector<MeshBinding> bound = bind_points(m, points);
  for (const MeshBinding& b : bound) CHECK(b.triangle >= 0);
  // The rest mesh gives the points back.
  const std::vector<Vec2> rest = bound_positions(m, bound, m.vertices);
  for (size_t i = 0; i < points.size(); ++i) {
    CHECK(rest[i].x == doctest::Approx(points[i].x).epsilon(1e-12));
    CHECK(rest[i].y == doctest::Approx(points[i].y).epsilon(1e-12));
  }
  for (const Affine& map : {Affine::translate(13, -7) * Affine::rotate_deg(40), Affine{1.3, 0.2, -0.4, 0.8, 5, 9}}) {
    std::vector<Vec2> moved;
    for (const Vec2& v : m.vertices) moved.push_back(map.apply(v));
    const std::vector<Vec2> got = bound_positions(m, bound, moved);
    for (size_t i = 0; i < points.size(); ++i) {
      const Vec2 want = map.apply(points[i]);
      CHECK(std::hypot(got[i].x - want.x, got[i].y - want.y) < 1e-9 * std::hypot(want.x, want.y));
    }
  }
  // An off-shape point is extrapolated from a triangle near it, not from across the shape.
  const MeshBinding off = bind_point(m, {250, 75});
  CHECK(m.vertices[m.triangles[off.triangle][0]].x > 200);
}

TEST_CASE("an empty mask gives an empty mesh that binds nothing; bad input is one error line") {
  const ShapeMesh m = build_shape_mesh(cv::Mat(10, 10, CV_8U, cv::Scalar(0)), 1.0);
  CHECK(m.vertices.empty());
  const MeshBinding b = bind_point(m, {3, 4});
  CHECK(b.triangle == -1);
  CHECK(bound_positions(m, {b}, {})[0] == Vec2{3, 4});
  CHECK(test::error_of([] { build_shape_mesh(cv::Mat(10, 10, CV_32F, cv::Scalar(0)), 1.0); }) ==
        "shape_pieces: the mask must be CV_8U");
  CHECK(test::error_of([] { build_shape_mesh(test::bar_mask(), 0); }) == "build_shape_mesh: the scale must be positive");
}

TEST_CASE("mesh quality: rest is perfect; a uniform scale, a fold and a pinch are measured") {
  const ShapeMesh m = build_shape_mesh(test::bar_mask(), 1.0);
  MeshQuality q = mesh_quality(m, m.vertices);
  CHECK(q.flipped == 0);
  CHECK(q.min_area_ratio == 1);
  CHECK(q.max_area_ratio == 1);
  CHECK(q.max_stretch == 1);

  std::vector<Vec2> doubled;
  for (const Vec2& v : m.vertices) doubled.push_back(2.0 * v);
  q = mesh_quality(m, doubled);
  CHECK(q.flipped == 0);
  CHECK(q.min_area_ratio == doctest::Approx(4));
  CHECK(q.max_stretch == doctest::Approx(2));

  // Mirroring the mesh flips every triangle.
  std::vector<Vec2> mirrored;
  for (const Vec2& v : m.vertices) mirrored.push_back({-v.x, v.y});
  CHECK(mesh_quality(m, mirrored).flipped == static_cast<int>(m.triangles.size()));

  // One vertex pushed across its neighbours folds the triangles around it.
  const MeshBinding mid = bind_point(m, {120.5, 40.5});
  const int v = m.triangles[mid.triangle][0];
  std::vector<Vec2> folded = m.vertices;
  folded[v] = folded[v] + Vec2{3.0 * m.cell, 0};
  q = mesh_quality(m, folded);
  CHECK(q.flipped > 0);
  CHECK(q.min_area_ratio < 0);
  CHECK(q.max_stretch > 2);
  CHECK(test::error_of([&] { mesh_quality(m, {}); }) == "mesh_quality: one deformed position per vertex is needed");
}

}  // TEST_SUITE
