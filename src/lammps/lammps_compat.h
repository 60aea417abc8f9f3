// Hides the two LAMMPS APIs a fix uses that changed on 24 Mar 2022.
// HARDCONTACT_MODERN_API is set by cmake/HardcontactLammpsApi.cmake from a compile check
// against the LAMMPS headers in use (there is no version macro to test).
#pragma once

#include "comm.h"
#include "domain.h"
#include "fix.h"
#include "region.h"
#include "neigh_request.h"
#include "neighbor.h"

#include <string>

namespace hardcontact {
namespace compat {

// A half list of every owned/ghost pair closer than r_i + r_j + skin, holding cross-processor
// pairs on both processors (newton off), with a stencil that reaches `cutoff`.
// `instance` is the fix's instance_me (protected in Fix, so the caller passes it).
inline void request_size_list(LAMMPS_NS::Neighbor *neighbor, LAMMPS_NS::Fix *fix, int instance,
                              double cutoff)
{
#if HARDCONTACT_MODERN_API
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
// its stencil and bins use the custom cutoff as given; old LAMMPS checks nothing. Asking for the
// extra skin of ghosts is the only way through that check: it costs one skin shell of ghosts.
inline double ghost_cutoff_for_request(double cutoff, double skin)
{
#if HARDCONTACT_MODERN_API
  return cutoff + skin;
#else
  (void) skin;
  return cutoff;
#endif
}

// The region with this ID, or nullptr (modern: Domain::get_region_by_id; old: an index).
inline LAMMPS_NS::Region *find_region(LAMMPS_NS::Domain *domain, const std::string &id)
{
#if HARDCONTACT_MODERN_API
  return domain->get_region_by_id(id);
#else
  const int i = domain->find_region(id);
  return i < 0 ? nullptr : domain->regions[i];
#endif
}

inline void forward_comm(LAMMPS_NS::Comm *comm, LAMMPS_NS::Fix *fix)
{
#if HARDCONTACT_MODERN_API
  comm->forward_comm(fix);
#else
  comm->forward_comm_fix(fix);
#endif
}

}    // namespace compat
}    // namespace hardcontact
