// Eq. 16: M u = M u_free + h sum_c mu_c G_c, the primal velocities of given multipliers.
#pragma once

#include "contact_problem.h"
#include "distributed_ops.h"

#include <vector>

namespace hardcontact {

// Writes u for owned bodies from u_free and mu, then fetches the ghosts' u from their owners.
// Each row pushes only its owned bodies: a row that couples an owned body with a ghost is held
// by both processes (newton off), so each side applies its own half exactly once.
// `rows`: the rows that may hold mu != 0 (a solver's working set).
void velocities_from_multipliers(const ContactProblem &p, const std::vector<int> &rows,
                                 const std::vector<double> &mu, std::vector<Vec3> &u,
                                 DistributedOps &ops);
// Same over every row.
void velocities_from_multipliers(const ContactProblem &p, const std::vector<double> &mu,
                                 std::vector<Vec3> &u, DistributedOps &ops);

// sum_c mu_c G_c on each owned body: the contact force (eq. 16 divided by h), per body.
void contact_forces(const ContactProblem &p, const std::vector<double> &mu,
                    std::vector<Vec3> &force);

}    // namespace hardcontact
