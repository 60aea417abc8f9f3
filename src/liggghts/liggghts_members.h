// The members of LIGGGHTS 3.8 classes the fix needs but LIGGGHTS keeps private or protected
// (all public in LAMMPS): the table of fix styles (to register the fix), the neighbour stencil's
// squared reach and the user's bin sizes (to size lists and bins without a pair style), the
// list of computes that record their invocation times (whether it exists yet).
#pragma once

#include "pointers.h"

#include <map>
#include <string>

namespace LAMMPS_NS {
class Atom;
class Fix;
class Modify;
class Neighbor;
}    // namespace LAMMPS_NS

namespace hardcontact {
namespace liggghts {

using FixCreator = LAMMPS_NS::Fix *(*) (LAMMPS_NS::LAMMPS *, int, char **);
using FixStyles = std::map<std::string, FixCreator>;

FixStyles &fix_styles(LAMMPS_NS::Modify *modify);            // Modify::fix_map (private)
double &stencil_reach_sq(LAMMPS_NS::Neighbor *neighbor);     // Neighbor::cutneighmaxsq
int &bin_size_set(LAMMPS_NS::Neighbor *neighbor);            // Neighbor::binsizeflag
double &bin_size(LAMMPS_NS::Neighbor *neighbor);             // Neighbor::binsize_user
double &sort_bin_size(LAMMPS_NS::Atom *atom);                // Atom::userbinsize (private)
int *compute_time_list(LAMMPS_NS::Modify *modify);           // Modify::list_timeflag

}    // namespace liggghts
}    // namespace hardcontact
