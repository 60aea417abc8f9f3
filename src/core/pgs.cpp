#include "pgs.h"

#include "residual.h"
#include "velocity_update.h"

#include <algorithm>

namespace hardcontact {

SolveReport Pgs::solve(const ContactProblem &p, const SolverSettings &s, DistributedOps &ops,
                       std::vector<double> &mu, std::vector<Vec3> &u)
{
  const int nc = p.n_contacts();
  mu.resize(nc, 0.0);
  for (double &m : mu) m = std::max(0.0, m);    // a start below 0 is no contact force
  set_.init(p, mu, s.tol, ops);
  velocities_from_multipliers(p, set_.rows(), mu, u, ops);
  const double h2 = p.h * p.h;

  // Row degrees for the Gershgorin step of the boundary rows (owners count, ghosts receive).
  auto count_degrees = [&] {
    deg_.assign(p.n_bodies(), 0.0);
    for (const int c : set_.rows()) {
      const int i = p.body_i[c], j = p.body_j[c];
      if (i < p.n_owned) deg_[i] += 1.0;
      if (j >= 0 && j < p.n_owned) deg_[j] += 1.0;
    }
    ops.forward(deg_.data(), 1);
  };
  count_degrees();

  auto apply = [&](int c, double dmu) {
    const Vec3 impulse = (p.h * dmu) * p.normal[c];
    const int i = p.body_i[c], j = p.body_j[c];
    if (i < p.n_owned) u[i] -= p.inv_mass[i] * impulse;
    if (j >= 0 && j < p.n_owned) u[j] += p.inv_mass[j] * impulse;
  };

  SolveReport report;
  for (int k = 0;; ++k) {
    double r = 0.0;
    for (const int c : set_.rows())
      r = std::max(r, set_.violation(c, p.predicted_gap(c, u), mu[c]));
    report.residual = ops.max_all(r);
    report.iterations = k;
    const auto verdict = set_.check(k, report.residual, s.tol, p, mu, u, ops);
    if (verdict == WorkingSet::Verdict::Converged) {
      report.converged = true;
      break;
    }
    if (verdict == WorkingSet::Verdict::Grown) {
      count_degrees();
      if (k >= s.maxiter) break;
      continue;
    }
    if (k >= s.maxiter) break;

    // One sweep: boundary rows (Jacobi, from the exchanged velocities) ...
    const int nrows = static_cast<int>(set_.rows().size());
    std::vector<double> &dmu = dmu_;
    dmu.assign(nrows, 0.0);
    for (int q = 0; q < nrows; ++q) {
      const int c = set_.rows()[q];
      const int j = p.body_j[c];
      if (j < p.n_owned) continue;    // owned pair or wall: swept below
      const int i = p.body_i[c];
      const double bound = h2 * (p.inv_mass[i] * deg_[i] + p.inv_mass[j] * deg_[j]);
      if (bound <= 0.0) continue;
      dmu[q] = std::max(0.0, mu[c] - p.predicted_gap(c, u) / bound) - mu[c];
    }
    for (int q = 0; q < nrows; ++q) {
      if (dmu[q] == 0.0) continue;
      const int c = set_.rows()[q];
      mu[c] += dmu[q];
      apply(c, dmu[q]);
    }
    // ... then rows inside this process, Gauss-Seidel: the exact minimiser along each row.
    for (const int c : set_.rows()) {
      const int i = p.body_i[c], j = p.body_j[c];
      if (j >= p.n_owned) continue;
      const double diag = h2 * (p.inv_mass[i] + (j >= 0 ? p.inv_mass[j] : 0.0));
      if (diag <= 0.0) continue;
      const double next = std::max(0.0, mu[c] - p.predicted_gap(c, u) / diag);
      apply(c, next - mu[c]);
      mu[c] = next;
    }
    ops.forward(u.data()->data(), 3);
  }
  if (!report.converged) report.residual = residual(p, mu, u, set_.scales(), ops);
  report.speed_scale = set_.speed_scale();
  return report;
}

}    // namespace hardcontact
