// Walls made of triangle meshes read from STL files (keyword `wall stl FILE [scale s] [move
// v_x v_y v_z] [rotate v_theta P A]`): one row per sphere and nearest feature of the surface (a
// face, a ridge, a corner; Remark 4, the form of a plane wall's row), core/mesh/triangle_mesh.h.
// The surface is two-sided: a sphere stays on the side it starts on. A mesh that moves is
// placed as LAMMPS places a moving region: x = R(theta) (X - P) + P + d, X its point in the
// file, d the displacement; the mesh itself stays in the file's frame and each sphere is
// searched for there. Its rows carry the velocity of the surface at the contact point over the
// step, as moving region walls' do (region_wall_source.h).
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

class MeshWallSource : public WallSource {
 public:
  struct Spec {
    std::string fix_id;     // `wall mesh ID`: a LIGGGHTS fix mesh/surface, else:
    std::string file;
    double scale = 1.0;
    std::string move[3];    // equal-style variables of the displacement ("" for none)
    std::string theta;      // equal-style variable of the angle (radians), "" for none
    Vec3 point = Vec3::Zero(), axis = Vec3::UnitZ();
    double friction = -1.0;    // its own Coulomb coefficient, negative for the atom type's
  };
  // Reads every file (process 0 reads, every process builds the mesh); a file that cannot be
  // read stops the run with an ERROR naming it and the problem, on every process. A mesh fix's
  // triangles are gathered at the first init (LIGGGHTS distributes them at its setup).
  MeshWallSource(LAMMPS_NS::LAMMPS *lmp, int groupbit, const std::vector<Spec> &specs);
  // Mesh k's feature f is wall first_wall() + offset(k) + f, stable across steps. reach: the
  // farthest a sphere's rows reach (largest radius + skin), which sizes the meshes' cells.
  // fix_index: the fix's own index in Modify (a mesh fix's mover must come before it).
  void init(const WallSourceInit &at) override;
  // Moving meshes where their variables put them now (setup: q^n and the meshes at t^n).
  void at_current_step() override;
  // Before a step at t^{n+1} (LAMMPS's step counter already advanced): moving meshes where
  // they will be at its end, and their motion over the step. Rows then measure the gap to the
  // mesh at t^{n+1} and offer D = that gap - h n . u_wall (the convention of region walls).
  void advance(double h) override;
  bool moving() const override;
  void visit(const Bodies &bodies, RowSink &sink) const override;
  bool empty() const { return meshes_.empty(); }
  int n_meshes() const { return static_cast<int>(meshes_.size()); }
  int n_walls() const override { return n_walls_; }
  double friction(int w) const override { return specs_[mesh_of(w)].friction; }
  // Gap of a sphere of this radius centred at x to the feature of wall w (diagnostics).
  double wall_gap(int w, const Vec3 &x, double radius) const override;

 private:
  LAMMPS_NS::LAMMPS *lmp_;
  int groupbit_;
  std::vector<std::string> files_;
  std::vector<TriangleMesh> meshes_;
  // Where a mesh is: x = R (X - P) + P + d for its point X in the file (or as first gathered
  // from a mesh fix), now (at t^{n+1} after advance) and one step before. A row's u_wall is
  // the displacement of the surface's material point at the contact over the step, / h.
  struct Placement {
    std::array<int, 3> move_var{{-1, -1, -1}};
    int theta_var = -1;
    bool fix_moves = false;         // a mesh fix moved by fix move/mesh
    int ref_gid = -1;               // the triangle whose nodes give a mesh fix's placement
    Eigen::Matrix3d ref_frame;      // its frame as first gathered (columns)
    Vec3 ref_origin = Vec3::Zero();
    Vec3 point = Vec3::Zero(), axis = Vec3::UnitZ();
    Vec3 d = Vec3::Zero(), d_before = Vec3::Zero();
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity(), rotation_before = rotation;
    bool moves() const
    {
      return fix_moves || theta_var >= 0 || move_var[0] >= 0 || move_var[1] >= 0 ||
             move_var[2] >= 0;
    }
    Vec3 to_mesh(const Vec3 &x) const { return rotation.transpose() * (x - point - d) + point; }
    Vec3 to_world(const Vec3 &X) const { return rotation * (X - point) + point + d; }
    Vec3 before(const Vec3 &X) const { return rotation_before * (X - point) + point + d_before; }
    // a LIGGGHTS mesh's surface velocity (surface_vel / surface_ang_vel): 0 none, 1 linear
    // (surface_v), 2 angular (surface_omega about surface_axis through surface_origin)
    int surface = 0;
    Vec3 surface_v = Vec3::Zero(), surface_origin = Vec3::Zero(), surface_axis = Vec3::UnitZ();
    double surface_omega = 0.0;
    Vec3 surface_velocity(const Vec3 &c, const Vec3 &n) const;
  };
  std::vector<Placement> place_;
  std::vector<Spec> specs_;
  bool ahead_ = false;    // moving meshes stand at t^{n+1} (advance), not t^n
  double h_ = 0.0;
  int moves_ = 0;         // counts placements: the rows found for one do not serve another
  void evaluate(size_t k);
  void gather_fix_mesh(size_t k);
  void place_fix_mesh(size_t k);
  void read_surface_velocity(size_t k);
  std::vector<int> offset_;    // per mesh, its first feature's wall index less first_wall_
  int n_walls_ = 0;
  size_t mesh_of(int w) const;    // the mesh of wall w
  // Per mesh, the rows of every owned sphere as its step's first pass found them: the passes
  // after it (missed rows, step.h) offer the same positions again, and with a fine mesh the
  // search was most of the step (bench/studies/mesh_walls). Reused while every owned centre
  // and radius is what it was, to the bit.
  struct Found {
    std::vector<int> start;                       // sphere i's rows: [start[i], start[i + 1])
    std::vector<MeshContact> rows;
    std::vector<std::array<double, 4>> at;        // x, y, z, radius of each sphere
    int placement = -1;                           // moves_ when found
  };
  mutable std::vector<Found> found_;
  const Found &rows_of(size_t k) const;
  mutable std::vector<MeshContact> scratch_;
};

}    // namespace hardcontact
