#include "exact.h"

#include "../dual_operator.h"
#include "../residual.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>

namespace hardcontact {

using SparseMatrix = Eigen::SparseMatrix<double>;

SolveReport Exact::solve(const ContactProblem &p, const SolverSettings &s, DistributedOps &ops,
                         std::vector<double> &mu, std::vector<Vec3> &u)
{
  const int nc = p.n_contacts();
  mu.assign(nc, 0.0);    // a cold start: the method is finite from mu = 0
  SolveReport report;

  DualOperator op;
  op.bind(p, ops);
  const SparseMatrix A = op.assembled();
  op.free_velocities(u);
  Eigen::VectorXd b(nc), scale(nc);
  double diag_max = 0.0;
  for (int c = 0; c < nc; ++c) {
    b[c] = p.predicted_gap(c, u);
    scale[c] = p.size[c];
    diag_max = std::max(diag_max, A.coeff(c, c));
  }
  const double reg = 1e-13 * diag_max;    // keeps A_PP definite with redundant rows
  // KKT test on g = A mu + b: relative to the contact size, but never below the round-off of
  // g itself (point-like spheres have sizes far below the gaps' rounding error).
  const double b_scale = nc > 0 ? b.cwiseAbs().maxCoeff() : 0.0;
  for (int c = 0; c < nc; ++c) scale[c] = 1e-13 * scale[c] + 1e-14 * b_scale;

  Eigen::VectorXd m = Eigen::VectorXd::Zero(nc);
  std::vector<char> passive(nc, 0);
  bool batch = true;    // add every violated row at once; one at a time if that stalls
  double phi_prev = 0.0;
  // Finite in exact arithmetic; maxiter caps the outer iterations like the others' iterations.
  const int max_outer = std::min(10 * nc + 10, s.maxiter + 1);
  for (int outer = 0; outer < max_outer; ++outer) {
    const Eigen::VectorXd grad = A * m + b;    // = predicted gaps g(mu)
    const double phi = 0.5 * m.dot(grad + b);
    if (outer > 0 && batch && phi >= phi_prev) batch = false;
    phi_prev = phi;
    int worst = -1;
    int added = 0;
    for (int c = 0; c < nc; ++c) {
      if (passive[c] || grad[c] >= -scale[c]) continue;
      if (batch) {
        passive[c] = 1;
        ++added;
      }
      if (worst < 0 || grad[c] / scale[c] < grad[worst] / scale[worst]) worst = c;
    }
    if (worst < 0) {
      report.converged = true;
      break;
    }
    if (!batch) passive[worst] = 1;
    report.iterations = outer + 1;

    // Inner loop: solve on the passive set; step back to the boundary while a variable of the
    // passive set would go negative (Lawson-Hanson), dropping it from the set.
    for (int inner = 0; inner <= nc; ++inner) {
      std::vector<int> P;
      for (int c = 0; c < nc; ++c)
        if (passive[c]) P.push_back(c);
      const int np = static_cast<int>(P.size());
      std::vector<Eigen::Triplet<double>> t;
      for (int a = 0; a < np; ++a) {
        t.emplace_back(a, a, reg);
        for (SparseMatrix::InnerIterator it(A, P[a]); it; ++it) {
          const auto pos = std::lower_bound(P.begin(), P.end(), static_cast<int>(it.row()));
          if (pos != P.end() && *pos == it.row())
            t.emplace_back(static_cast<int>(pos - P.begin()), a, it.value());
        }
      }
      SparseMatrix App(np, np);
      App.setFromTriplets(t.begin(), t.end());
      Eigen::SimplicialLDLT<SparseMatrix> ldlt(App);
      Eigen::VectorXd rhs(np);
      for (int a = 0; a < np; ++a) rhs[a] = -b[P[a]];
      const Eigen::VectorXd z = ldlt.solve(rhs);
      if (ldlt.info() != Eigen::Success || !z.allFinite()) break;
      double alpha = 1.0;
      for (int a = 0; a < np; ++a)
        if (z[a] <= 0.0) alpha = std::min(alpha, m[P[a]] / (m[P[a]] - z[a]));
      for (int a = 0; a < np; ++a) m[P[a]] += alpha * (z[a] - m[P[a]]);
      if (alpha >= 1.0) break;
      for (int a = 0; a < np; ++a)
        if (m[P[a]] <= 0.0) {
          m[P[a]] = 0.0;
          passive[P[a]] = 0;
        }
    }
  }
  for (int c = 0; c < nc; ++c) mu[c] = m[c];
  op.velocities(mu, u);
  std::vector<double> row_scale_of;
  report.speed_scale = row_scales(p, s.tol, ops, row_scale_of);
  report.residual = residual<NormalLaw>(op, mu, u, row_scale_of);
  report.converged = report.converged && report.residual <= s.tol;
  return report;
}

}    // namespace hardcontact
