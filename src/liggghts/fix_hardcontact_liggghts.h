// fix hardcontact on LIGGGHTS 3.8: FixHardContact (src/lammps/) plus the callbacks LIGGGHTS
// offers instead of LAMMPS's. Its Fix has no post_neighbor: post_neighbor() runs from pre_force
// on the steps whose lists were just built (nothing happens in between: Verlet builds the lists,
// clears forces, then calls pre_force). Forward communication is pack_comm/unpack_comm there
// (pack_comm returns the values per atom, not their total). Its fix_modify has no virial
// keyword: the fix takes `fix_modify ID virial yes|no` itself.
// Its neighbour requests carry no cutoff: the stencil is widened to the fix's reach before the
// bins are set up, every run (Neighbor::init resets it).
#pragma once

#include "fix_hardcontact.h"

namespace LAMMPS_NS {

class FixHardContactLiggghts : public FixHardContact {
 public:
  FixHardContactLiggghts(class LAMMPS *lmp, int narg, char **arg);
  int setmask() override;
  void init() override;
  void setup_pre_exchange() override;
  void pre_exchange() override;
  void setup_pre_force(int) override;
  void pre_force(int) override;
  int pack_comm(int n, int *list, double *buf, int pbc_flag, int *pbc) override;
  void unpack_comm(int n, int first, double *buf) override;
  int modify_param(int narg, char **arg) override;
};

// Puts the fix style "hardcontact" into this LIGGGHTS instance's table of fix styles.
void register_fix_hardcontact(class LAMMPS *lmp);

}    // namespace LAMMPS_NS
