// The surface velocity of a triangle mesh whose triangles stay in place while their surface
// moves (LIGGGHTS's fix mesh/surface ... surface_vel vx vy vz, or surface_ang_vel origin ox oy
// oz axis ax ay az omega w): kind 0 none, 1 linear (v), 2 angular (omega about the axis
// through origin). The LIGGGHTS adapter reads it (src/liggghts/liggghts_mesh.h); a mesh wall
// turns it into its rows' wall velocity (src/lammps/sources/mesh_wall_source.cpp).
#pragma once

namespace hardcontact {

struct SurfaceVelocity {
  int kind = 0;
  double v[3] = {0.0, 0.0, 0.0};
  double origin[3] = {0.0, 0.0, 0.0};
  double axis[3] = {0.0, 0.0, 1.0};
  double omega = 0.0;
};

}    // namespace hardcontact
