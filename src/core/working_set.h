// Remark 7 inside the solver: the rows a solver iterates on. Most candidate rows never touch
// within the step; iterating on them costs time and, through the step bound, convergence speed.
// The working set starts with the rows that can close at the free relative speed and grows
// whenever the current iterate violates a row outside it. Rows outside hold mu = 0, so a solve
// that converges with no violation outside has solved eq. 15 for every candidate row.
#pragma once

#include "contact_problem.h"
#include "distributed_ops.h"
#include "container_bytes.h"
#include "residual.h"

#include <vector>

namespace hardcontact {

// Law: the contact law of the rows (laws/normal.h): its violation measure.
template <class Law>
class WorkingSet {
 public:
  enum class Verdict { Iterate, Grown, Converged };

  // The stopping test every solver shares, given the residual of the set at iteration k
  // (largest violation() over the set): at iterations 1, 2, 4, ..., then every 64, and
  // whenever the set itself has converged, rows outside that the iterate violates join the set
  // (Grown: the solver adapts and goes on). Converged: residual <= tol, nothing violated
  // outside, i.e. eq. 15 holds everywhere to tol, and no kinetic energy gained beyond what
  // the exact projection may gain (energy_within_bound, Prop. 3).
  Verdict check(int k, double residual, double tol, const ContactProblem &p,
                const std::vector<double> &mu, const std::vector<Vec3> &u, DistributedOps &ops);

  // Rows with a start multiplier > 0, or whose gap the free relative speed closes in one step;
  // and the tolerance scales of every row (residual.h: its gap conditions', and with friction
  // its slip conditions').
  void init(const ContactProblem &p, const std::vector<double> &mu, double tol,
            DistributedOps &ops);
  // Adds the rows outside the set that u violates by more than tol (predicted overlap: a row
  // without force has no other condition once friction's shift is at its fixed point);
  // returns how many (local).
  int expand(const ContactProblem &p, const std::vector<Vec3> &u, double tol);

  // Row c joins the set (at its multiplier; a row in the set may hold 0)
  void include(int c)
  {
    if (member_[c]) return;
    rows_.push_back(c);
    member_[c] = 1;
  }
  const std::vector<int> &rows() const { return rows_; }
  bool contains(int c) const { return member_[c] != 0; }
  // Row c's violation in units of its scale, the quantity compared with tol (g, m: the row's
  // Law::block components, k: its coefficients).
  double violation(int c, const double *g, const double *m, const Coefficients &k) const
  {
    if constexpr (Law::block > 1) {
      double unused;
      return Law::violation(g, m, k, scale_[c], slip_scale_[c], unused, -1.0);
    } else {
      return Law::violation(g, m, k, scale_[c]);
    }
  }
  // The same for a largest violation over rows (friction: it may return floor when at most
  // floor, laws/coulomb.h), also giving Law::shift(g, k), computed with it at no extra cost
  // (the normal law has no shift).
  double violation(int c, const double *g, const double *m, const Coefficients &k,
                   double &shift, double floor) const
  {
    if constexpr (Law::block > 1) {
      return Law::violation(g, m, k, scale_[c], slip_scale_[c], shift, floor);
    } else {
      shift = 0.0;
      return Law::violation(g, m, k, scale_[c]);
    }
  }
  double scale(int c) const { return scale_[c]; }
  double memory_usage() const { return bytes_of(rows_, member_, scale_, slip_scale_); }
  const std::vector<double> &scales() const { return scale_; }
  double speed_scale() const { return speed_scale_; }

 private:
  std::vector<int> rows_;
  std::vector<char> member_;
  std::vector<double> scale_;
  std::vector<double> slip_scale_;    // friction: the slip conditions' (init)
  double speed_scale_ = 0.0;
  int next_check_ = 1;
};

}    // namespace hardcontact
