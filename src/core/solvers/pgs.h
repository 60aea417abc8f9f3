// Projected Gauss-Seidel on the dual of eq. 15 (one row at a time, exact minimisation along
// it), made consistent under domain decomposition by a block-Jacobi split:
// - rows whose two bodies are owned here are swept Gauss-Seidel, each seeing the impulses of
//   the rows before it;
// - rows coupling an owned body with a ghost (held by both processes) are updated first in each
//   sweep, all at once from the velocities of the last exchange, with the Gershgorin step of
//   their row (dual_operator.h), so both processes compute the same multiplier and apply their
//   half of the same impulse: momentum stays exact. The simultaneous step is a descent step
//   because that row sum bounds the row of the dual operator.
// Each sweep decreases the dual objective; ghost velocities are refreshed after each sweep.
#pragma once

#include "../laws/coulomb.h"
#include "../laws/normal.h"
#include "../laws/rolling.h"
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

using Pgs = PgsSolver<NormalLaw>;
using PgsFriction = PgsSolver<CoulombLaw>;
using PgsRolling = PgsSolver<RollingLaw>;

}    // namespace hardcontact
