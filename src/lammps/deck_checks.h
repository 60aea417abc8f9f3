// What the rest of the input deck must not do beside the fix: the lines a soft-sphere deck
// leaves behind when it is half converted. Each would change the result without a word:
//   - another fix integrating the same atoms (a leftover `fix nve/sphere`): every atom would
//     move twice per step - an ERROR;
//   - a granular pair style (pair gran*, granular): soft contact forces on top of the hard
//     ones, so the spheres overlap and bounce as both models say - a WARNING naming the line;
//   - `fix wall/gran*` on the fix's atoms: soft walls on top of (or instead of) the fix's own -
//     a WARNING naming the fix and the `wall` keyword that replaces it;
// (A region wall with open faces is its source's to warn about: RegionWallSource::init.)
// Warnings are printed once per fix (on the first run), by rank 0; the counts of shared atoms
// are summed over all ranks first, so every rank takes the same decision.
#pragma once

#include <vector>

namespace LAMMPS_NS {
class Fix;
class LAMMPS;
}    // namespace LAMMPS_NS

namespace hardcontact {

class DeckChecks {
 public:
  // From FixHardContact::init: `fix` is the hardcontact fix.
  // `restitution_given`: whether the fix line has the restitution keyword (the messages say
  // what the soft deck's damping becomes).
  void check(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::Fix &fix, bool restitution_given);

 private:
  bool warned_ = false;
};

}    // namespace hardcontact
