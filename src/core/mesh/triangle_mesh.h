// A triangle mesh as an obstacle (`wall stl`): the rows a sphere has with it, each the exact
// distance from the sphere's centre to the nearest point of one feature (a face, an edge or a
// vertex) with the normal along it, as a plane wall's row (Remark 4).
//
// Which features give rows: the nearest points of the surface, each once. The nearest point of
// a triangle near the sphere may be an edge or a vertex it shares with a triangle that comes
// nearer elsewhere: a floor split into triangles, where the sphere lies over a neighbouring
// face, or a fold towards the sphere. Such a point is not a nearest point of the surface and
// gives no row: its row would be implied by the face's, and linearised (eq. 15) its tilted
// normal would stop a sphere rolling towards the edge (a bump at every edge). An edge or a
// vertex gives a row only when every triangle holding it has its nearest point there (a ridge,
// a corner, a rim); it then gives one row, however many triangles reach it. Where the surface
// folds towards the sphere, the face it approaches enters once the sphere is over it: within
// one step a sphere can overlap that face by at most its motion along the fold times the
// fold's angle (measured in the tests).
#pragma once

#include "stl_reader.h"

#include <Eigen/Geometry>

#include <array>
#include <vector>

namespace hardcontact {

struct MeshContact {
  int feature;                // TriangleMesh numbering: vertices, then edges, then faces
  Eigen::Vector3d point;      // the nearest point of that feature
  double distance;            // |centre - point|
};

class TriangleMesh {
 public:
  // Vertices closer than kWeld times the mesh's extent are one vertex (an STL file repeats
  // them per triangle, often to within round-off only); two triangles share an edge when they
  // share both its vertices.
  static constexpr double kWeld = 1e-9;
  explicit TriangleMesh(const std::vector<Triangle> &triangles);

  int n_vertices() const { return static_cast<int>(vertex_.size()); }
  int n_edges() const { return static_cast<int>(edge_.size()); }
  int n_triangles() const { return static_cast<int>(tri_.size()); }
  int n_features() const { return n_vertices() + n_edges() + n_triangles(); }
  // edges held by one triangle only (an open sheet's rim) and by more than two (a T-junction)
  int n_boundary_edges() const;
  const Eigen::AlignedBox3d &bounds() const { return bounds_; }

  // Cells of at least min_cell (the reach of the queries to come): a query then visits at most
  // 27 cells, where cells the size of the triangles (the default) could make it visit
  // hundreds, mostly empty, on a fine mesh (measured: bench/studies/mesh_walls).
  void index(double min_cell);
  // The rows of a sphere centred at p: one per feature within reach of p (see above).
  // out is cleared first; no allocation once the scratch has grown.
  void contacts(const Eigen::Vector3d &p, double reach, std::vector<MeshContact> &out) const;
  // The distance from p to a feature (diagnostics: a row's gap after the step).
  double distance(int feature, const Eigen::Vector3d &p) const;

 private:
  enum Kind { kVertex, kEdge, kFace };
  struct Nearest {
    Kind kind;
    int id;    // vertex, edge or triangle id
    Eigen::Vector3d point;
  };
  Nearest nearest_on_triangle(int t, const Eigen::Vector3d &p) const;
  bool nearest_of_surface(const Nearest &f) const;
  int feature_of(const Nearest &f) const;
  void build_grid(double min_cell);

  std::vector<Eigen::Vector3d> vertex_;
  std::vector<std::array<int, 3>> tri_;         // vertex ids
  // per triangle: the centre and radius of a ball holding it (its box's), so that a triangle
  // out of reach costs one distance, not its nearest point
  std::vector<Eigen::Vector3d> ball_centre_;
  std::vector<double> ball_radius_;
  std::vector<std::array<int, 3>> tri_edge_;    // edge k joins tri_ k and k + 1 (mod 3)
  std::vector<std::array<int, 2>> edge_;        // vertex ids, smaller first
  std::vector<int> edge_count_;                 // triangles holding each edge
  std::vector<int> vertex_tri_start_, vertex_tri_, edge_tri_start_, edge_tri_;    // CSR
  Eigen::AlignedBox3d bounds_;
  // A uniform grid over the bounds: cell c holds the triangles whose boxes meet it,
  // cell_tri_[cell_start_[c] .. cell_start_[c + 1]).
  Eigen::Vector3d origin_;
  double cell_ = 1.0;
  std::array<int, 3> dims_{{1, 1, 1}};
  std::vector<int> cell_start_, cell_tri_;
  // query scratch
  mutable std::vector<int> stamp_, report_;    // report_[t]: t's entry in found_, or -1
  mutable int stamp_now_ = 0;
  mutable std::vector<std::pair<int, Nearest>> found_;
};

}    // namespace hardcontact
