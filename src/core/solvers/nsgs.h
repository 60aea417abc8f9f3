// Nonsmooth (block) Gauss-Seidel on the frictional contact problem: each contact in turn takes
// the exact solution of its own law with the other contacts held (Law::local_solve), in a
// fixed order that runs forward and backward on alternate sweeps (a symmetric sweep: under
// gravity the rows come roughly bottom-up in the host's order, so one direction carries the
// weight down the pile and the other the reaction back up).
//
// Why it is the frictional solver: the local solve of Coulomb's law is exact and closed-form
// (a sphere contact's block of A is diagonal), so it solves the true law - no convex relaxation
// and no De Saxce shift to bring to a fixed point by an outer loop, which is where the
// projected-gradient solvers spent most of their iterations (bench/studies/friction_deep, friction_rest).
// The literature's comparison of frictional solvers on rigid granular sets (Acary, Bremond &
// Huber 2018) found this family the most efficient and robust (../shared/FRICTION_SOLVERS.md).
//
// Under domain decomposition the sweep splits as pgs's (block_sweep.h): rows shared with
// another process are updated first, all at once, from the gaps of the last exchange and with
// a Gershgorin diagonal (a damped local solve both processes compute alike: momentum stays
// exact); the owned rows are then swept Gauss-Seidel.
#pragma once

#include "../laws/law_list.h"
#include "iterative_solver.h"

namespace hardcontact {

template <class Law>
class NsgsSolver : public IterativeSolver<Law> {
 public:
  double memory_usage() const override
  {
    return IterativeSolver<Law>::memory_usage() + bytes_of(diag_, dmu_, shared_);
  }

 protected:
  using IterativeSolver<Law>::B;
  // Every solve starts with a forward sweep: the solve depends on nothing but its problem and
  // start (a run split by a restart file solves as the unsplit one).
  void start(const SolverSettings &s, std::vector<double> &mu, std::vector<Vec3> &u) override
  {
    sweeps_ = 0;
    IterativeSolver<Law>::start(s, mu, u);
  }
  void rows_changed(const SolverSettings &) override;
  bool step(const SolverSettings &s, std::vector<double> &mu, std::vector<Vec3> &u) override;
  // The residual of the true law: each row's shift is set to Law::shift of its iterate, so the
  // base's fixed point of the shifts is always met (drift 0) and the test measures Coulomb's
  // law itself (laws/coulomb.h: with the shift at its value, the violation is that of g_n = 0
  // for a pushing contact, g_n >= 0 for a free one).
  double set_residual(const std::vector<double> &mu, const std::vector<Vec3> &u) override;
  // No fixed point of the shifts: set_residual() gives each row Law::shift of its iterate, the
  // shift of Coulomb's law, which the sweeps solve under every cone; the start shifts and the
  // lagged cone's caps (IterativeSolver) are the projected-gradient solvers' relaxation.
  // Measured against those caps, a row whose slip grew beyond its cap drifted by 3 tol for
  // ever, every check moved the shifts back instead of sweeping, and the solve froze with its
  // residual at 3 tol until maxiter (a creeping 8000-sphere pile: 3000 sweeps at a constant
  // 0.027-0.030 against tol 0.01, against 23-85 once the sweeps run; bench/friction/README.md,
  // "nsgs froze under the lagged cone").
  bool moves_shifts() const override { return false; }

 private:
  // The row's own gradient without the shift (the local solve needs none).
  void true_gradient(int c, const std::vector<Vec3> &u, double *g) const;
  void local(int c, std::vector<double> &mu, std::vector<Vec3> &u);
  // The local solve of this solve's cone: Coulomb's law itself (Lagged, Exact: the sweeps need
  // no shift), or the unshifted cone's (Convex).
  void local_law(double *m, const double *g, const double *d, const Coefficients &k) const
  {
    if constexpr (B > 1) {
      if (this->cone_ == SolverSettings::Cone::Convex) return Law::local_solve_convex(m, g, d, k);
    }
    Law::local_solve(m, g, d, k);
  }
  std::vector<double> diag_;      // per row, B entries: the local solve's diagonal
  std::vector<double> dmu_;       // shared rows' steps of one sweep
  std::vector<int> shared_;       // rows of the set coupling an owned body with a ghost
  std::vector<int> own_;          // the other rows of the set, in sweep order
  int sweeps_ = 0;
};

HARDCONTACT_SOLVER_ALIASES(Nsgs, NsgsSolver)

}    // namespace hardcontact
