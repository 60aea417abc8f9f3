// The paper's algorithm (section 3.3): projected gradient ascent on the dual of eq. 15,
// iterating on a working set of rows (Remark 7, working_set.h).
#pragma once

#include "solver.h"
#include "working_set.h"

namespace hardcontact {

class Uzawa : public Solver {
 public:
  SolveReport solve(const ContactProblem &p, const SolverSettings &s, DistributedOps &ops,
                    std::vector<double> &mu, std::vector<Vec3> &u) override;

 private:
  WorkingSet set_;
  std::vector<double> next_;    // kept between solves: no allocation per step
};

}    // namespace hardcontact
