// What every iterative solver of the dual of eq. 15 shares, so that each solver file holds only
// its algorithm box: the prologue (start multipliers projected onto the law, operator bound,
// working set of Remark 7), the loop of verdicts of the shared stopping test (working_set.h),
// and the epilogue (an unconverged answer reports its violation over every row). Virtual calls
// happen once per iteration, never per contact.
#pragma once

#include "../dual_operator.h"
#include "../residual.h"
#include "../solver.h"
#include "../working_set.h"

#include <vector>

namespace hardcontact {

template <class Law>
class IterativeSolver : public Solver {
 public:
  SolveReport solve(const ContactProblem &p, const SolverSettings &s, DistributedOps &ops,
                    std::vector<double> &mu, std::vector<Vec3> &u) final
  {
    const int nc = p.n_contacts();
    mu.resize(nc, 0.0);
    for (double &m : mu) m = Law::project(m);    // a start outside the law is no contact force
    g_.resize(nc);
    op_.bind(p, ops);
    set_.init(p, mu, s.tol, ops);
    start(s, mu, u);

    SolveReport report;
    for (int k = 0;; ++k) {
      report.iterations = k;
      report.residual = ops.max_all(set_residual(mu, u));
      const auto verdict = set_.check(k, report.residual, s.tol, p, mu, u, ops);
      if (verdict == Verdict::Converged) {
        report.converged = true;
        break;
      }
      if (verdict == Verdict::Grown) grown(s, mu, u);
      if (k >= s.maxiter) break;
      if (verdict == Verdict::Grown) continue;
      if (!step(s, mu, u)) break;    // the method broke down: report the iterate
    }
    report.rho = rho_;
    if (!report.converged) report.residual = residual<Law>(p, mu, u, set_.scales(), ops);
    report.speed_scale = set_.speed_scale();
    return report;
  }

 protected:
  using Verdict = typename WorkingSet<Law>::Verdict;

  // Once per solve, after the working set is made: u = u(mu), and the solver's own state.
  virtual void start(const SolverSettings &s, std::vector<double> &mu, std::vector<Vec3> &u)
  {
    op_.velocities(set_.rows(), mu, u);
    rows_changed(s);
  }
  // One iteration from (mu, u = u(mu)) to the next; false if the method broke down.
  virtual bool step(const SolverSettings &s, std::vector<double> &mu, std::vector<Vec3> &u) = 0;
  // Rows joined the working set (at mu = 0; u unchanged).
  virtual void grown(const SolverSettings &s, std::vector<double> &, std::vector<Vec3> &)
  {
    rows_changed(s);
  }
  // The working set is new or larger: what depends on its rows (step bounds) is out of date.
  virtual void rows_changed(const SolverSettings &) {}
  // This process's largest violation over the working set at (mu, u); by default from the
  // gaps of u, which it leaves in g_ for the next step.
  virtual double set_residual(const std::vector<double> &mu, const std::vector<Vec3> &u)
  {
    double r = 0.0;
    for (const int c : set_.rows()) {
      g_[c] = op_.gap(c, u);
      const double v = set_.violation(c, g_[c], mu[c]);
      r = r > v ? r : v;
    }
    return r;
  }

  DualOperator op_;
  WorkingSet<Law> set_;
  std::vector<double> g_;    // g(mu) on the working set; kept between solves (no allocation)
  double rho_ = 0.0;         // the step the method used, reported (0: none)
};

}    // namespace hardcontact
