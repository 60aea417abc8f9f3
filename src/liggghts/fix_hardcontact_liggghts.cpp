#include "fix_hardcontact_liggghts.h"

#include "liggghts_members.h"

#include "error.h"
#include "force.h"
#include "modify.h"
#include "neighbor.h"

#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

FixHardContactLiggghts::FixHardContactLiggghts(LAMMPS *lmp, int narg, char **arg) :
    FixHardContact(lmp, narg, arg)
{
}

int FixHardContactLiggghts::setmask()
{
  return FixHardContact::setmask() | PRE_EXCHANGE | PRE_FORCE;
}

void FixHardContactLiggghts::init()
{
  // LIGGGHTS's granular list (the one a request can ask for that tests r_i + r_j + skin) holds
  // a pair across processors on both of them only with newton off, as its pair gran with
  // history also requires.
  if (force->newton_pair)
    error->all(FLERR, "Fix hardcontact on LIGGGHTS requires 'newton off' (as pair gran with "
                      "history does): add 'newton off' before the box is created");
  FixHardContact::init();
}

void FixHardContactLiggghts::setup_pre_exchange()
{
  pre_exchange();
}

// Before Verlet sets up the bins (at setup, and on box changes during a run).
void FixHardContactLiggghts::pre_exchange()
{
  hardcontact::compat::reach_stencil(neighbor, reach_cutoff());
}

void FixHardContactLiggghts::setup_pre_force(int)
{
  setup_post_neighbor();
}

void FixHardContactLiggghts::pre_force(int)
{
  if (neighbor->ago == 0) post_neighbor();
}

// LIGGGHTS's Comm sends n x (what pack_comm returns) values: the count per atom, where
// LAMMPS's pack_forward_comm returns the total.
int FixHardContactLiggghts::pack_comm(int n, int *list, double *buf, int pbc_flag, int *pbc)
{
  pack_forward_comm(n, list, buf, pbc_flag, pbc);
  return forward_values_per_atom();
}

void FixHardContactLiggghts::unpack_comm(int n, int first, double *buf)
{
  unpack_forward_comm(n, first, buf);
}

// fix_modify ID virial yes|no, as on LAMMPS (compat::offer_virial: virial_flag is the switch
// LIGGGHTS's computes read); the fix's own options (contacts) as on LAMMPS
int FixHardContactLiggghts::modify_param(int narg, char **arg)
{
  if (std::strcmp(arg[0], "virial") != 0) return FixHardContact::modify_param(narg, arg);
  if (narg < 2 || (std::strcmp(arg[1], "yes") != 0 && std::strcmp(arg[1], "no") != 0))
    error->all(FLERR, "Illegal fix_modify command: fix hardcontact virial takes yes or no");
  virial_flag = std::strcmp(arg[1], "yes") == 0 ? 1 : 0;
  return 2;
}

/* ---------------------------------------------------------------------- registration */

namespace {

Fix *create_fix_hardcontact(LAMMPS *lmp, int narg, char **arg)
{
  return new FixHardContactLiggghts(lmp, narg, arg);
}

}    // namespace

// Modify::fix_map is private in LIGGGHTS: liggghts_members.cpp says how it is reached.
void LAMMPS_NS::register_fix_hardcontact(LAMMPS *lmp)
{
  hardcontact::liggghts::fix_styles(lmp->modify)["hardcontact"] = &create_fix_hardcontact;
}
