#include "liggghts_mesh.h"

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

bool mesh_surface_velocity(LAMMPS *lmp, const std::string &id)
{
  return mesh_fix(lmp, id)->surfaceVel();
}

}    // namespace liggghts
}    // namespace hardcontact
