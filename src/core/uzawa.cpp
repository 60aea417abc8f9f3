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
  for (double &m : mu) m = std::max(0.0, m);    // a start below 0 is no contact force
  next_.resize(nc);
  set_.init(p, mu, s.tol, ops);

  SolveReport report;
  // rho = 1/L: inside (0, 2/L) with margin, and the exact one-step answer for an isolated pair.
  auto choose_rho = [&] {
    if (s.rho > 0.0) return s.rho;
    const double bound = dual_operator_bound(p, set_.rows(), ops);
    return bound > 0.0 ? 1.0 / bound : 0.0;
  };
  report.rho = choose_rho();

  velocities_from_multipliers(p, set_.rows(), mu, u, ops);
  for (int k = 0;; ++k) {
    // With C = -h G: mu_{k+1} = max(0, mu_k + rho (C u_k - D)) = max(0, mu_k - rho g(u_k)).
    double r = 0.0;
    for (const int c : set_.rows()) {
      const double g = p.predicted_gap(c, u);
      r = std::max(r, set_.violation(c, g, mu[c]));
      next_[c] = std::max(0.0, mu[c] - report.rho * g);
    }
    report.residual = ops.max_all(r);
    report.iterations = k;
    const auto verdict = set_.check(k, report.residual, s.tol, p, mu, u, ops);
    if (verdict == WorkingSet::Verdict::Converged) {
      report.converged = true;
      break;
    }
    if (verdict == WorkingSet::Verdict::Grown) {
      // New rows start at mu = 0 and enter the update from the next pass, with a new step:
      // the bound holds for the working set only.
      report.rho = choose_rho();
      if (k >= s.maxiter) break;
      continue;
    }
    if (k >= s.maxiter) break;
    for (const int c : set_.rows()) mu[c] = next_[c];
    velocities_from_multipliers(p, set_.rows(), mu, u, ops);    // u_{k+1} from mu_{k+1} (eq. 16)
  }
  // An unconverged answer reports its violation over every row, inside the working set or not.
  if (!report.converged) report.residual = residual(p, mu, u, set_.scales(), ops);
  report.speed_scale = set_.speed_scale();
  return report;
}

}    // namespace hardcontact
