// Frictionless rows that pushed in the last step keep a shallow overlap instead of clearing it,
// while that keeps every solve short; the paper's clearing comes back for a step, and for the
// steps after it, when it does not (bench/studies/kept_overlaps 10.8).
//
// Why: at rest a solve leaves gaps within tol s of 0 (residual.h), and clearing asks the next
// step to undo them. Its warm start is then a few tol away (section 10.2), and a frictionless
// pile, whose forces are ill-determined (10.1), pays hundreds of iterations every step for an
// error it made itself. A row whose warm-start force is > 0 and whose overlap is at most
// kKeptOverlap tol size (targets.cpp, as with friction) therefore gets the target 0: it may not
// deepen, it need not clear (Targets::apply counts the raised rows here).
//
// Raising targets never makes eq. 15 infeasible (the cleared targets' solution still
// satisfies it), but in a tight redundant loop (a row of spheres from wall to wall, a crystal)
// the raised rows leave slack that some row of the loop must take up: the solution is then
// nearly degenerate, and solvers stall on it (10.7: the crystals of the stability suite).
// Cleared targets are the gaps of one configuration and have no such slack. So a solve with
// kept overlaps gets a budget of iterations (budget()); a solve that stops at it is continued,
// from its multipliers, with the cleared targets of the paper (undo()), and the next 1, 2, 4,
// ... 256 steps clear from the start (begin_step()).
//
// The budget follows what clearing costs: kBudgetFactor times the iterations of the recent steps
// solved with the paper's targets from the start (cleared()), at least kMinBudget, at most
// maxiter / kBudgetDivisor (the only bound before such a step). A stalled solve is then given
// up after a few times what clearing would have cost, not after a tenth of maxiter: on the 2D
// crystal of the accuracy report (cleared steps 20-60 iterations) a fixed budget of 1000 was
// spent 4 times in 60 steps (bench/studies/kept_overlaps 10.10). Where keeping pays (a pile at rest:
// 19 against 195 per step) the budget is far above what a kept solve takes.
#pragma once

#include <algorithm>

namespace hardcontact {

class KeptOverlaps {
 public:
  // Solves with kept overlaps stop after maxiter / kBudgetDivisor iterations (at least 1), or
  // earlier: kBudgetFactor x what recent cleared steps took (cleared()), at least kMinBudget.
  static constexpr int kBudgetDivisor = 10;
  static constexpr int kBudgetFactor = 4;
  static constexpr int kMinBudget = 50;
  // The longest run of steps that clear after a solve stopped at its budget.
  static constexpr int kMaxBackoff = 256;

  // A new step: forgets the last step's rows; true when this step may keep overlaps (not
  // within a back-off). The same on every process: it depends only on global verdicts.
  bool begin_step();
  // Whether the rows being targeted now may keep their overlaps (this step, before undo()).
  bool active() const { return active_; }
  // A row's target raised above the paper's (Targets::apply).
  void raised() { ++raised_; }
  int budget(int maxiter) const;
  // A step that could have kept overlaps was solved with the paper's targets from the start (a
  // back-off, or no row to keep) in `iterations` (the same on every process): what clearing
  // costs now, the measure of the next budgets. One step solved in 0 iterations says little of
  // the next, so the measure is the largest recent count, halved at each step that took fewer.
  void cleared(int iterations)
  {
    cleared_iterations_ = std::max(iterations, cleared_iterations_ / 2);
  }
  // The solve stopped at its budget: keeping ends for this step (the caller writes every
  // row's target again, Targets::apply from row 0: the paper's, since the gaps beside them
  // are as measured), rows targeted later this step clear, and the next steps clear
  // (back-off, doubled each time).
  void undo();
  // Solves that stopped at their budget and went on with cleared targets, since the start.
  long undone() const { return undone_; }
  // What decides the coming steps (the back-off under way, its next length, the budget's
  // measure), as kStateSize doubles for a host's restart file: a run split by write_restart /
  // read_restart then keeps and clears in the same steps as the unsplit run. undone() is not
  // part of it (it counts since the fix was defined). load_state() clamps to valid values.
  static constexpr int kStateSize = 3;
  void save_state(double *out) const;
  void load_state(const double *in);
  int rows_raised() const { return raised_; }

 private:
  int raised_ = 0;
  bool active_ = false;
  int skip_ = 0;       // steps still to clear from the start
  int backoff_ = 1;    // the next back-off's length
  long undone_ = 0;
  int cleared_iterations_ = -1;    // what recent cleared steps took (cleared()); -1: none yet
};

}    // namespace hardcontact
