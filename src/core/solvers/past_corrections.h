// The subspace start (SolverSettings::subspace) shared by cg and apgd (frictionless): a solver's last N
// corrections W (answer - warm start, per row block) and their products A W, kept from step to
// step, and the best point of the dual objective phi over mu + W c.
//
// Why (bench/studies/spectrum 10.2): at rest every step starts a few times tol away from
// its answer, in the slowest modes of A: the error one step leaves returns in the next as
// 3 r_n - 3 r_(n-1) + r_(n-2). A first-order or Krylov method pays for those modes again every
// step; the past corrections span them, so one N x N Galerkin solve
//   (W^T A W) c = -W^T g(mu)
// removes most of the start's error. A W is carried from the step each correction was made in
// (at rest A hardly changes); the solver checks the move exactly and keeps it only if phi
// fell, so a stale product costs iterations, never accuracy.
#pragma once

#include "../contact_problem.h"
#include "../container_bytes.h"
#include "../distributed_ops.h"

#include <Eigen/Dense>

#include <algorithm>
#include <vector>

namespace hardcontact {

class PastCorrections {
 public:
  // block: multipliers per row (the law's; 1 frictionless). With friction the start was tried
  // and not kept (bench/studies/friction_deep 10.4): the best point of the span leaves the
  // cone far, its projection raises phi, and the tangential pairs would also have to follow the
  // tangents the host derives from each step's normal.
  explicit PastCorrections(int block) : block_(block) {}

  bool empty() const { return w_.empty(); }
  // Whether this solve tries the start (called once per solve, before rows_used). After a
  // refused move the next 1, 2, 4, ... kMaxSkip solves do not try: where the move is refused
  // step after step (a deep frictionless pile at rest whose sliding spheres change contacts)
  // each try cost its N x N system, a product and the rows its corrections bring into the
  // working set, 8-14 % of the time for nothing (bench/studies/subspace_default 10.7). Every process
  // takes the same decision: the outcome of a try is a reduced sum.
  bool due()
  {
    trying_ = !w_.empty() && skip_ == 0;
    if (!w_.empty() && skip_ > 0) --skip_;
    return trying_;
  }
  // what the last due() said: improve_start runs only then
  bool trying() const { return trying_; }
  void clear()
  {
    w_.clear();
    aw_.clear();
  }
  // At the start of a solve: onto this problem's rows, by their bodies (rows new since hold 0).
  // A new neighbour list renumbers the bodies: then every process drops them (the subspace
  // must have the same dimension everywhere).
  void follow(const ContactProblem &p, DistributedOps &ops);
  // The rows a kept correction moves (f(c) for each): they join the working set before the
  // start is moved, so that W^T A W over the set is the one the products were made for (a row
  // that left the set would otherwise count in A W and not in W: the predicted decrease of
  // phi was then wrong, and most moves were refused).
  template <class F>
  void rows_used(F &&f) const
  {
    if (w_.empty()) return;
    const size_t B = static_cast<size_t>(block_);
    const size_t nc = w_[0].size() / B;
    for (size_t c = 0; c < nc; ++c) {
      bool used = false;
      for (size_t a = 0; a < w_.size() && !used; ++a)
        for (size_t k = 0; k < B; ++k) used = used || w_[a][B * c + k] != 0.0;
      if (used) f(static_cast<int>(c));
    }
  }
  // After a solve: the correction d and its product ad (block per row, every row of p), the
  // newest first; at most `keep` are kept.
  void record(std::vector<double> d, std::vector<double> ad, const ContactProblem &p, int keep);
  // c minimising phi over mu + W c, from g = grad phi(mu) on the listed rows (sums over
  // counted rows, all processes). False if the corrections span nothing (c is then empty).
  bool coefficients(const ContactProblem &p, const std::vector<int> &rows,
                    const std::vector<double> &g, DistributedOps &ops, Eigen::VectorXd &c) const;
  // The start mu moved to the minimum of phi over mu + W c, each row's block then put back in
  // the law's set by project(c, m); regap(mu, g, u) makes u = u(mu) and g = grad phi on the
  // rows. The move is kept only if phi fell: phi(mu1) - phi(mu) = (mu1 - mu).(g + g1) / 2,
  // exact for a quadratic (the same linear term). Every sum is over counted rows and all
  // processes, so every process takes the same c and a row two processes hold the same
  // multipliers. Needs u = u(mu), g = grad phi(mu) on the rows; leaves them so.
  template <class Project, class Regap>
  void improve_start(const ContactProblem &p, const std::vector<int> &rows, DistributedOps &ops,
                     std::vector<double> &mu, std::vector<double> &g, std::vector<Vec3> &u,
                     Project &&project, Regap &&regap)
  {
    Eigen::VectorXd coef;
    if (!coefficients(p, rows, g, ops, coef)) return;
    const size_t B = static_cast<size_t>(block_);
    start_mu_ = mu;    // the way back
    start_g_ = g;
    start_u_ = u;
    for (const int c : rows) {
      double *m = &mu[B * c];
      for (size_t k = 0; k < B; ++k) m[k] = moved(m[k], coef, B * c + k);
      project(c, m);
    }
    regap(mu, g, u);
    double change = 0.0;
    for (const int c : rows) {
      if (!p.counted[c]) continue;
      for (size_t k = 0; k < B; ++k) {
        const size_t a = B * c + k;
        change += 0.5 * (mu[a] - start_mu_[a]) * (start_g_[a] + g[a]);
      }
    }
    if (ops.sum_all(change) < 0.0) {
      backoff_ = 0;
      return;
    }
    mu.swap(start_mu_);    // phi did not fall: the start as it came
    g.swap(start_g_);
    u.swap(start_u_);
    backoff_ = backoff_ == 0 ? 1 : std::min(2 * backoff_, kMaxSkip);
    skip_ = backoff_;
  }
  // m + (W c) at multiplier a (= block x row + component)
  double moved(double m, const Eigen::VectorXd &c, size_t a) const
  {
    for (size_t k = 0; k < w_.size(); ++k) m += c(static_cast<Eigen::Index>(k)) * w_[k][a];
    return m;
  }
  double memory_usage() const
  {
    return bytes_of(bodies_i_, bodies_j_, start_mu_, start_g_, start_u_) +
           (w_.empty() ? 0.0 : 2.0 * bytes_of(w_[0]) * static_cast<double>(w_.size()));
  }

 private:
  // eigenvalues of W^T A W below this x the largest: directions the corrections repeat
  static constexpr double kCut = 1e-12;
  static constexpr int kMaxSkip = 16;
  int backoff_ = 0;    // solves skipped after the last refused move (0: the last was kept)
  int skip_ = 0;       // solves still to skip
  bool trying_ = false;
  int block_;
  std::vector<std::vector<double>> w_, aw_;    // newest first
  std::vector<int> bodies_i_, bodies_j_;       // the rows they are stored on
  std::vector<double> start_mu_, start_g_;     // improve_start's scratch
  std::vector<Vec3> start_u_;
};

}    // namespace hardcontact
