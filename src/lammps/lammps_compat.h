// Hides the differences between the hosts the adapter is compiled for:
//   LAMMPS before 24 Mar 2022 ("old"), LAMMPS from 24 Mar 2022 on ("modern"), and LIGGGHTS 3.8
//   (a LAMMPS of 2013 extended by DCS: no fmt, no utils::, no custom neighbour cutoffs, no
//   post_neighbor callback, regions that do not number their faces).
// HARDCONTACT_MODERN_API is set by cmake/HardcontactLammpsApi.cmake from a compile check
// against the LAMMPS headers in use (there is no version macro to test); HARDCONTACT_LIGGGHTS=1
// only in the LIGGGHTS build (CMakeLists.txt, "LIGGGHTS host"). LIGGGHTS-only glue that is not
// a difference of an API the adapter calls lives in src/liggghts/ (doc/architecture.md).
#pragma once

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "modify.h"
#include "region.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "variable.h"

#if HARDCONTACT_LIGGGHTS
#include "brace_format.h"       // src/liggghts/
#include "liggghts_members.h"    // src/liggghts/
#include "liggghts_mesh.h"       // src/liggghts/
#endif

#include "../core/mesh/surface_velocity.h"

#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#if HARDCONTACT_LIGGGHTS
namespace LAMMPS_NS {
namespace FixConst {
// LIGGGHTS 3.8's Fix has no post_neighbor callback: this mask bit is empty there and the
// LIGGGHTS fix (src/liggghts/fix_hardcontact_liggghts.h) calls post_neighbor() itself from
// pre_force on the steps the lists were rebuilt.
static const int POST_NEIGHBOR = 0;
}    // namespace FixConst
}    // namespace LAMMPS_NS
// Callbacks LIGGGHTS's Fix does not declare (post_neighbor, setup_post_neighbor) or names
// differently (pack_forward_comm is pack_comm there): plain members of FixHardContact, which
// the LIGGGHTS fix forwards to.
#define HARDCONTACT_LAMMPS_OVERRIDE
// LAMMPS numbers the instances of a fix class for their neighbour requests (Fix::instance_me,
// protected); LIGGGHTS tells requests of one fix apart by the fix itself.
#define HARDCONTACT_FIX_INSTANCE 0
#else
#define HARDCONTACT_LAMMPS_OVERRIDE override
#define HARDCONTACT_FIX_INSTANCE instance_me
#endif

namespace hardcontact {
namespace compat {

// ------------------------------------------------------------------------- messages
// error->all / one / warning with fmt-style placeholders: LAMMPS formats them itself (fmt);
// LIGGGHTS's Error takes a finished C string, formatted here (brace_format.h).
template <typename... Args>
[[noreturn]] void error_all(LAMMPS_NS::Error *error, const char *file, int line,
                            const char *format, Args &&...args)
{
#if HARDCONTACT_LIGGGHTS
  error->all(file, line, hardcontact::format(format, args...).c_str());
#else
  error->all(file, line, format, std::forward<Args>(args)...);
#endif
  std::abort();    // not reached: both stop the run (LIGGGHTS's all() is not [[noreturn]])
}

template <typename... Args>
[[noreturn]] void error_one(LAMMPS_NS::Error *error, const char *file, int line,
                            const char *format, Args &&...args)
{
#if HARDCONTACT_LIGGGHTS
  error->one(file, line, hardcontact::format(format, args...).c_str());
#else
  error->one(file, line, format, std::forward<Args>(args)...);
#endif
  std::abort();
}

template <typename... Args>
void warning(LAMMPS_NS::Error *error, const char *file, int line, const char *format,
             Args &&...args)
{
#if HARDCONTACT_LIGGGHTS
  error->warning(file, line, hardcontact::format(format, args...).c_str());
#else
  error->warning(file, line, format, std::forward<Args>(args)...);
#endif
}

// ------------------------------------------------------------------------- neighbour list
// A half list of every owned/ghost pair closer than r_i + r_j + skin, holding cross-processor
// pairs on both processors (newton off), with a stencil that reaches `cutoff`.
// `instance` is the fix's instance_me (protected in Fix, so the caller passes it).
// LIGGGHTS: its granular list is that list (radius + skin per pair), newton off only when
// newton_pair is off (checked by the LIGGGHTS fix); a request cannot carry a cutoff, so the
// LIGGGHTS fix widens the stencil itself (reach_stencil below).
inline void request_size_list(LAMMPS_NS::Neighbor *neighbor, LAMMPS_NS::Fix *fix, int instance,
                              double cutoff)
{
#if HARDCONTACT_LIGGGHTS
  (void) instance;
  (void) cutoff;
  const int irequest = neighbor->request(fix);
  LAMMPS_NS::NeighRequest *req = neighbor->requests[irequest];
  req->pair = 0;
  req->fix = 1;
  req->half = 0;
  req->gran = 1;
#elif HARDCONTACT_MODERN_API
  (void) instance;
  auto *req = neighbor->add_request(fix, LAMMPS_NS::NeighConst::REQ_SIZE |
                                                 LAMMPS_NS::NeighConst::REQ_NEWTON_OFF);
  req->set_cutoff(cutoff);
#else
  const int irequest = neighbor->request(fix, instance);
  LAMMPS_NS::NeighRequest *req = neighbor->requests[irequest];
  req->pair = 0;
  req->fix = 1;
  req->size = 1;
  req->newton = 2;
  req->cut = 1;
  req->cutoff = cutoff;
#endif
}

// The ghost cutoff a size request of reach `cutoff` needs. Modern LAMMPS stops a run whose
// custom request cutoff plus the skin exceeds the communication cutoff (Neighbor::init), although
// its stencil and bins use the custom cutoff as given; old LAMMPS and LIGGGHTS check nothing.
// Asking for the extra skin of ghosts is the only way through that check: it costs one skin
// shell of ghosts.
inline double ghost_cutoff_for_request(double cutoff, double skin)
{
#if HARDCONTACT_MODERN_API && !HARDCONTACT_LIGGGHTS
  return cutoff + skin;
#else
  (void) skin;
  return cutoff;
#endif
}

#if HARDCONTACT_LIGGGHTS
// LIGGGHTS sizes its bins and stencils from the largest pair cutoff plus skin (cutneighmax),
// which is 0 without a pair style: the stencil would be empty. Raised to the fix's reach after
// Neighbor::init (which recomputes it at every run) and before the bins are set up; the
// granular list itself still tests each pair against r_i + r_j + skin.
inline void reach_stencil(LAMMPS_NS::Neighbor *neighbor, double cutoff)
{
  if (neighbor->cutneighmax >= cutoff) return;
  neighbor->cutneighmax = cutoff;
  liggghts::stencil_reach_sq(neighbor) = cutoff * cutoff;
}
#endif

// The command that sets the ghost cutoff, as the fix's advice names it.
#if HARDCONTACT_LIGGGHTS
constexpr const char *kGhostCutoffCommand = "communicate single cutoff";
#else
constexpr const char *kGhostCutoffCommand = "comm_modify cutoff";
#endif

// The bin size the user set with neigh_modify binsize (0: none), and setting it. (LIGGGHTS
// keeps these members, and Atom's sort bin below, private: liggghts_members.h.)
inline double user_bin_size(LAMMPS_NS::Neighbor *neighbor)
{
#if HARDCONTACT_LIGGGHTS
  return liggghts::bin_size_set(neighbor) ? liggghts::bin_size(neighbor) : 0.0;
#else
  return neighbor->binsizeflag ? neighbor->binsize_user : 0.0;
#endif
}

// The bin size of atom sorting the user set with atom_modify sort (0: none), and setting it.
inline double &sort_bin_size(LAMMPS_NS::Atom *atom)
{
#if HARDCONTACT_LIGGGHTS
  return liggghts::sort_bin_size(atom);
#else
  return atom->userbinsize;
#endif
}

inline void set_user_bin_size(LAMMPS_NS::Neighbor *neighbor, double size)
{
#if HARDCONTACT_LIGGGHTS
  liggghts::bin_size_set(neighbor) = 1;
  liggghts::bin_size(neighbor) = size;
#else
  neighbor->binsizeflag = 1;
  neighbor->binsize_user = size;
#endif
}

// ------------------------------------------------------------------------- regions
// The region with this ID, or nullptr (modern: Domain::get_region_by_id; old: an index).
inline LAMMPS_NS::Region *find_region(LAMMPS_NS::Domain *domain, const std::string &id)
{
#if HARDCONTACT_MODERN_API && !HARDCONTACT_LIGGGHTS
  return domain->get_region_by_id(id);
#else
  const int i = domain->find_region(id.c_str());
  return i < 0 ? nullptr : domain->regions[i];
#endif
}

// Region walls follow each face of a region from step to step by the face number LAMMPS's
// Region::surface() gives every contact (Contact::iwall). LIGGGHTS 3.8's Region::Contact has
// no such number, so region walls are not available there (an error names the reason).
// A moving region (LAMMPS): prematch() puts it where its variables say at this step,
// set_velocity() differences that against the last call; velocity_contact() is the velocity
// of the surface at contact m of the last surface() call. (Never reached on LIGGGHTS.)
#if HARDCONTACT_LIGGGHTS
constexpr bool kRegionFacesNumbered = false;
inline int region_face(const LAMMPS_NS::Region::Contact &) { return 0; }
inline void region_move_to_step(LAMMPS_NS::Region *region) { region->prematch(); }
inline void region_contact_velocity(LAMMPS_NS::Region *, double *, double *, int) {}
#else
constexpr bool kRegionFacesNumbered = true;
inline int region_face(const LAMMPS_NS::Region::Contact &contact) { return contact.iwall; }
inline void region_move_to_step(LAMMPS_NS::Region *region)
{
  region->prematch();
  region->set_velocity();
}
inline void region_contact_velocity(LAMMPS_NS::Region *region, double *u_wall, double *x, int m)
{
  region->velocity_contact(u_wall, x, m);
}
#endif

// ------------------------------------------------------------------------- mesh fixes
// `wall mesh ID`: LIGGGHTS's fix mesh/surface (src/liggghts/liggghts_mesh.h). LAMMPS has no
// triangle-mesh fix: there every call says so (a deck names its STL file with `wall stl`).
using hardcontact::SurfaceVelocity;    // core/mesh/surface_velocity.h
#if HARDCONTACT_LIGGGHTS
constexpr bool kMeshFixes = true;
using liggghts::mesh_moving;
using liggghts::mesh_mover_after;
using liggghts::mesh_owned;
using liggghts::mesh_surface_velocity;
using liggghts::mesh_triangle;
#else
constexpr bool kMeshFixes = false;
inline std::string mesh_owned(LAMMPS_NS::LAMMPS *, const std::string &, std::vector<int> &,
                              std::vector<double> &)
{
  return "LAMMPS has no triangle-mesh fix (LIGGGHTS's fix mesh/surface): give the STL file "
         "itself with 'wall stl FILE'";
}
inline bool mesh_triangle(LAMMPS_NS::LAMMPS *, const std::string &, int, double *) { return false; }
inline bool mesh_moving(LAMMPS_NS::LAMMPS *, const std::string &) { return false; }
inline std::string mesh_mover_after(LAMMPS_NS::LAMMPS *, const std::string &, int) { return ""; }
inline SurfaceVelocity mesh_surface_velocity(LAMMPS_NS::LAMMPS *, const std::string &)
{
  return {};
}
#endif

// ------------------------------------------------------------------------- atoms, comm
// Which per-atom callback a fix asks Atom for (LIGGGHTS numbers them: 0 grow, 1 restart).
#if HARDCONTACT_LIGGGHTS
constexpr int kAtomGrowCallback = 0;
constexpr int kAtomRestartCallback = 1;
#else
constexpr int kAtomGrowCallback = LAMMPS_NS::Atom::GROW;
constexpr int kAtomRestartCallback = LAMMPS_NS::Atom::RESTART;
#endif

// The most doubles one atom's fix data takes in Comm::exchange(); it changes during a run (it
// grows with an atom's contacts). LAMMPS asks each fix (maxexchange, with maxexchange_dynamic
// to ask again every exchange); LIGGGHTS keeps one figure for all fixes in Comm.
inline void set_exchange_size(LAMMPS_NS::Fix *fix, LAMMPS_NS::Comm *comm, int per_atom)
{
#if HARDCONTACT_LIGGGHTS
  (void) fix;
  if (per_atom > comm->maxexchange_fix) comm->maxexchange_fix = per_atom;
#else
  (void) comm;
  fix->maxexchange = per_atom;
  fix->maxexchange_dynamic = 1;
#endif
}

inline void forward_comm(LAMMPS_NS::Comm *comm, LAMMPS_NS::Fix *fix)
{
#if HARDCONTACT_MODERN_API && !HARDCONTACT_LIGGGHTS
  comm->forward_comm(fix);
#else
  comm->forward_comm_fix(fix);
#endif
}

// ------------------------------------------------------------------------- virial
// The switch of a fix's virial in pressure and stress: LAMMPS's `fix_modify virial` sets
// thermo_virial, and the fix says what it offers (global and per-atom); LIGGGHTS 3.8's computes
// read virial_flag alone and its fix_modify has no virial keyword (the LIGGGHTS fix takes it).
inline void offer_virial(LAMMPS_NS::Fix *fix)
{
#if HARDCONTACT_LIGGGHTS
  fix->virial_flag = 1;
#else
  fix->thermo_virial = 1;
  fix->virial_global_flag = 1;
  fix->virial_peratom_flag = 1;
#endif
}

inline bool virial_on(const LAMMPS_NS::Fix *fix)
{
#if HARDCONTACT_LIGGGHTS
  return fix->virial_flag != 0;
#else
  return fix->thermo_virial != 0;
#endif
}

// ------------------------------------------------------------------------- variables
// After evaluating a variable outside thermo output: the computes it used must be invoked again
// on the next step (Modify::addstep_compute). LIGGGHTS's Modify leaves the count of those
// computes uninitialised until its first init() has listed them (after the fixes' init(), where
// the fix already evaluates its wall variables): before that there is nothing to tell.
inline void addstep_compute(LAMMPS_NS::Modify *modify, LAMMPS_NS::bigint step)
{
#if HARDCONTACT_LIGGGHTS
  if (liggghts::compute_time_list(modify) == nullptr) return;
#endif
  modify->addstep_compute(step);
}

// The index of the variable with this name, or -1 (LIGGGHTS's Variable::find takes a char *).
inline int find_variable(LAMMPS_NS::Variable *variable, const std::string &name)
{
#if HARDCONTACT_LIGGGHTS
  std::vector<char> writable(name.begin(), name.end());
  writable.push_back('\0');
  return variable->find(writable.data());
#else
  return variable->find(name.c_str());
#endif
}

}    // namespace compat
}    // namespace hardcontact
