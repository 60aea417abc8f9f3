// The paper's algorithm (section 3.3): projected gradient ascent on the dual of eq. 15.
#pragma once

#include "solver.h"

namespace hardcontact {

class Uzawa : public Solver {
 public:
  SolveReport solve(const ContactProblem &p, const SolverSettings &s, DistributedOps &ops,
                    std::vector<double> &mu, std::vector<Vec3> &u) override;

 private:
  std::vector<double> next_;    // kept between solves: no allocation per step
};

}    // namespace hardcontact
