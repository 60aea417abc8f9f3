#include "liggghts_mesh.h"

#include "expose_member.h"

#include "abstract_mesh.h"
#include "fix_mesh_surface.h"
#include "fix_move_mesh.h"
#include "lammps.h"
#include "modify.h"

#include <cstring>

using namespace LAMMPS_NS;

namespace hardcontact {
namespace liggghts {

namespace {

// FixMeshSurface keeps its surface velocity private: reached as liggghts_members.cpp reaches
// Modify's and Neighbor's members (an explicit instantiation names them; each type spelled
// out, so that a LIGGGHTS that renames or retypes one stops this file from compiling).
HARDCONTACT_MEMBER_TAG(VelFlag, bool FixMeshSurface::*)
HARDCONTACT_MEMBER_TAG(VSurf, double (FixMeshSurface::*)[3])
HARDCONTACT_MEMBER_TAG(AngVelFlag, bool FixMeshSurface::*)
HARDCONTACT_MEMBER_TAG(Origin, double (FixMeshSurface::*)[3])
HARDCONTACT_MEMBER_TAG(Axis, double (FixMeshSurface::*)[3])
HARDCONTACT_MEMBER_TAG(OmegaSurf, double FixMeshSurface::*)

}    // namespace

template struct ExposeMember<VelFlag, &FixMeshSurface::velFlag_>;
template struct ExposeMember<VSurf, &FixMeshSurface::vSurf_>;
template struct ExposeMember<AngVelFlag, &FixMeshSurface::angVelFlag_>;
template struct ExposeMember<Origin, &FixMeshSurface::origin_>;
template struct ExposeMember<Axis, &FixMeshSurface::axis_>;
template struct ExposeMember<OmegaSurf, &FixMeshSurface::omegaSurf_>;

namespace {

FixMeshSurface *mesh_fix(LAMMPS *lmp, const std::string &id)
{
  return dynamic_cast<FixMeshSurface *>(lmp->modify->find_fix_id(id.c_str()));
}

}    // namespace

std::string mesh_owned(LAMMPS *lmp, const std::string &id, std::vector<int> &ids,
                       std::vector<double> &nodes)
{
  Fix *any = lmp->modify->find_fix_id(id.c_str());
  if (any == nullptr)
    return "no fix with ID " + id + ": define it with 'fix " + id +
           " all mesh/surface file ...' before this fix";
  FixMeshSurface *f = mesh_fix(lmp, id);
  if (f == nullptr)
    return "fix " + id + " is a " + std::string(any->style) +
           ", not a mesh/surface: name the fix mesh/surface of the wall";
  AbstractMesh *mesh = f->mesh();
  ids.clear();
  nodes.clear();
  const int n = mesh->sizeLocal();
  double x[3];
  for (int i = 0; i < n; ++i) {
    ids.push_back(mesh->id_slow(i));
    for (int j = 0; j < 3; ++j) {
      mesh->node_slow(i, j, x);
      nodes.insert(nodes.end(), {x[0], x[1], x[2]});
    }
  }
  return "";
}

bool mesh_triangle(LAMMPS *lmp, const std::string &id, int gid, double *nodes)
{
  AbstractMesh *mesh = mesh_fix(lmp, id)->mesh();
  const int n = mesh->sizeLocal();
  for (int i = 0; i < n; ++i) {
    if (mesh->id_slow(i) != gid) continue;
    for (int j = 0; j < 3; ++j) mesh->node_slow(i, j, nodes + 3 * j);
    return true;
  }
  return false;
}

bool mesh_moving(LAMMPS *lmp, const std::string &id)
{
  return mesh_fix(lmp, id)->mesh()->isMoving();
}

std::string mesh_mover_after(LAMMPS *lmp, const std::string &id, int after_index)
{
  FixMeshSurface *f = mesh_fix(lmp, id);
  for (int i = after_index + 1; i < lmp->modify->nfix; ++i) {
    FixMoveMesh *m = dynamic_cast<FixMoveMesh *>(lmp->modify->fix[i]);
    if (m && m->fixMeshCompare(f)) return m->id;
  }
  return "";
}

SurfaceVelocity mesh_surface_velocity(LAMMPS *lmp, const std::string &id)
{
  FixMeshSurface *f = mesh_fix(lmp, id);
  SurfaceVelocity s;
  if (f->*member(VelFlag{})) {
    s.kind = 1;
    for (int d = 0; d < 3; ++d) s.v[d] = (f->*member(VSurf{}))[d];
  } else if (f->*member(AngVelFlag{})) {
    s.kind = 2;
    for (int d = 0; d < 3; ++d) {
      s.origin[d] = (f->*member(Origin{}))[d];
      s.axis[d] = (f->*member(Axis{}))[d];
    }
    s.omega = f->*member(OmegaSurf{});
  }
  return s;
}

}    // namespace liggghts
}    // namespace hardcontact
