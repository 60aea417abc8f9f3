// Walls made of triangle meshes read from STL files (keyword `wall stl FILE [scale s]`): one
// row per sphere and nearest feature of the surface (a face, a ridge, a corner; Remark 4, the
// form of a plane wall's row), core/mesh/triangle_mesh.h. The surface is two-sided: a sphere
// stays on the side it starts on. Fixed meshes (a moving mesh is a later addition).
#pragma once

#include "contact_source.h"

#include "../../core/mesh/triangle_mesh.h"

#include <array>
#include <string>
#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace hardcontact {

class MeshWallSource : public ContactSource {
 public:
  struct Spec {
    std::string file;
    double scale = 1.0;
  };
  // Reads every file (process 0 reads, every process builds the mesh); a file that cannot be
  // read stops the run with an ERROR naming it and the problem, on every process.
  MeshWallSource(LAMMPS_NS::LAMMPS *lmp, int groupbit, const std::vector<Spec> &specs);
  // first_wall: the wall index of the first mesh's first feature (after planes and regions);
  // mesh k's feature f is wall first_wall + offset(k) + f, stable across steps. reach: the
  // farthest a sphere's rows reach (largest radius + skin), which sizes the meshes' cells.
  void init(int first_wall, double reach);
  void visit(const Bodies &bodies, RowSink &sink) const override;
  bool empty() const { return meshes_.empty(); }
  int n_meshes() const { return static_cast<int>(meshes_.size()); }
  int n_walls(int k) const { return meshes_[k].n_features(); }
  bool owns(int w) const { return !meshes_.empty() && w >= first_wall_ && w < end_wall_; }
  // Gap of a sphere of this radius centred at x to the feature of wall w (diagnostics).
  double gap(int w, const Vec3 &x, double radius) const;

 private:
  LAMMPS_NS::LAMMPS *lmp_;
  int groupbit_;
  std::vector<std::string> files_;
  std::vector<TriangleMesh> meshes_;
  std::vector<int> offset_;    // per mesh, its first feature's wall index less first_wall_
  int first_wall_ = 0, end_wall_ = 0;
  // Per mesh, the rows of every owned sphere as its step's first pass found them: the passes
  // after it (missed rows, step.h) offer the same positions again, and with a fine mesh the
  // search was most of the step (bench/studies/mesh_walls). Reused while every owned centre
  // and radius is what it was, to the bit.
  struct Found {
    std::vector<int> start;                       // sphere i's rows: [start[i], start[i + 1])
    std::vector<MeshContact> rows;
    std::vector<std::array<double, 4>> at;        // x, y, z, radius of each sphere
  };
  mutable std::vector<Found> found_;
  const Found &rows_of(size_t k) const;
  mutable std::vector<MeshContact> scratch_;
};

}    // namespace hardcontact
