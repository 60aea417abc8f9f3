// Projected Gauss-Seidel on the dual of eq. 15: one row at a time, the exact minimisation
// along it; each iteration is one sweep of block_sweep.h over the working set, which makes it
// consistent under domain decomposition (a block-Jacobi split at the process boundary).
#pragma once

#include "../laws/law_list.h"
#include "block_sweep.h"
#include "iterative_solver.h"

namespace hardcontact {

template <class Law>
class PgsSolver : public IterativeSolver<Law> {
 protected:
  using IterativeSolver<Law>::B;
  // row degrees for the Gershgorin step of the boundary rows
  void rows_changed(const SolverSettings &) override { this->op_.count_degrees(this->set_.rows()); }
  bool step(const SolverSettings &s, std::vector<double> &mu, std::vector<Vec3> &u) override;

 public:
  double memory_usage() const override
  {
    return IterativeSolver<Law>::memory_usage() + bytes_of(dmu_);
  }

 private:
  std::vector<double> dmu_;    // boundary-row steps of one sweep, kept between solves
};

HARDCONTACT_SOLVER_ALIASES(Pgs, PgsSolver)

}    // namespace hardcontact
