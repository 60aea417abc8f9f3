// Cohesion: a touching contact holds up to F of pull before it opens, i.e. its multiplier may
// go down to -F (the law's bound shifted: mu >= -F, complementary to g >= 0). With mu' = mu + F
// the bound is the paper's mu' >= 0 again, and since u is affine in mu (eq. 16),
//   u(mu) = u_free + h M^-1 G^T mu = (u_free - h M^-1 G^T F) + h M^-1 G^T mu',
// so the shifted problem is the paper's problem from a u_free that already carries the pull F
// of every cohesive row. Solve it as usual; the contact force is mu' - F. Its work is part of
// u_free, so the energy test of the solve holds as it is.
#pragma once

#include "contact_problem.h"
#include "distributed_ops.h"

#include <vector>

namespace hardcontact {

// pull[c]: the cohesion F of row c if it is touching (D <= touch size_c), else 0. Applies the
// pulls to p.u_free (owned bodies; ghosts forwarded). Returns whether any row pulls (here).
bool apply_cohesion(ContactProblem &p, const std::vector<double> &cohesion, double touch,
                    DistributedOps &ops, std::vector<double> &pull);

}    // namespace hardcontact
