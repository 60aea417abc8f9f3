// The paper's algorithm (section 3.3): projected gradient ascent on the dual of eq. 15,
// iterating on a working set of rows (Remark 7, working_set.h).
#pragma once

#include "../laws/law_list.h"
#include "iterative_solver.h"

namespace hardcontact {

template <class Law>
class UzawaSolver : public IterativeSolver<Law> {
 protected:
  using IterativeSolver<Law>::B;
  // rho from the Gershgorin bound of the working set (or the user's)
  void rows_changed(const SolverSettings &s) override;
  bool step(const SolverSettings &s, std::vector<double> &mu, std::vector<Vec3> &u) override;
};

HARDCONTACT_SOLVER_ALIASES(Uzawa, UzawaSolver)

}    // namespace hardcontact
