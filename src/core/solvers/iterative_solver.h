// What every iterative solver of the dual of eq. 15 shares, so that each solver file holds only
// its algorithm box: the prologue (start multipliers projected onto the law, operator bound,
// working set of Remark 7), the loop of verdicts of the shared stopping test (working_set.h),
// and the epilogue (an unconverged answer reports its violation over every row). Virtual calls
// happen once per iteration, never per contact.
#pragma once

#include "../dual_operator.h"
#include "../problem_dump.h"
#include "../residual.h"
#include "../solver.h"
#include "../working_set.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace hardcontact {

template <class Law>
class IterativeSolver : public Solver {
 public:
  // the scratch every solver of this base keeps; a solver adds its own arrays
  double memory_usage() const override
  {
    return bytes_of(shift_, shift_delta_, g_, law_shift_, cap_, warm_) + op_.memory_usage() +
           set_.memory_usage();
  }

  SolveReport solve(const ContactProblem &p, const SolverSettings &s, DistributedOps &ops,
                    std::vector<double> &mu, std::vector<Vec3> &u) final
  {
    const int nc = p.n_contacts();
    mu.resize(static_cast<size_t>(B) * nc, 0.0);
    for (int c = 0; c < nc; ++c) Law::project(&mu[static_cast<size_t>(B) * c], coef(p, c));
    g_.resize(static_cast<size_t>(B) * nc);
    if constexpr (B > 1) {
      law_shift_.resize(nc);
      shift_.assign(nc, 0.0);
    }
    op_.bind(p, ops);
    set_.init(p, mu, s.tol, ops);
    bool dump_failed = false;    // developers' dump (problem_dump.h): the law of eq. 15 only
    if constexpr (B == 1) {
      if (!s.dump_problem.empty())
        dump_failed = !write_problem(s.dump_problem, p, set_.scales(), mu, s.tol);
    }
    if constexpr (B > 1) {
      cone_ = s.cone;
      tol_ = s.tol;
      downward_ = false;
      // Cone::Lagged: each row that pushed at the step's warm start caps its shift at its
      // value there: from mu, in start_shifts' pass, or from lag_from()'s warm start when mu
      // is not it (one more product)
      cap_.assign(nc, std::numeric_limits<double>::infinity());
      const bool lagged = cone_ == SolverSettings::Cone::Lagged && moves_shifts();
      if (lagged && given_warm_) {    // the warm start as this solve's mu was made from it
        warm_.resize(static_cast<size_t>(B) * nc, 0.0);
        for (int c = 0; c < nc; ++c) Law::project(&warm_[static_cast<size_t>(B) * c], coef(p, c));
        op_.template velocities<Law>(set_.rows(), warm_, u);
        double g[B];
        for (const int c : set_.rows()) {
          if (!(warm_[static_cast<size_t>(B) * c] > 0.0)) continue;
          op_.template gap_block<Law>(c, u, g);
          cap_[c] = Law::shift(g, coef(c));
        }
      }
      if (moves_shifts()) start_shifts(mu, u, lagged && !given_warm_);
      given_warm_ = false;
      best_drift_ = 1e300;
      stalled_ = 0;
    }
    start(s, mu, u);

    SolveReport report;
    report.dump_failed = dump_failed;
    for (int k = 0;; ++k) {
      report.iterations = k;
      [[maybe_unused]] double drift = 0.0;    // friction: how far the shifts are from Law::shift of the iterate
      if constexpr (B == 1) {
        report.residual = residual_all(mu, u);
      } else {
        // the residual and the drift (which reads the law_shift_ set_residual leaves) in one
        // reduction
        double worst[2] = {set_residual(mu, u), 0.0};
        worst[1] = cone_ == SolverSettings::Cone::Convex || !moves_shifts() ? 0.0 : local_shift_drift();
        ops.sum_max_all(worst, 0, 2);
        report.residual = worst[0];
        drift = worst[1];
        // Friction's fixed point: solving the problem of stale shifts further than they are
        // off is wasted work, so the shifts move as soon as the residual is below their drift.
        if (drift > s.tol && report.residual <= kShiftEagerness * drift && k < s.maxiter) {
          // a fixed point that stopped approaching: from now on shifts only go down
          if (drift < 0.5 * best_drift_) {
            best_drift_ = drift;
            stalled_ = 0;
          } else if (!downward_ && ++stalled_ > kMaxStalledShifts) {
            downward_ = true;
            continue;
          }
          move_shifts();
          shifted(s, mu, u);
          continue;
        }
      }
      const auto verdict = set_.check(k, report.residual, s.tol, p, mu, u, ops);
      if (verdict == Verdict::Converged) {
        if constexpr (B > 1) {
          // the problem solved had the last shifts: converged once they are its own
          if (k < s.maxiter && drift > s.tol) {
            move_shifts();
            shifted(s, mu, u);
            continue;
          }
        }
        report.converged = true;
        break;
      }
      if (verdict == Verdict::Grown) grown(s, mu, u);
      if (k >= s.maxiter) break;
      if (verdict == Verdict::Grown) continue;
      if (!step(s, mu, u)) break;    // the method broke down: report the iterate
    }
    finished(s, mu, u);
    report.rho = rho_;
    if (!report.converged) {
      if constexpr (B == 1) {
        report.residual = residual<Law>(op_, mu, u, set_.scales());
      } else {
        // Rows outside the set have no shift: their condition is the real gap (working_set.h);
        // the set's own residual is the last one computed, at this (mu, u).
        double outside = 0.0;
        const int nc = p.n_contacts();
        for (int c = 0; c < nc; ++c)
          if (!set_.contains(c))
            outside = std::max(outside, NormalLaw::violation(p.predicted_gap(c, u), 0.0,
                                                             set_.scales()[c]));
        report.residual = std::max(report.residual, ops.max_all(outside));
      }
    }
    report.speed_scale = set_.speed_scale();
    return report;
  }

  // Cone::Lagged: the next solve caps the shifts at their values at this warm start, not at
  // its own start (hybrid.h: the sweeps' iterate is not a warm start).
  void lag_from(const std::vector<double> &warm)
  {
    warm_ = warm;
    given_warm_ = true;
  }

 protected:
  using Verdict = typename WorkingSet<Law>::Verdict;
  static constexpr int B = Law::block;

  static Coefficients coef(const ContactProblem &p, int c)
  {
    return law_coefficients<Law>(p, c);
  }
  Coefficients coef(int c) const { return coef(op_.problem(), c); }

  // Once per solve, after the working set is made: u = u(mu), and the solver's own state.
  virtual void start(const SolverSettings &s, std::vector<double> &mu, std::vector<Vec3> &u)
  {
    op_.template velocities<Law>(set_.rows(), mu, u);
    rows_changed(s);
  }
  // One iteration from (mu, u = u(mu)) to the next; false if the method broke down.
  virtual bool step(const SolverSettings &s, std::vector<double> &mu, std::vector<Vec3> &u) = 0;
  // Rows joined the working set (at mu = 0; u unchanged).
  virtual void grown(const SolverSettings &s, std::vector<double> &, std::vector<Vec3> &)
  {
    rows_changed(s);
  }
  // The working set is new or larger: what depends on its rows (step bounds) is out of date.
  virtual void rows_changed(const SolverSettings &) {}
  // After the last iteration of a solve (converged or not), with its answer.
  virtual void finished(const SolverSettings &, const std::vector<double> &,
                        const std::vector<Vec3> &)
  {
  }
  // The shifts changed (friction): g_ holds the new gradient at (mu, u); the linear term of
  // the dual moved by the same amount.
  virtual void shifted(const SolverSettings &s, std::vector<double> &, std::vector<Vec3> &)
  {
    rows_changed(s);
  }
  // This process's largest violation over the working set at (mu, u); by default from the
  // gaps of u, which it leaves in g_ for the next step. With friction it must also leave
  // law_shift_ current for g_ (set_violation() does both).
  virtual double set_residual(const std::vector<double> &mu, const std::vector<Vec3> &u)
  {
    double r = 0.0;
    for (const int c : set_.rows()) {
      const size_t at = static_cast<size_t>(B) * c;
      gradient_block(c, u, &g_[at]);
      const double v = set_violation(c, mu, r);
      r = r > v ? r : v;
    }
    return r;
  }
  // Friction: whether the solver brings De Saxce's shifts to their fixed point (the
  // projected-gradient solvers: the start shifts, the lagged cone's caps, the drift and the
  // moves below), or its set_residual() gives each row its iterate's own (no drift, no caps).
  virtual bool moves_shifts() const { return true; }
  // The largest violation over the working set on every process (the stopping test's), at
  // (mu, u), without friction (with friction solve() reduces it with the shifts' drift). A
  // solver that reduces it together with its own sums overrides this.
  virtual double residual_all(const std::vector<double> &mu, const std::vector<Vec3> &u)
  {
    return op_.ops().max_all(set_residual(mu, u));
  }
  // Row c's violation at (mu, g_) for a largest one over rows: a row at most floor (the
  // largest so far) may give floor instead (laws/coulomb.h). With friction it keeps
  // law_shift_[c] = Law::shift(g_ of c), computed with it.
  double set_violation(int c, const std::vector<double> &mu, double floor)
  {
    const size_t at = static_cast<size_t>(B) * c;
    if constexpr (B == 1) return set_.violation(c, &g_[at], &mu[at], coef(c));
    else return set_.violation(c, &g_[at], &mu[at], coef(c), law_shift_[c], floor);
  }

  DualOperator op_;
  WorkingSet<Law> set_;
  std::vector<double> shift_delta_;    // per row: the last move of its shift (friction)
  std::vector<double> g_;    // g(mu) on the working set; kept between solves (no allocation)
  // Friction: Law::shift of g_ per set row, what the shifts move to (before the downward rule
  // of next_shift()). set_residual() leaves it current, from the norms of g_'s tangential
  // components that the violations take anyway (local_shift_drift() reads it right after: a second
  // hypot per row and iteration was 6 % of a frictional pile's instructions). A shift move
  // changes only g_'s normal components, so it stays current through move_shifts().
  std::vector<double> law_shift_;
  double rho_ = 0.0;         // the step the method used, reported (0: none)
  // Friction: De Saxce's shift s_c of each row's normal target (laws/disc_law.h), 0 at the
  // start of a solve and moved to its fixed point by solve() (the operator itself is linear)
  std::vector<double> shift_;
  double shift(int c) const { return shift_[c]; }
  // The B components of row c's gradient at u: h G_c u + D_c, the normal one shifted by s_c.
  void gradient_block(int c, const std::vector<Vec3> &u, double *g) const
  {
    op_.template gap_block<Law>(c, u, g);
    if constexpr (B > 1) g[0] += shift_[c];
  }
  SolverSettings::Cone cone_ = SolverSettings::Cone::Lagged;    // friction: this solve's cone

 private:
  // Measured on a settling 3D pile (726 spheres, mu = 0.5, apgd): updating only once the
  // problem of the old shifts is solved to tol took 835 iterations per step, at residual <=
  // 0.5 x drift 394, at residual <= drift 175 (with the momentum kept), every iteration 272.
  static constexpr double kShiftEagerness = 1.0;
  // The fixed point may have no solution or stop approaching it (a sliding contact whose shift
  // changes the slip that sets it, e.g. wedged spheres under impact): after this many moves
  // without the drift halving, the shifts only go down: s <- min(s, Law::shift). That sequence
  // converges (monotone, bounded below by 0), and at its end no shift exceeds its contact's
  // own value, so the stall leaves no overlap, only a lift-off of sliding contacts below the
  // relaxation's h mu |v_t| in that step.
  static constexpr int kMaxStalledShifts = 50;
  bool downward_ = false;
  // Cone::Lagged: per row, the cap of its shift: for a row that pushed at the warm start, its
  // shift there (the last step's slip carried over), else none (+inf). The shift the solve
  // moves to is Coulomb's, L = Law::shift, where L <= cap, else max(cap, L - kLagAllowance tol
  // scale): a sliding contact whose slip grew beyond what the warm start predicted may lift
  // off, by at most kLagAllowance tol of its row scale (an overlap may be 2 tol of it). One
  // equation in the answer, s = that function of L, so the answer does not depend on the
  // path of the iterates (nor on the rank count). Why: in a rearranging packing the fixed
  // point's upward moves by a few tol, each a change of the normal targets the solve must then
  // follow, were most of the iterations. Measured on the 6-layer settle (hybrid, tol 1e-2 /
  // 1e-3; bench/friction/README.md, "The cone"): iterations per step with the allowance at 0
  // (Cone::Exact) 106 / 347, 1 tol 74 / 266, 3 tol 58 / 320, 10 tol 59 / 241, unbounded 60 /
  // 219. Unbounded, a resting contact struck by an impact lifted off by mu times the slip the
  // impact gave it (a restarted frictional pile then departed from the straight run by 1.2 in
  // velocity, tests/integration/test_restart.py); at 3 tol it stays within tolerance.
  static constexpr double kLagAllowance = 3.0;
  std::vector<double> cap_;
  std::vector<double> warm_;       // lag_from()'s warm start, for the next solve
  bool given_warm_ = false;
  double tol_ = 0.0;
  double best_drift_ = 0.0;
  int stalled_ = 0;
  // The shift row c moves to at the current iterate (g_ at u(mu)).
  double next_shift(int c) const
  {
    const double next = capped(c, law_shift_[c]);
    const double now = shift_[c];
    return downward_ && next > now ? now : next;
  }
  // The shift row c takes where Coulomb's is `law` (cap_ above).
  double capped(int c, double law) const
  {
    return law > cap_[c] ? std::max(cap_[c], law - kLagAllowance * tol_ * set_.scale(c)) : law;
  }
  // Largest |next_shift - s_c| / scale over this process's working set (solve() reduces it).
  double local_shift_drift() const
  {
    double worst = 0.0;
    for (const int c : set_.rows())
      worst = std::max(worst, std::abs(next_shift(c) - shift_[c]) / set_.scale(c));
    return worst;
  }
  // Friction's normal shifts s_c = Law::shift (laws/law.h) from the start multipliers (and,
  // with caps_from_start, the caps of the rows pushing there: Cone::Lagged).
  void start_shifts(const std::vector<double> &mu, std::vector<Vec3> &u, bool caps_from_start)
  {
    op_.template velocities<Law>(set_.rows(), mu, u);
    std::vector<double> &shift = shift_;
    double g[B];
    for (const int c : set_.rows()) {
      op_.template gap_block<Law>(c, u, g);
      const double law = Law::shift(g, coef(c));
      if (caps_from_start && mu[static_cast<size_t>(B) * c] > 0.0) cap_[c] = law;
      shift[c] = cone_ == SolverSettings::Cone::Convex ? 0.0 : capped(c, law);
    }
  }
  // The shifts, and g_ with them, moved to those of the current iterate (g_ at u(mu)).
  void move_shifts()
  {
    std::vector<double> &shift = shift_;
    shift_delta_.resize(shift.size());
    for (const int c : set_.rows()) {
      const double next = next_shift(c);
      shift_delta_[c] = next - shift[c];
      g_[static_cast<size_t>(B) * c] += next - shift[c];
      shift[c] = next;
    }
  }
};

}    // namespace hardcontact
