// The stopping criterion shared by every solver, so that they compare fairly.
#pragma once

#include "contact_problem.h"
#include "distributed_ops.h"

#include <vector>

namespace hardcontact {

// Violation of the complementarity conditions (eq. 17-18) by row c, in units of its size:
// the predicted overlap max(0, -g)/size, and for a pushing row (mu > 0) also the predicted
// gap |g|/size that its force should have closed. 0 exactly at the solution of eq. 15.
inline double row_violation(double g, double mu, double size)
{
  const double v = mu > 0.0 ? (g < 0.0 ? -g : g) : (g < 0.0 ? -g : 0.0);
  return v / size;
}

// Largest row_violation over all rows of all processes.
double residual(const ContactProblem &p, const std::vector<double> &mu,
                const std::vector<Vec3> &u, DistributedOps &ops);

}    // namespace hardcontact
