// Accelerated projected gradient on the dual of eq. 15 (Nesterov / FISTA), with gradient
// restart (O'Donoghue & Candes 2015) and backtracking on the Lipschitz estimate L, over the
// same working set as Uzawa. It needs no step bound from the user and converges in about
// sqrt(cond) iterations instead of cond for Uzawa.
#pragma once

#include "solver.h"
#include "working_set.h"

namespace hardcontact {

class Apgd : public Solver {
 public:
  SolveReport solve(const ContactProblem &p, const SolverSettings &s, DistributedOps &ops,
                    std::vector<double> &mu, std::vector<Vec3> &u) override;

 private:
  WorkingSet set_;
  // per row, kept between solves: no allocation per step
  std::vector<double> b_;       // g at mu = 0: the linear term of the dual
  std::vector<double> g_;       // g at mu
  std::vector<double> y_;       // extrapolated point
  std::vector<double> gy_;      // g at y (g is affine in mu, so no extra product)
  std::vector<double> next_;    // trial point
  std::vector<double> gnext_;
};

}    // namespace hardcontact
