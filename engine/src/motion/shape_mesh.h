// A triangle mesh covering a figure, for as-rigid-as-possible deformation (arap.h), and the
// binding of the drawing's points to it.
//
// Why a lattice and not a Delaunay triangulation of sampled outline points: the mask is all we
// are given (a rendered drawing has no clean outline polygon: strokes, overlaps, holes), and a
// lattice of square cells split into two triangles each covers every mask pixel by construction
// (a cell is kept when any pixel of the piece lies in it), has well-shaped triangles (no
// slivers, so the cotangent weights are 0 and 1 and the system is well conditioned), and its
// size is set by one number, the cell's side. A Delaunay of boundary samples would need the
// outline traced, thinned and filtered, and still make slivers along the boundary.
//
// A plain lattice glues whatever shares a cell: two legs 2 px apart, inside one 5-px cell, would
// bend as one. So cells are split into "cell pieces" (the virtual node method of Molino, Bao and
// Fedkiw 2004, on a pixel lattice): each 4-connected group of a piece's pixels inside a cell
// gets its own copy of the cell with its own four corners, and two cell copies share the
// corners of their common side only when a pixel of one is 4-adjacent to a pixel of the other
// across that side. Two legs in one cell are two overlapping copies that move apart freely; the
// pieces of the mask (shape_pieces.h: shapes that merely touch) never share a vertex.
//
// Binding: a point of the drawing (canvas coordinates) is bound to the triangle of the cell
// copy that owns the mask pixel under it, as barycentric coordinates. A point on no mask pixel
// (a Bézier handle off the shape, a point in the lattice's margin) takes the cell copy of the
// nearest mask pixel and the one of its two triangles it is nearer to, with barycentrics outside
// [0, 1]: an affine extrapolation of that triangle, so any affine motion (a rigid one included)
// moves it exactly as it moves the triangle.
#pragma once

#include <array>
#include <vector>

#include <opencv2/core.hpp>

#include "svgmotion/affine.h"

namespace svgm {

struct ShapeMeshOptions {
  int target_vertices = 600;  // about this many vertices (the cell side is chosen for it)
  int cell = 0;               // the cell's side in mask pixels; 0: chosen from target_vertices
};

// A point's place on the mesh: p = sum_k bary[k] * vertex[triangle's k-th], sum bary = 1.
struct MeshBinding {
  int triangle = -1;          // -1: not bound (the mesh is empty); the point keeps `rest`
  std::array<double, 3> bary{};
  Vec2 rest;                  // the point as bound
};

struct ShapeMesh {
  std::vector<Vec2> vertices;                 // rest positions, canvas coordinates
  std::vector<std::array<int, 3>> triangles;  // positive signed area in canvas coordinates
  std::vector<int> vertex_piece;              // the mesh piece (connected component) of each vertex
  std::vector<int> triangle_piece;
  int pieces = 0;
  int cell = 0;        // the lattice's cell side, mask pixels
  double scale = 1;    // mask pixels per canvas unit

  // For binding: per mask pixel (row-major), the cell copy that owns it (-1 outside the mask)
  // and the nearest pixel inside the mask (itself when inside).
  int width = 0, height = 0;
  std::vector<int> pixel_copy;
  std::vector<int> nearest_inside;
  std::vector<std::array<int, 2>> copy_triangles;  // the two triangles of each cell copy
};

// mask: CV_8U, non-zero where the figure covers (its coverage > 0 at a working size); scale:
// mask pixels per canvas unit (mask = canvas * scale). An empty mask gives an empty mesh.
ShapeMesh build_shape_mesh(const cv::Mat& mask, double scale, const ShapeMeshOptions& options = {});

// Binds each point (canvas coordinates); an empty mesh binds nothing (triangle -1).
std::vector<MeshBinding> bind_points(const ShapeMesh& mesh, const std::vector<Vec2>& points);
MeshBinding bind_point(const ShapeMesh& mesh, Vec2 point);

// The bound points' positions for the given vertex positions (an unbound point stays at rest).
std::vector<Vec2> bound_positions(const ShapeMesh& mesh, const std::vector<MeshBinding>& bindings,
                                  const std::vector<Vec2>& vertices);

}  // namespace svgm
