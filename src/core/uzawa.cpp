#include "uzawa.h"

#include "residual.h"
#include "step_size.h"
#include "velocity_update.h"

#include <algorithm>

namespace hardcontact {

SolveReport Uzawa::solve(const ContactProblem &p, const SolverSettings &s, DistributedOps &ops,
                         std::vector<double> &mu, std::vector<Vec3> &u)
{
  const int nc = p.n_contacts();
  mu.resize(nc, 0.0);
  next_.resize(nc);

  SolveReport report;
  // rho = 1/L: inside (0, 2/L) with margin, and the exact one-step answer for an isolated pair.
  if (s.rho > 0.0) {
    report.rho = s.rho;
  } else {
    const double bound = dual_operator_bound(p, ops);
    report.rho = bound > 0.0 ? 1.0 / bound : 0.0;
  }

  velocities_from_multipliers(p, mu, u, ops);
  for (int k = 0;; ++k) {
    // With C = -h G: mu_{k+1} = max(0, mu_k + rho (C u_k - D)) = max(0, mu_k - rho g(u_k)).
    double r = 0.0;
    for (int c = 0; c < nc; ++c) {
      const double g = p.predicted_gap(c, u);
      r = std::max(r, row_violation(g, mu[c], p.size[c]));
      next_[c] = std::max(0.0, mu[c] - report.rho * g);
    }
    report.residual = ops.max_all(r);
    report.iterations = k;
    if (report.residual <= s.tol) {
      report.converged = true;
      break;
    }
    if (k >= s.maxiter) break;
    mu.swap(next_);
    velocities_from_multipliers(p, mu, u, ops);    // u_{k+1} from mu_{k+1} (eq. 16)
  }
  return report;
}

}    // namespace hardcontact
