#include "step_size.h"

#include <algorithm>
#include <vector>

namespace hardcontact {

double dual_operator_bound(const ContactProblem &p, const std::vector<int> &rows,
                           DistributedOps &ops)
{
  // Degrees are complete on the owner of a body (it holds every row of its own bodies),
  // so owners count and ghosts receive the count.
  std::vector<double> deg(p.n_bodies(), 0.0);
  for (const int c : rows) {
    const int i = p.body_i[c], j = p.body_j[c];
    if (i < p.n_owned) deg[i] += 1.0;
    if (j >= 0 && j < p.n_owned) deg[j] += 1.0;
  }
  ops.forward(deg.data(), 1);

  double bound = 0.0;
  for (const int c : rows) {
    const int i = p.body_i[c], j = p.body_j[c];
    double row = p.inv_mass[i] * deg[i];
    if (j >= 0) row += p.inv_mass[j] * deg[j];
    bound = std::max(bound, row);
  }
  return p.h * p.h * ops.max_all(bound);
}

double dual_operator_bound(const ContactProblem &p, DistributedOps &ops)
{
  std::vector<int> all(p.n_contacts());
  for (int c = 0; c < p.n_contacts(); ++c) all[c] = c;
  return dual_operator_bound(p, all, ops);
}

}    // namespace hardcontact
