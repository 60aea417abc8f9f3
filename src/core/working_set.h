// Remark 7 inside the solver: the rows a solver iterates on. Most candidate rows never touch
// within the step; iterating on them costs time and, through the step bound, convergence speed.
// The working set starts with the rows that can close at the free relative speed and grows
// whenever the current iterate violates a row outside it. Rows outside hold mu = 0, so a solve
// that converges with no violation outside has solved eq. 15 for every candidate row.
#pragma once

#include "contact_problem.h"
#include "distributed_ops.h"

#include <vector>

namespace hardcontact {

class WorkingSet {
 public:
  enum class Verdict { Iterate, Grown, Converged };

  // The stopping test every solver shares, given the residual of the set at iteration k: at
  // iterations 1, 2, 4, ..., then every 64, and whenever the set itself has converged, rows
  // outside that the iterate violates join the set (Grown: the solver adapts and goes on).
  // Converged: residual <= tol and nothing violated outside, i.e. eq. 15 holds everywhere.
  Verdict check(int k, double residual, double tol, const ContactProblem &p,
                const std::vector<Vec3> &u, DistributedOps &ops);

  // Rows with a start multiplier > 0, or whose gap the free relative speed closes in one step.
  void init(const ContactProblem &p, const std::vector<double> &mu);
  // Adds the rows outside the set that u violates by more than tol; returns how many (local).
  int expand(const ContactProblem &p, const std::vector<Vec3> &u, double tol);

  const std::vector<int> &rows() const { return rows_; }
  bool contains(int c) const { return member_[c] != 0; }

 private:
  std::vector<int> rows_;
  std::vector<char> member_;
  int next_check_ = 1;
};

}    // namespace hardcontact
