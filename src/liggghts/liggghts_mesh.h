// LIGGGHTS's triangle meshes (`fix mesh/surface`) as the fix's `wall mesh ID` reads them
// (lammps_compat.h includes this on LIGGGHTS; LAMMPS has no such fix). A LIGGGHTS mesh is
// distributed: each process holds the triangles near its sub-domain, its own ones first, each
// with a global id; `fix move/mesh` moves the nodes in its initial_integrate.
#pragma once

#include "../core/mesh/surface_velocity.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace hardcontact {
namespace liggghts {

// The triangles this process owns of the fix mesh/surface `id`: their global ids and 9
// coordinates each (3 nodes), where the mesh is now. Returns "" or what is wrong with `id`.
std::string mesh_owned(LAMMPS_NS::LAMMPS *lmp, const std::string &id, std::vector<int> &ids,
                       std::vector<double> &nodes);
// The 3 nodes of the triangle of global id `gid` if this process owns it (true), now.
bool mesh_triangle(LAMMPS_NS::LAMMPS *lmp, const std::string &id, int gid, double *nodes);
// Whether some fix move/mesh moves the mesh; which of those comes after fix `after_index` in
// the deck (its ID), "" if none: the fix must see the mesh already moved to the step's end.
bool mesh_moving(LAMMPS_NS::LAMMPS *lmp, const std::string &id);
std::string mesh_mover_after(LAMMPS_NS::LAMMPS *lmp, const std::string &id, int after_index);
// The mesh's surface velocity (core/mesh/surface_velocity.h) as the fix holds it now
// (variables evaluated by LIGGGHTS).
SurfaceVelocity mesh_surface_velocity(LAMMPS_NS::LAMMPS *lmp, const std::string &id);

}    // namespace liggghts
}    // namespace hardcontact
