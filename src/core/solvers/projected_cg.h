// Projected conjugate gradients on the dual of eq. 15 with the paper's law (frictionless):
// min phi(mu) = 1/2 mu.A mu + b.mu over mu >= 0, a quadratic with bounds. Jacobi-preconditioned
// CG runs on the free rows (a force > 0, or none yet but an overlap its force would open);
// a step that would take forces below 0 is projected instead (every row that reaches 0 on
// the way stops there at once) and the conjugate directions go on. In a pile whose contacts
// persist from step to step, warm-started, this is a linear solve on nearly the same rows,
// where CG removes the slow modes of the chains of contacts that a first-order method (Uzawa,
// apgd) pays for again every step.
//
// Why this form (measured on the resting 20-layer pile of bench/perf, apgd: 376 it/step): CG
// restarted at every row that reaches 0, as MPRGP (Dostal 2005) does, restarts every few
// iterations - a frictionless pile creeps, and hundreds of its weak contacts open or close
// in every step - 527 it/step; projected steps 354; keeping the conjugate direction across
// them 242; letting rows at 0 with an overlap join CG (no proportioning step) 200. An active
// set method (PDAS) cycled on the same pile.
//
// Every step decreases phi (a projected step is kept only when it decreases phi at least as
// much as the step to the first row's bound), and a direction that stops descending restarts
// CG from the preconditioned gradient: the method cannot diverge. Runs in the variables
// x = D^1/2 mu, D = diag(A) (Jacobi), so every row's scale is its own: a heavy sphere on light
// ones costs far less than with one global step (bench/perf's tray at mass ratio 1000: 33
// it/step against apgd's 509 from the same state).
#pragma once

#include "../laws/normal.h"
#include "iterative_solver.h"
#include "past_corrections.h"

namespace hardcontact {

class ProjectedCg : public IterativeSolver<NormalLaw> {
 protected:
  void start(const SolverSettings &s, std::vector<double> &mu, std::vector<Vec3> &u) override;
  bool step(const SolverSettings &s, std::vector<double> &mu, std::vector<Vec3> &u) override;
  void grown(const SolverSettings &s, std::vector<double> &mu, std::vector<Vec3> &u) override;
  void finished(const SolverSettings &s, const std::vector<double> &mu,
                const std::vector<Vec3> &u) override;
  // residual_, reduced by the last refresh together with gamma's numerator
  double residual_all(const std::vector<double> &mu, const std::vector<Vec3> &u) override;

 public:
  double memory_usage() const override
  {
    return IterativeSolver<NormalLaw>::memory_usage() +
           bytes_of(inv_d_, dir_, q_, w_, moved_, clipped_, clip_, wc_, touched_, near_, qc_,
                    near_mark_, body_mark_, row_start_, row_list_, warm_) +
           past_.memory_usage();
  }

 private:
  // A row CG moves: it pushes, or it overlaps and may start to.
  bool free(int c, const std::vector<double> &mu) const { return mu[c] > 0.0 || g_[c] < 0.0; }
  // dir_ on the free rows (D^-1 g - gamma dir), w_ its velocity change, q_ = A dir_;
  // sums_ = g.dir, dir.A dir (counted rows, all processes); returns the largest dir / mu
  // (the inverse of the step at which the first force reaches 0), all processes: the sums
  // and the maximum in one reduction.
  double product(const std::vector<double> &mu, double gamma);
  // mu -= a dir_, g -= a q_, u -= a w_ (ghosts included: w_ was forwarded).
  void move(double a, std::vector<double> &mu, std::vector<Vec3> &u);
  void move_and_refresh(double a, std::vector<double> &mu, std::vector<Vec3> &u);
  // one row of move(), and its bodies' part (u -= a w_, ghosts included)
  void move_row(int c, double a, std::vector<double> &mu)
  {
    mu[c] -= a * dir_[c];
    g_[c] -= a * q_[c];
  }
  void move_bodies(double a, std::vector<Vec3> &u) const;
  // The projected step mu <- max(0, mu - a dir_): the clipped rows' correction, its velocity
  // change and gaps computed sparsely (only the rows that share a body with a clipped row).
  // Taken if it lowers phi at least by `floor` (the decrease of the step to the bound);
  // returns whether it was.
  bool projected_step(double a, double floor, std::vector<double> &mu, std::vector<Vec3> &u);
  // After mu changed: residual_ and gamma's numerator (D^-1 g_new).A dir over free rows,
  // both over all processes in one reduction.
  void refresh(const std::vector<double> &mu);
  // the same with each row first updated by update(c) (a move fused into the pass)
  template <class Update>
  void refresh_with(const std::vector<double> &mu, Update &&update);
  // Rows per body over the working set (CSR), for the sparse correction; moved_ from it.
  void index_rows();

  std::vector<double> inv_d_;  // 1 / diag(A) per row (1 for a row no body can move)
  std::vector<double> dir_;    // CG direction in mu's variables (D^-1/2 p, p in x)
  std::vector<double> q_;      // A dir_
  std::vector<Vec3> w_;        // the velocity change of dir_
  std::vector<int> moved_;     // owned bodies with rows in the set: where w_ can be nonzero
  // sparse correction of a projected step
  std::vector<int> clipped_;             // rows clipped (local)
  std::vector<double> clip_;             // per row: the force given back (0 elsewhere)
  std::vector<Vec3> wc_;                 // its velocity change (0 outside touched_)
  std::vector<int> touched_;             // bodies wc_ is nonzero on
  std::vector<int> near_;                // rows sharing a body with a clipped row
  std::vector<double> qc_;               // A clip_ on near_ rows (per row, 0 elsewhere)
  std::vector<char> near_mark_;
  std::vector<char> body_mark_;          // per owned body: already in touched_
  std::vector<int> row_start_, row_list_;    // rows of body b: row_list_[row_start_[b]..+1)
  // Past corrections (subspace start, SolverSettings::subspace), with their products A w
  // (set rows of the step that made them)
  PastCorrections past_{1};
  std::vector<double> warm_;            // the start this solve received
  double sums_[2] = {0.0, 0.0};
  double residual_ = 0.0, gamma_num_ = 0.0, pq_ = 0.0;
  bool cg_ = false;    // dir_ continues a conjugate sequence
};

}    // namespace hardcontact
