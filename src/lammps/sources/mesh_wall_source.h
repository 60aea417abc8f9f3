// Walls made of triangle meshes read from STL files (keyword `wall stl FILE [scale s]`): one
// row per sphere and nearest feature of the surface (a face, a ridge, a corner; Remark 4, the
// form of a plane wall's row), core/mesh/triangle_mesh.h. The surface is two-sided: a sphere
// stays on the side it starts on. Fixed meshes (a moving mesh is a later addition).
#pragma once

#include "contact_source.h"

#include "../../core/mesh/triangle_mesh.h"

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
  // mesh k's feature f is wall first_wall + offset(k) + f, stable across steps.
  void init(int first_wall);
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
  mutable std::vector<MeshContact> scratch_;
};

}    // namespace hardcontact
