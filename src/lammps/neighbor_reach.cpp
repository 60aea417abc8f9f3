#include "neighbor_reach.h"

#include "lammps_compat.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "neighbor.h"

using namespace LAMMPS_NS;

namespace hardcontact {

double NeighborReach::largest_radius() const
{
  double rmax_local = 0.0;
  for (int i = 0; i < atom->nlocal; ++i) rmax_local = MAX(rmax_local, atom->radius[i]);
  double rmax = 0.0;
  MPI_Allreduce(&rmax_local, &rmax, 1, MPI_DOUBLE, MPI_MAX, world);
  return rmax;
}

// Contacts reach r_i + r_j <= 2 r_max; the list must hold every pair that close plus the
// skin, and ghosts must reach as far (DESIGN.md: with pair_style none LAMMPS sets neither).
void NeighborReach::init(Fix *fix, int instance_me)
{
  rmax_ = largest_radius();
  // A ghost cutoff set by the user (comm_modify / LIGGGHTS communicate cutoff) makes room for larger spheres that
  // appear later (fix pour into an empty box).
  if (user_cutghost_ < 0.0) user_cutghost_ = comm->cutghostuser;
  rmax_ = MAX(rmax_, 0.5 * (user_cutghost_ - neighbor->skin));
  cutoff_ = 2.0 * rmax_ + neighbor->skin;
  comm->cutghostuser =
      MAX(user_cutghost_, compat::ghost_cutoff_for_request(cutoff_, neighbor->skin));
  if (force->pair == nullptr && (compat::user_bin_size(neighbor) == 0.0 || binsize_set_here_)) {
    // Without a pair style LAMMPS bins with the whole box (master cutoff 0): O(N^2) lists,
    // and it stops sorting atoms (memory locality). Bin as a pair style of this reach would.
    compat::set_user_bin_size(neighbor, 0.5 * cutoff_);
    binsize_set_here_ = true;
  }
  if (force->pair == nullptr && (compat::sort_bin_size(atom) == 0.0 || sortbin_set_here_)) {
    compat::sort_bin_size(atom) = 0.5 * cutoff_;
    sortbin_set_here_ = true;
  }
  compat::request_size_list(neighbor, fix, instance_me, cutoff_);
}

void NeighborReach::check_all_radii() const
{
  check_radius(largest_radius());
}

// Radii may change during a run (fix adapt, fix pour): the list and ghosts only reach
// 2 r_max + skin.
void NeighborReach::check_radius(double rmax_now) const
{
  if (rmax_now <= rmax_) return;
  compat::error_all(error, FLERR,
                    "Fix hardcontact: a sphere of radius {} appeared during the run, larger than "
                    "the {} the neighbor list and ghosts were sized for; its contacts could be "
                    "missed: use '{} {:.6g}' (room for radius {:.6g} with this "
                    "skin) before the run",
                    rmax_now, rmax_, compat::kGhostCutoffCommand, 2.0 * rmax_now + neighbor->skin,
                    rmax_now);
}

}    // namespace hardcontact
