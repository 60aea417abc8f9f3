// The frictional default: nonsmooth Gauss-Seidel sweeps from the warm start, and accelerated
// projected gradient from where they stop if they do not converge within a few sweeps.
//
// Why two methods (measured, bench/studies/friction_hybrid 12): once friction has been mobilised
// (a bed that slid to rest, a pile that settled, a bed dragged by a moving wall), a frictional
// packing at rest holds tangential forces on or near the cones' edges. From the warm start such
// a problem is a few tolerances off, and apgd - one global step, the cones' edges seen only
// through projections - takes hundreds to thousands of iterations per step to close that gap
// (and at tol 1e-2 it leaves the bed agitated); nsgs solves each contact's law exactly and
// takes 0-15 sweeps. While the packing moves (a bed sliding on a floor, a flowing layer),
// nsgs stalls and apgd converges. So each solve first tries nsgs for at most kSweeps sweeps;
// if they do not reach the tolerance, apgd goes on from their iterate with the rest of the
// budget. A try that fails makes the next 1, 2, 4, ... kMaxBackoff (64) solves skip it (a
// converged one tries again at once), so a flowing scene pays little for the tries.
#pragma once

#include "../laws/law_list.h"
#include "apgd.h"
#include "nsgs.h"

namespace hardcontact {

template <class Law>
class HybridSolver : public Solver {
 public:
  SolveReport solve(const ContactProblem &p, const SolverSettings &s, DistributedOps &ops,
                    std::vector<double> &mu, std::vector<Vec3> &u) override;
  // the back-off (restart files)
  void save_state(double *state) const override
  {
    state[0] = skip_;
    state[1] = backoff_;
  }
  void load_state(const double *state) override
  {
    skip_ = static_cast<int>(state[0]);
    backoff_ = state[1] >= 1.0 ? static_cast<int>(state[1]) : 1;
  }
  double memory_usage() const override
  {
    return sweeps_.memory_usage() + gradient_.memory_usage() + bytes_of(warm_);
  }

  // Sweeps of one try: a packing at rest converges in 0-15 (measured); a try that fails costs
  // its sweeps (in the drum, where contacts through the periodic axis are swept Jacobi-wise,
  // 30 sweeps and a back-off to 16 cost 24 % of the time, 15 and 64 nothing measurable).
  static constexpr int kSweeps = 15;
  static constexpr int kMaxBackoff = 64;

 private:
  NsgsSolver<Law> sweeps_;
  ApgdSolver<Law> gradient_;
  std::vector<double> warm_;    // the lagged cone: the warm start of a try
  int skip_ = 0;       // solves left to run without a try
  int backoff_ = 1;    // solves to skip after the next failed try
};

HARDCONTACT_SOLVER_ALIASES(Hybrid, HybridSolver)

}    // namespace hardcontact
