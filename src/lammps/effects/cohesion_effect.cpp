#include "cohesion_effect.h"

#include "../keywords.h"
#include "../../core/cohesion.h"

#include <limits>

namespace hardcontact {

bool CohesionEffect::present() const { return FixOptions::any_positive(table_); }

std::vector<EffectKeyword> CohesionEffect::keywords()
{
  return {
      {"cohesion", 1, 2,
       "cohesion F [I J]: a touching contact holds up to F of pull, for type pairs I J (all: "
       "default)",
       [](LAMMPS_NS::LAMMPS *lmp, char **values, int n, Effect &e) {
         parse_pair_coefficient(lmp, "cohesion",
                                "a force >= 0 (the pull a touching contact holds before it opens)",
                                0.0, std::numeric_limits<double>::infinity(), values, n,
                                static_cast<CohesionEffect &>(e).table_);
       }},
  };
}

bool CohesionEffect::begin_step(EffectStep &step)
{
  step.pair_values(table_, 0, row_f_);
  apply_cohesion(step.problem, row_f_, step.tol, step.ops, pull_);
  return true;
}

const std::vector<double> *CohesionEffect::reported_forces(const ContactProblem &p,
                                                           const std::vector<double> &mu,
                                                           int block)
{
  const int nc = p.n_contacts();
  pull_.resize(nc, 0.0);    // rows of later rounds do not pull
  force_ = mu;
  for (int c = 0; c < nc; ++c) force_[static_cast<size_t>(block) * c] -= pull_[c];
  return &force_;
}

}    // namespace hardcontact
