#include "apgd.h"

#include "residual.h"
#include "step_size.h"
#include "velocity_update.h"

#include <algorithm>
#include <cmath>

namespace hardcontact {

// The dual of eq. 15 as a minimisation over mu >= 0:
//   phi(mu) = 1/2 mu.A mu + b.mu,  grad phi = A mu + b = g(u(mu)),  A = h^2 G M^-1 G^T,
// so the Uzawa step of section 3.3 is projected gradient descent with step rho, and
// phi(mu) = 1/2 mu.(g(mu) + b) costs no extra product.
SolveReport Apgd::solve(const ContactProblem &p, const SolverSettings &s, DistributedOps &ops,
                        std::vector<double> &mu, std::vector<Vec3> &u)
{
  const int nc = p.n_contacts();
  mu.resize(nc, 0.0);
  for (double &m : mu) m = std::max(0.0, m);    // a start below 0 is no contact force
  for (auto *v : {&b_, &g_, &y_, &gy_, &next_, &gnext_}) v->assign(nc, 0.0);
  set_.init(p, mu, s.tol, ops);

  velocities_from_multipliers(p, std::vector<int>(), mu, u, ops);    // u = u_free
  for (int c = 0; c < nc; ++c) b_[c] = p.predicted_gap(c, u);

  auto gaps = [&](const std::vector<double> &m, std::vector<double> &g) {
    velocities_from_multipliers(p, set_.rows(), m, u, ops);
    for (const int c : set_.rows()) g[c] = p.predicted_gap(c, u);
  };
  gaps(mu, g_);

  SolveReport report;
  // Start L below the Gershgorin bound of the working set: backtracking raises it as needed.
  auto initial_lipschitz = [&] {
    return s.rho > 0.0 ? 1.0 / s.rho : 0.25 * dual_operator_bound(p, set_.rows(), ops);
  };
  double L = initial_lipschitz();
  double theta = 1.0;
  auto restart = [&] {
    theta = 1.0;
    for (const int c : set_.rows()) {
      y_[c] = mu[c];
      gy_[c] = g_[c];
    }
  };
  restart();

  for (int k = 0;; ++k) {
    double r = 0.0;
    for (const int c : set_.rows()) r = std::max(r, set_.violation(c, g_[c], mu[c]));
    report.residual = ops.max_all(r);
    report.iterations = k;
    const auto verdict = set_.check(k, report.residual, s.tol, p, mu, u, ops);
    if (verdict == WorkingSet::Verdict::Converged) {
      report.converged = true;
      break;
    }
    if (verdict == WorkingSet::Verdict::Grown) {
      // New rows enter at mu = y = 0 and the momentum of the others is kept: restarting here
      // would turn the cascade of a large impact (rows joining a few at a time) into plain
      // gradient steps. One extra product gives g(y) on the grown set.
      for (const int c : set_.rows()) g_[c] = p.predicted_gap(c, u);    // u = u(mu)
      gaps(y_, gy_);
      // back to u = u(mu): the next check and the answer must see the iterate, not y
      velocities_from_multipliers(p, set_.rows(), mu, u, ops);
      if (k >= s.maxiter) break;
      continue;
    }
    if (k >= s.maxiter || L <= 0.0) break;

    // Projected step from y with backtracking: accept when the quadratic model with L bounds
    // phi at the trial point (this is what makes 1/L a valid step without knowing ||A||).
    double sums[5];
    for (;;) {
      for (const int c : set_.rows()) next_[c] = std::max(0.0, y_[c] - gy_[c] / L);
      gaps(next_, gnext_);
      // phi(y), phi(next), gy.(next - y), |next - y|^2, gy.(next - mu) - each row counted once
      for (double &v : sums) v = 0.0;
      for (const int c : set_.rows()) {
        if (!p.counted[c]) continue;
        const double d = next_[c] - y_[c];
        sums[0] += 0.5 * y_[c] * (gy_[c] + b_[c]);
        sums[1] += 0.5 * next_[c] * (gnext_[c] + b_[c]);
        sums[2] += gy_[c] * d;
        sums[3] += d * d;
        sums[4] += gy_[c] * (next_[c] - mu[c]);
      }
      ops.sum_all(sums, 5);
      const double slack = 1e-12 * (std::abs(sums[0]) + std::abs(sums[1]));
      if (sums[1] <= sums[0] + sums[2] + 0.5 * L * sums[3] + slack) break;
      // A step too small to change anything cannot fail the test for a real reason (round-off
      // in phi): accept it rather than let L run away.
      if (!(L < 1e300) || sums[3] == 0.0) break;
      L *= 2.0;
    }
    if (!(L < 1e300)) {    // the estimate broke down: report the iterate, unconverged
      velocities_from_multipliers(p, set_.rows(), mu, u, ops);
      break;
    }

    // Nesterov momentum, dropped when it points uphill (gradient restart).
    double theta_next = 0.5 * (1.0 + std::sqrt(1.0 + 4.0 * theta * theta));
    double beta = (theta - 1.0) / theta_next;
    if (sums[4] > 0.0) {
      theta_next = 1.0;
      beta = 0.0;
    }
    for (const int c : set_.rows()) {
      y_[c] = next_[c] + beta * (next_[c] - mu[c]);
      gy_[c] = gnext_[c] + beta * (gnext_[c] - g_[c]);
      mu[c] = next_[c];
      g_[c] = gnext_[c];
    }
    theta = theta_next;
    L *= 0.9;    // let the estimate come back down where the problem is softer
  }
  report.rho = L > 0.0 ? 1.0 / L : 0.0;
  // An unconverged answer reports its violation over every row, inside the working set or not.
  if (!report.converged) report.residual = residual(p, mu, u, set_.scales(), ops);
  report.speed_scale = set_.speed_scale();
  return report;
}

}    // namespace hardcontact
