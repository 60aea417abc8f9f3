// A direct solver to machine precision, for validation and small scenes: the active-set method
// of Lawson and Hanson on the dual of eq. 15, min 1/2 mu.A mu + b.mu over mu >= 0, each
// subproblem solved with Eigen's sparse LDL^T of the assembled A = h^2 G M^-1 G^T (slightly
// regularised: redundant contacts make A singular, Lemma 1). One process only: assembling A
// needs every body's rows (ghosts must be images of owned bodies, ContactProblem::owner).
#pragma once

#include "../solver.h"

namespace hardcontact {

class Exact : public Solver {
 public:
  SolverTraits traits() const override { return {false, true, false}; }
  SolveReport solve(const ContactProblem &p, const SolverSettings &s, DistributedOps &ops,
                    std::vector<double> &mu, std::vector<Vec3> &u) override;
};

}    // namespace hardcontact
