// The Uzawa step rho (section 3.3, Remark 8) computed from the rows actually present.
#pragma once

#include "contact_problem.h"
#include "distributed_ops.h"

#include <vector>

namespace hardcontact {

// An upper bound L of the largest eigenvalue of A = h^2 G M^-1 G^T (the dual operator
// C M^-1 C^T of section 3.3): Gershgorin on row c, whose off-diagonal entries are
// h^2 w_k n_c.n_d for rows d sharing body k, gives L = h^2 max_c (w_i deg_i + w_j deg_j),
// deg_k = rows touching body k. This is Remark 8 for any radii and masses: with equal masses
// and kappa rows per body it is 2 kappa h^2 / m. Uzawa converges for 0 < rho < 2 / L.
// Global over processes; 0 when there is no row.
double dual_operator_bound(const ContactProblem &p, DistributedOps &ops);
// Same for the principal submatrix of the listed rows (a solver's working set).
double dual_operator_bound(const ContactProblem &p, const std::vector<int> &rows,
                           DistributedOps &ops);

}    // namespace hardcontact
