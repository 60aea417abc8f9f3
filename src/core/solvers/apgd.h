// Accelerated projected gradient on the dual of eq. 15 (Nesterov / FISTA), with gradient
// restart (O'Donoghue & Candes 2015) and backtracking on the Lipschitz estimate L, over the
// same working set as Uzawa. It needs no step bound from the user and converges in about
// sqrt(cond) iterations instead of cond for Uzawa.
#pragma once

#include "../laws/law_list.h"
#include "iterative_solver.h"
#include "past_corrections.h"

namespace hardcontact {

template <class Law>
class ApgdSolver : public IterativeSolver<Law> {
 protected:
  void start(const SolverSettings &s, std::vector<double> &mu, std::vector<Vec3> &u) override;
  bool step(const SolverSettings &s, std::vector<double> &mu, std::vector<Vec3> &u) override;
  void grown(const SolverSettings &s, std::vector<double> &mu, std::vector<Vec3> &u) override;
  double set_residual(const std::vector<double> &mu, const std::vector<Vec3> &u) override;
  void shifted(const SolverSettings &s, std::vector<double> &mu, std::vector<Vec3> &u) override;
  void finished(const SolverSettings &s, const std::vector<double> &mu,
                const std::vector<Vec3> &u) override;

 public:
  double memory_usage() const override
  {
    return IterativeSolver<Law>::memory_usage() +
           bytes_of(d_, sd_, isd_, kd_, b_, y_, gy_, next_, gnext_, warm_, scratch_u_) +
           past_.memory_usage();
  }

 protected:

 private:
  // g(m) on the working set, leaving u = u(m)
  void gaps(const std::vector<double> &m, std::vector<double> &g, std::vector<Vec3> &u);
  void restart(const std::vector<double> &mu);
  double L_ = 0.0;        // Lipschitz estimate of grad phi (friction: in x = D^1/2 mu)
  // The reported step: 1/L, with friction that of the stiffest component, 1 / (L max D)
  double report_rho() const
  {
    const double l = B == 1 ? L_ : L_ * dmax_;
    return l > 0.0 ? 1.0 / l : 0.0;
  }
  double theta_ = 1.0;    // Nesterov's sequence
  double residual_ = 0.0;          // the set's residual at the iterate, from step()'s last pass
  bool residual_ready_ = false;
  // per row, kept between solves: no allocation per step (g(mu) is the base's g_)
  using IterativeSolver<Law>::B;
  // b + the shift (friction) of row c's normal component
  double linear(int c, int k) const;

  // Friction (B > 1): the diagonal preconditioner D = diag(A_cc) per component (d_) and its
  // square root (sd_), and each row's law coefficients in the variables x = D^1/2 mu (kd_).
  void precondition(const SolverSettings &s);
  std::vector<double> d_, sd_, isd_;    // D, D^1/2, D^-1/2
  std::vector<Coefficients> kd_;
  double dmax_ = 0.0;
  std::vector<double> b_;       // g at mu = 0 without shifts: the linear term of the dual
  std::vector<double> y_;       // extrapolated point
  std::vector<double> gy_;      // g at y (g is affine in mu, so no extra product)
  std::vector<double> next_;    // trial point
  std::vector<double> gnext_;
  // subspace start: the corrections, the start this solve received (and the scratch of a
  // correction's product)
  PastCorrections past_{B};
  std::vector<double> warm_;
  std::vector<Vec3> scratch_u_;
};

HARDCONTACT_SOLVER_ALIASES(Apgd, ApgdSolver)

}    // namespace hardcontact
