// Remark 7 inside the solver: the rows a solver iterates on. Most candidate rows never touch
// within the step; iterating on them costs time and, through the step bound, convergence speed.
// The working set starts with the rows that can close at the free relative speed and grows
// whenever the current iterate violates a row outside it. Rows outside hold mu = 0, so a solve
// that converges with no violation outside has solved eq. 15 for every candidate row.
#pragma once

#include "contact_problem.h"

#include <vector>

namespace hardcontact {

class WorkingSet {
 public:
  // Rows with a start multiplier > 0, or whose gap the free relative speed closes in one step.
  void init(const ContactProblem &p, const std::vector<double> &mu);
  // Adds the rows outside the set that u violates by more than tol; returns how many (local).
  int expand(const ContactProblem &p, const std::vector<Vec3> &u, double tol);

  const std::vector<int> &rows() const { return rows_; }
  bool contains(int c) const { return member_[c] != 0; }

 private:
  std::vector<int> rows_;
  std::vector<char> member_;
};

}    // namespace hardcontact
