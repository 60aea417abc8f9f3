#include "effect.h"

#include "atom.h"

namespace hardcontact {

void pair_values_of_rows(const ContactProblem &p, const int *type, int ntypes,
                         const std::vector<double> &table, int first, std::vector<double> &out)
{
  const int nc = p.n_contacts();
  const int stride = ntypes + 1;
  out.resize(nc);
  for (int c = first; c < nc; ++c) {
    const int ti = type[p.body_i[c]];
    const int j = p.body_j[c];
    out[c] = table[ti * stride + (is_wall(j) ? ti : type[j])];
  }
}

void EffectStep::pair_values(const std::vector<double> &table, int first,
                             std::vector<double> &out) const
{
  pair_values_of_rows(problem, lmp->atom->type, lmp->atom->ntypes, table, first, out);
}

}    // namespace hardcontact
