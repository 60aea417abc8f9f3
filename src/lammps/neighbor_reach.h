// How far the fix's neighbour list and the ghosts reach: contacts up to 2 r_max, plus the skin.
// With pair_style none LAMMPS sizes neither (DESIGN.md), so the fix asks for both itself.
#pragma once

#include "pointers.h"

namespace LAMMPS_NS {
class Fix;
}

namespace hardcontact {

class NeighborReach : protected LAMMPS_NS::Pointers {
 public:
  explicit NeighborReach(LAMMPS_NS::LAMMPS *lmp) : Pointers(lmp) {}
  // At Fix::init: the request, the ghost cutoff and the bins for the radii present.
  void init(LAMMPS_NS::Fix *fix, int instance_me);
  // Collective: the largest radius of all owned atoms now, checked against the reach.
  void check_all_radii() const;
  // Stops with an error if rmax_now (over all processes) exceeds the radius sized for.
  void check_radius(double rmax_now) const;
  // 2 r_max + skin, set by init
  double cutoff() const { return cutoff_; }

 private:
  double largest_radius() const;

  double cutoff_ = 0.0;    // 2 r_max + skin, reach of list and ghosts
  double rmax_ = 0.0;
  double user_cutghost_ = -1.0;
  bool binsize_set_here_ = false;
  bool sortbin_set_here_ = false;
};

}    // namespace hardcontact
