#include "residual.h"

#include <algorithm>

namespace hardcontact {

double residual(const ContactProblem &p, const std::vector<double> &mu,
                const std::vector<Vec3> &u, DistributedOps &ops)
{
  double r = 0.0;
  const int nc = p.n_contacts();
  for (int c = 0; c < nc; ++c) r = std::max(r, row_violation(p.predicted_gap(c, u), mu[c], p.size[c]));
  return ops.max_all(r);
}

}    // namespace hardcontact
