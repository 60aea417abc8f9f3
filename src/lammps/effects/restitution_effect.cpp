#include "restitution_effect.h"

#include "../keywords.h"
#include "../lammps_compat.h"
#include "../lammps_ops.h"
#include "../../core/restitution.h"

#include "atom.h"
#include "error.h"

namespace hardcontact {

bool RestitutionEffect::present() const { return FixOptions::any_positive(table_); }

std::vector<EffectKeyword> RestitutionEffect::keywords()
{
  return {
      {"restitution", 1, 2,
       "restitution e [I J]: Newton's restitution e in [0, 1] for type pairs I J (all: default)",
       [](LAMMPS_NS::LAMMPS *lmp, char **values, int n, Effect &e) {
         parse_pair_coefficient(lmp, "restitution",
                                "in [0, 1] (0: inelastic, the paper's scheme; 1: elastic)", 0.0,
                                1.0, values, n, static_cast<RestitutionEffect &>(e).table_);
       }},
      {"bounce", 1, 0, "bounce vmin: contacts closing slower stay inelastic",
       [](LAMMPS_NS::LAMMPS *lmp, char **values, int, Effect &e) {
         double &vmin = static_cast<RestitutionEffect &>(e).vmin_;
         vmin = keyword_number(lmp, "bounce", values[0]);
         if (vmin < 0.0)
           compat::error_all(lmp->error, FLERR,
                             "Fix hardcontact bounce must be a speed >= 0 (contacts closing "
                             "slower stay inelastic), got {}",
                             values[0]);
       }},
  };
}

bool RestitutionEffect::begin_step(EffectStep &step)
{
  const LAMMPS_NS::Atom *atom = step.lmp->atom;
  const int nlocal = atom->nlocal;
  u_start_.resize(nlocal + atom->nghost);
  for (int i = 0; i < nlocal; ++i) u_start_[i] = Vec3(atom->v[i]);
  step.ops.forward(doubles(u_start_), kDoublesPerVec3);
  return false;
}

void RestitutionEffect::target_rows(EffectStep &step, int first)
{
  step.pair_values(table_, first, row_e_);
  add_rebound_targets(step.problem, first, row_e_, u_start_, vmin_);
}

}    // namespace hardcontact
