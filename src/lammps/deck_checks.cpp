#include "deck_checks.h"

#include "lammps_compat.h"

#include "force.h"
#include "pair.h"

#include <mpi.h>

#include <cstring>
#include <string>

using namespace LAMMPS_NS;

namespace hardcontact {
namespace {

// Atoms (over all ranks) in both groups.
long long shared_atoms(LAMMPS *lmp, int groupbit_a, int groupbit_b)
{
  const int *mask = lmp->atom->mask;
  long long mine = 0;
  for (int i = 0; i < lmp->atom->nlocal; ++i)
    if ((mask[i] & groupbit_a) && (mask[i] & groupbit_b)) ++mine;
  long long all = 0;
  MPI_Allreduce(&mine, &all, 1, MPI_LONG_LONG, MPI_SUM, lmp->world);
  return all;
}

bool starts_with(const char *s, const char *prefix)
{
  return s != nullptr && std::strncmp(s, prefix, std::strlen(prefix)) == 0;
}

// What a soft deck's damping becomes, for the messages.
const char *damping_note(bool restitution_given)
{
  return restitution_given ? "damping -> the fix's restitution keyword (given)"
                           : "damping -> 'restitution e' (without it the hard contacts are "
                             "perfectly inelastic, e = 0)";
}

}    // namespace

void DeckChecks::check(LAMMPS *lmp, Fix &fix, bool restitution_given)
{
  Modify *modify = lmp->modify;
  const bool speak = !warned_ && lmp->comm->me == 0;
  for (int k = 0; k < modify->nfix; ++k) {
    Fix *other = modify->fix[k];
    if (other == &fix) continue;
    const bool integrates = other->time_integrate != 0;
    const bool soft_wall = starts_with(other->style, "wall/gran");
    if (!integrates && !soft_wall) continue;
    const long long shared = shared_atoms(lmp, fix.groupbit, other->groupbit);
    if (shared == 0) continue;
    if (integrates)
      compat::error_all(
          lmp->error, FLERR,
          "Fix hardcontact {}: fix {} ({}) also integrates {} of its atoms, which would move "
          "twice per step: delete the line 'fix {} ... {}' (fix hardcontact integrates the "
          "positions, velocities and spins of its group itself), or give the two fixes "
          "groups that do not overlap",
          fix.id, other->id, other->style, shared, other->id, other->style);
    if (speak)
      compat::warning(
          lmp->error, FLERR,
          "Fix hardcontact {}: fix {} ({}) adds soft-sphere wall forces on {} of its atoms, "
          "on top of the hard contacts: delete that line and give the wall to fix "
          "hardcontact ({}), with 'friction mu' after it for a frictional wall",
          fix.id, other->id, other->style, shared,
          compat::kRegionFacesNumbered
              ? "'wall xplane|yplane|zplane lo hi' for a plane, 'wall region ID' for a region"
              : "'wall xplane|yplane|zplane lo hi'; this host has no region or mesh walls yet");
  }
  Force *force = lmp->force;
  if (speak && force->pair != nullptr && force->pair_match("gran", 0) != nullptr)
    compat::warning(lmp->error, FLERR,
                    "Fix hardcontact {}: pair_style {} adds soft-sphere contact forces on top "
                    "of the hard contacts (the spheres would overlap and bounce as the soft "
                    "model says): replace the pair_style and pair_coeff lines by 'pair_style "
                    "none' and carry their parameters to the fix line: stiffness -> nothing, "
                    "{}, friction -> 'friction mu', rolling -> 'rolling mur', twisting -> "
                    "'twisting mut', cohesion -> 'cohesion'",
                    fix.id, force->pair_style, damping_note(restitution_given));
  // (a region wall with open faces: RegionWallSource::init warns)
  warned_ = true;
}

}    // namespace hardcontact
