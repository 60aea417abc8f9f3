// The paper's experiments of section 6, run with a small time-stepping loop written here
// (scheme (S): rows from the current positions, u_free = u + h f/m, solve, q += h u) around
// the core's solver.
//
// 6.2 Sticky particles: N = 20 point masses on a line. Checked: the centre of mass is exact at
//     every step for every h (Prop. 4 / Remark 11), even with an unconverged solver; and the
//     positions agree with an exact event-driven sticky-particle solution (written here:
//     clusters merge at their exact collision times, momentum conserved). In 1D the scheme
//     with an exact projection is exact at the grid times (q^{n+1} = P_K(q^n + h u^n) and the
//     sticky flow is X(t) = P_K(X(0) + t V(0)), Brenier & Grenier 1998), so the three runs
//     h = 0.01, 0.5, 1.5 give the same positions at t = 3 - the paper's "same final state",
//     here at any grid time and without waiting for all collisions. When every particle has
//     merged, the cluster is at x_cm(0) + t v_cm with velocity v_cm.
// 6.1 Non-uniqueness: one point above a wall at 0, the self-similar force of SCHEME.md. Two
//     exact solutions are derived below in closed form; the steps h = 2^-p converge to one for
//     even p and to the other for odd p.
#include "solver.h"

#include "core_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

using namespace hardcontact;

namespace {

// Bodies on the x axis, ordered: body k+1 is right of body k, radius r each. In 1D only
// neighbours can meet first (Remark 1: the order never changes), so one row per neighbour
// pair is enough; all_pairs adds the redundant others (a cross-check of Lemma 1: same u).
struct Line {
  std::vector<double> q, u, m;
  double r = 0.0;
};

struct StepStats {
  int max_iterations = 0;
  bool all_converged = true;
};

// One step of scheme (S) with per-body force f (its mean over the step), and an optional wall
// at x = 0 left of body 0 (1D, point or segment of radius r).
StepStats step(Line &L, const std::vector<double> &f, double h, Solver &solver,
               const SolverSettings &set, double size, bool wall, bool all_pairs,
               std::vector<double> &mu_warm)
{
  const int n = static_cast<int>(L.q.size());
  ContactProblem p;
  p.h = h;
  p.n_owned = n;
  for (int k = 0; k < n; ++k) {
    p.inv_mass.push_back(1.0 / L.m[k]);
    p.u_free.push_back(Vec3(L.u[k] + h * f[k] / L.m[k], 0, 0));
  }
  // Normals from the order, not from the positions: merged points coincide.
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < (all_pairs ? n : std::min(n, i + 2)); ++j)
      p.add_contact(i, j, Vec3(1, 0, 0), L.q[j] - L.q[i] - 2.0 * L.r * (j - i) , size);
  if (wall) p.add_contact(0, -1, Vec3(-1, 0, 0), L.q[0] - L.r, size);
  // Warm start: the rows are the same from step to step (same order), as in the host.
  SerialOps ops;
  std::vector<Vec3> u;
  const SolveReport rep = solver.solve(p, set, ops, mu_warm, u);
  for (int k = 0; k < n; ++k) {
    L.u[k] = u[k].x();
    L.q[k] += h * L.u[k];
  }
  return {rep.iterations, rep.converged};
}

double centre_of_mass(const Line &L)
{
  double s = 0.0, M = 0.0;
  for (size_t k = 0; k < L.q.size(); ++k) {
    s += L.m[k] * L.q[k];
    M += L.m[k];
  }
  return s / M;
}

// ---------------------------------------------------------------------------------------
// Exact sticky particles (event driven): clusters of consecutive particles, each with mass,
// position and velocity; the earliest collision of neighbours merges them (momentum kept).
struct Cluster {
  double x, v, m;
  int first, last;    // particle range
  double formed;      // time of its last merge (0 if initial)
};

std::vector<Cluster> exact_sticky(const std::vector<double> &q0, const std::vector<double> &u0,
                                  const std::vector<double> &m, double T,
                                  double *next_collision = nullptr)
{
  std::vector<Cluster> cl;
  for (size_t k = 0; k < q0.size(); ++k)
    cl.push_back({q0[k], u0[k], m[k], static_cast<int>(k), static_cast<int>(k), 0.0});
  double t = 0.0;
  for (;;) {
    double best = INFINITY;
    size_t kb = 0;
    for (size_t k = 0; k + 1 < cl.size(); ++k)
      if (cl[k].v > cl[k + 1].v) {
        const double tc = t + (cl[k + 1].x - cl[k].x) / (cl[k].v - cl[k + 1].v);
        if (tc < best) best = tc, kb = k;
      }
    if (!(best <= T)) {
      if (next_collision) *next_collision = best;
      break;
    }
    for (Cluster &c : cl) c.x += c.v * (best - t);
    t = best;
    Cluster &a = cl[kb];
    const Cluster &b = cl[kb + 1];
    const double M = a.m + b.m;
    a.v = (a.m * a.v + b.m * b.v) / M;
    a.x = (a.m * a.x + b.m * b.x) / M;    // equal up to round-off: they touch
    a.m = M;
    a.last = b.last;
    a.formed = t;
    cl.erase(cl.begin() + kb + 1);
  }
  for (Cluster &c : cl) c.x += c.v * (T - t);
  return cl;
}

struct StickySetup {
  std::vector<double> q0, u0, m;
};

// Paper 6.2: q0 = (0, a, ..., 1), a = 1/(N-1), u0 uniform in [-1, 1]; masses 1, or
// log-uniform in [1, 10] for the variant; converge > 0 adds an inward ramp -converge (x - 1/2)
// so that every particle ends in one cluster.
StickySetup sticky_setup(unsigned seed, int N, bool unequal_masses, double converge = 0.0)
{
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> U(-1.0, 1.0), E(0.0, 1.0);
  StickySetup s;
  for (int k = 0; k < N; ++k) {
    s.q0.push_back(static_cast<double>(k) / (N - 1));
    s.u0.push_back(U(gen) - converge * (s.q0.back() - 0.5));
    s.m.push_back(unequal_masses ? std::pow(10.0, E(gen)) : 1.0);
  }
  return s;
}

struct StickyRun {
  Line final_state;
  double max_cm_error = 0.0;      // |x_cm(t_n) - (x_cm(0) + t_n v_cm)| over all steps
  double max_exact_error = 0.0;   // max |q_k(t_n) - exact| over all steps and particles
  bool converged = true;
};

StickyRun run_sticky(const StickySetup &s, double h, double T, int maxiter, bool all_pairs,
                     bool compare_every_step)
{
  const int N = static_cast<int>(s.q0.size());
  const double a = 1.0 / (N - 1);
  Line L{s.q0, s.u0, s.m, 0.0};
  const double x0 = centre_of_mass(L);
  double P = 0.0, M = 0.0;
  for (int k = 0; k < N; ++k) P += s.m[k] * s.u0[k], M += s.m[k];
  const double vcm = P / M;

  std::unique_ptr<Solver> solver = make_solver("uzawa");
  SolverSettings set;
  set.tol = 1e-12;    // relative to the spacing a: 5e-14 in length
  set.maxiter = maxiter;
  std::vector<double> mu;
  StickyRun run;
  const int steps = static_cast<int>(std::lround(T / h));
  for (int n = 1; n <= steps; ++n) {
    const StepStats st = step(L, std::vector<double>(N, 0.0), h, *solver, set, a, false,
                              all_pairs, mu);
    run.converged = run.converged && st.all_converged;
    const double t = n * h;
    run.max_cm_error = std::max(run.max_cm_error, std::abs(centre_of_mass(L) - (x0 + t * vcm)));
    if (compare_every_step || n == steps) {
      for (const Cluster &c : exact_sticky(s.q0, s.u0, s.m, t))
        for (int k = c.first; k <= c.last; ++k)
          run.max_exact_error = std::max(run.max_exact_error, std::abs(L.q[k] - c.x));
    }
  }
  run.final_state = L;
  return run;
}

}    // namespace

TEST(PaperStickyParticles, ExactOracleIsSane)
{
  // Two particles: 1 at +1 from 0, 2 at rest at 1 (masses 1, 3): meet at t = 1, then move at
  // 1/4 together; at t = 3 both at 1 + 2/4 = 1.5.
  double next = 0.0;
  const std::vector<Cluster> cl = exact_sticky({0.0, 1.0}, {1.0, 0.0}, {1.0, 3.0}, 3.0, &next);
  ASSERT_EQ(cl.size(), 1u);
  EXPECT_DOUBLE_EQ(cl[0].x, 1.5);
  EXPECT_DOUBLE_EQ(cl[0].v, 0.25);
  EXPECT_DOUBLE_EQ(cl[0].formed, 1.0);
  EXPECT_TRUE(std::isinf(next));
}

TEST(PaperStickyParticles, CentreOfMassExactAndSameStateForEveryStep)
{
  const int N = 20;
  for (bool unequal : {false, true}) {
    SCOPED_TRACE(unequal);
    const StickySetup s = sticky_setup(3, N, unequal);
    double next = 0.0;
    const std::vector<Cluster> exact = exact_sticky(s.q0, s.u0, s.m, 3.0, &next);
    // Not everything has merged, and some collisions happened: a non-trivial state ...
    ASSERT_GT(exact.size(), 1u);
    ASSERT_LT(exact.size(), static_cast<size_t>(N) - 3);
    // ... and it is the final one (the paper's "once all collisions have been taken into
    // account"): no further collision ever, the clusters' velocities do not decrease, and each
    // cluster moves with the momentum-weighted mean of its particles' initial velocities.
    ASSERT_TRUE(std::isinf(next));
    for (size_t c = 0; c + 1 < exact.size(); ++c) EXPECT_LE(exact[c].v, exact[c + 1].v);
    for (const Cluster &c : exact) {
      double P = 0.0, M = 0.0;
      for (int k = c.first; k <= c.last; ++k) P += s.m[k] * s.u0[k], M += s.m[k];
      EXPECT_NEAR(c.v, P / M, 1e-15);
    }

    std::vector<StickyRun> runs;
    for (double h : {0.01, 0.5, 1.5}) {
      SCOPED_TRACE(h);
      runs.push_back(run_sticky(s, h, 3.0, 1000000, false, true));
      const StickyRun &r = runs.back();
      EXPECT_TRUE(r.converged);
      // Remark 11: the centre of mass moves exactly on x_cm(0) + t v_cm.
      EXPECT_LE(r.max_cm_error, 1e-14);
      // The positions are the exact sticky positions at the grid times (and at t = 3).
      EXPECT_LE(r.max_exact_error, 1e-9);
      // Prop. 2: no particle passed its neighbour (up to the solver tolerance).
      for (int k = 0; k + 1 < N; ++k)
        EXPECT_GE(r.final_state.q[k + 1] - r.final_state.q[k], -1e-12) << k;
    }
    // Hence the same state at t = 3 for the three steps.
    for (int k = 0; k < N; ++k) {
      EXPECT_NEAR(runs[1].final_state.q[k], runs[0].final_state.q[k], 2e-9) << k;
      EXPECT_NEAR(runs[2].final_state.q[k], runs[0].final_state.q[k], 2e-9) << k;
    }
    // The coarse runs really were coarse: the first step of the h = 1.5 run took at least 5
    // collisions of (0, 1.5] into account at once, and some merges happened after t = 0.5.
    EXPECT_LE(exact_sticky(s.q0, s.u0, s.m, 1.5).size(), static_cast<size_t>(N - 5));
    bool late_merge = false;
    for (const Cluster &c : exact) late_merge = late_merge || c.formed > 0.5;
    EXPECT_TRUE(late_merge);
  }
}

TEST(PaperStickyParticles, RedundantRowsForAllPairsGiveTheSameMotion)
{
  // Rows for all 190 pairs instead of the 19 neighbour pairs: the extra rows are implied
  // (points: D_ik = D_ij + D_jk), the projection is the same (u unique), so is the motion.
  const StickySetup s = sticky_setup(3, 20, false);
  for (double h : {0.5, 1.5}) {
    const StickyRun neighbours = run_sticky(s, h, 3.0, 1000000, false, false);
    const StickyRun all = run_sticky(s, h, 3.0, 1000000, true, false);
    EXPECT_TRUE(all.converged);
    EXPECT_LE(all.max_exact_error, 1e-9);
    for (int k = 0; k < 20; ++k)
      EXPECT_NEAR(all.final_state.q[k], neighbours.final_state.q[k], 2e-9) << k;
  }
}

TEST(PaperStickyParticles, CentreOfMassExactEvenWithUnconvergedSolver)
{
  // Remark 10: momentum (hence the centre of mass) does not need a converged solve.
  const StickySetup s = sticky_setup(7, 20, true);
  for (double h : {0.01, 0.5, 1.5}) {
    SCOPED_TRACE(h);
    const StickyRun r = run_sticky(s, h, 3.0, 2, false, false);
    EXPECT_FALSE(r.converged);
    EXPECT_LE(r.max_cm_error, 1e-14);
    // ... while the individual positions are visibly wrong (particles overlap).
    EXPECT_GT(r.max_exact_error, 0.1);
  }
}

TEST(PaperStickyParticles, AllMergedClusterMovesWithCentreOfMass)
{
  // Inward ramp: every particle ends in one cluster well before t = 3. Its position is then
  // fixed by the centre of mass alone, x_cm(0) + 3 v_cm, for every h; its velocity is v_cm
  // once the last merge is at least one step old.
  const int N = 20;
  const StickySetup s = sticky_setup(11, N, true, 4.0);
  double next = 0.0;
  const std::vector<Cluster> exact = exact_sticky(s.q0, s.u0, s.m, 3.0, &next);
  ASSERT_EQ(exact.size(), 1u);
  ASSERT_LT(exact[0].formed, 1.0);
  double P = 0.0, M = 0.0, X = 0.0;
  for (int k = 0; k < N; ++k) P += s.m[k] * s.u0[k], M += s.m[k], X += s.m[k] * s.q0[k];
  const double vcm = P / M, x3 = X / M + 3.0 * vcm;
  for (double h : {0.01, 0.5, 1.5}) {
    SCOPED_TRACE(h);
    const StickyRun r = run_sticky(s, h, 3.0, 1000000, false, false);
    for (int k = 0; k < N; ++k) EXPECT_NEAR(r.final_state.q[k], x3, 1e-9) << k;
    // The last merge happened in step ceil(t_f / h); the step after it pools the velocities.
    if (std::ceil(exact[0].formed / h) * h + h <= 3.0 + 1e-12) {
      for (int k = 0; k < N; ++k) EXPECT_NEAR(r.final_state.u[k], vcm, 1e-9) << k;
    }
  }
}

// ---------------------------------------------------------------------------------------
// 6.1: one point, q >= 0, u(0) = 0, f = 1 on (T, 3T/2) and -alpha on (3T/2, 2T) for every
// T = 2^-(k+1), k >= -4, alpha = 1.8. f(2t) = f(t): the problem is invariant under
// q(t) -> q(2t)/4, and under q(t) -> q(4t)/16.

namespace {

constexpr double kAlpha = 1.8;

// F(t) = int_0^t f, exact: every dyadic interval (T, 2T) contributes T/2 - alpha T/2 = -0.4 T,
// so F(T) = -0.4 T at every T = 2^-j, and inside (T, 2T) F grows with f.
double F(double t)
{
  if (t <= 0.0) return 0.0;
  double T = std::exp2(std::floor(std::log2(t)));    // T <= t < 2T
  if (T == t) return -(kAlpha - 1.0) / 2.0 * T;
  const double base = -(kAlpha - 1.0) / 2.0 * T, s = t - T;
  return s <= T / 2 ? base + s : base + T / 2 - kAlpha * (s - T / 2);
}

// Solution A: at rest on the wall at t = 1 (and at every 4^-m). Derived by hand:
//  (1, 3/2):  f = 1 from rest          q = (t-1)^2/2                  (q = 1/8, u = 1/2 at 3/2)
//  (3/2, 2):  f = -alpha               q = 1/8 + (t-3/2)/2 - 0.9 (t-3/2)^2   (apex 0.194 at
//             t = 3/2 + 1/(2 alpha); q(2) = 0.15, u(2) = -0.4: still in the air at t = 2)
//  (2, 3):    f = 1                    q = 0.15 - 0.4 (t-2) + (t-2)^2/2  (min 0.07 > 0 at 2.4;
//             q(3) = 0.25, u(3) = 0.6)
//  (3, 4):    f = -alpha               q = 0.25 + 0.6 (t-3) - 0.9 (t-3)^2 until it lands at
//             t* = 3 + (0.6 + sqrt(1.26)) / 1.8 = 3.957 (< 4), then q = 0 (inelastic, f < 0).
// So it is at rest at 4 again; on (0, 1] it is the same pattern scaled: q(t) = q(4t)/16.
double q_A(double t)
{
  double scale = 1.0;
  while (t <= 1.0) {
    t *= 4.0;
    scale /= 16.0;
  }
  double q;
  if (t <= 1.5) {
    q = 0.5 * (t - 1) * (t - 1);
  } else if (t <= 2.0) {
    const double d = t - 1.5;
    q = 0.125 + 0.5 * d - 0.5 * kAlpha * d * d;
  } else if (t <= 3.0) {
    const double d = t - 2.0;
    q = 0.15 - 0.4 * d + 0.5 * d * d;
  } else {
    const double d = t - 3.0, landing = (0.6 + std::sqrt(0.36 + 2 * kAlpha * 0.25)) / kAlpha;
    q = d < landing ? 0.25 + 0.6 * d - 0.5 * kAlpha * d * d : 0.0;
  }
  return scale * q;
}

// Solution B: the same pattern shifted by one octave, q_B(t) = 4 q_A(t/2): at rest at 2 (and
// 1/2, 1/8, ...), in the air at 4 (q_B(4) = 4 q_A(2) = 0.6).
double q_B(double t) { return 4.0 * q_A(0.5 * t); }

struct Trajectory {
  std::vector<double> t, q;
  double h;
};

Trajectory run_nonuniqueness(int p)
{
  const double h = std::exp2(-p);
  std::unique_ptr<Solver> solver = make_solver("uzawa");
  SolverSettings set;
  set.tol = 1e-12;
  std::vector<double> mu;
  Line L{{0.0}, {0.0}, {1.0}, 0.0};
  Trajectory tr;
  tr.h = h;
  const int steps = static_cast<int>(std::lround(4.0 / h));
  for (int n = 0; n < steps; ++n) {
    const double fmean = (F((n + 1) * h) - F(n * h)) / h;    // eq. 14 with the exact mean
    const StepStats st = step(L, {fmean}, h, *solver, set, 1.0, true, false, mu);
    EXPECT_TRUE(st.all_converged);
    tr.t.push_back((n + 1) * h);
    tr.q.push_back(L.q[0]);
  }
  return tr;
}

double max_error(const Trajectory &tr, const std::function<double(double)> &exact)
{
  double e = 0.0;
  for (size_t n = 0; n < tr.t.size(); ++n) e = std::max(e, std::abs(tr.q[n] - exact(tr.t[n])));
  return e;
}

double at(const Trajectory &tr, double t) { return tr.q[std::lround(t / tr.h) - 1]; }

}    // namespace

TEST(PaperNonUniqueness, ForceMeansAndExactSolutionsAreConsistent)
{
  // F is the integral of f: -0.4 per unit of dyadic interval, and f = 1 / -alpha pieces.
  EXPECT_DOUBLE_EQ(F(4.0), -1.6);
  EXPECT_DOUBLE_EQ(F(2.0), -0.8);
  EXPECT_DOUBLE_EQ(F(3.0), -0.8 + 1.0);
  EXPECT_DOUBLE_EQ(F(3.5), -0.8 + 1.0 - 0.9);
  EXPECT_DOUBLE_EQ(F(0.75), -0.2 + 0.25);
  EXPECT_DOUBLE_EQ(F(std::exp2(-20)), -0.4 * std::exp2(-20));
  // Both closed forms: continuous, q >= 0, at rest / in flight where derived.
  for (double t = 1e-3; t < 4.0; t += 1e-3) {
    EXPECT_GE(q_A(t), 0.0);
    EXPECT_NEAR(q_A(t), q_A(t + 1e-7), 1e-6);
    EXPECT_NEAR(q_B(t), q_B(t + 1e-7), 1e-6);
  }
  EXPECT_EQ(q_A(1.0), 0.0);
  EXPECT_EQ(q_A(4.0), 0.0);
  EXPECT_NEAR(q_A(2.0), 0.15, 1e-15);
  EXPECT_EQ(q_B(2.0), 0.0);
  EXPECT_NEAR(q_B(4.0), 0.6, 1e-15);
  EXPECT_NEAR(q_B(1.0), 0.0375, 1e-15);
}

TEST(PaperNonUniqueness, EvenAndOddPowersOfTwoConvergeToTwoSolutions)
{
  std::vector<Trajectory> tr;
  for (int p = 8; p <= 11; ++p) tr.push_back(run_nonuniqueness(p));
  for (const Trajectory &t : tr) {
    SCOPED_TRACE(t.h);
    const bool even = std::lround(-std::log2(t.h)) % 2 == 0;
    for (double q : t.q) EXPECT_GE(q, -1e-12);    // Prop. 2
    // O(h) from its own limit, O(1) from the other: h = 2^-(2n) -> A, 2^-(2n+1) -> B.
    const double eA = max_error(t, q_A), eB = max_error(t, q_B);
    EXPECT_LE(even ? eA : eB, 1.0 * t.h);
    EXPECT_GE(even ? eB : eA, 0.5);
    // The two limits at chosen times: A rests at 1 and 4 and flies at 2 and 3; B the reverse
    // at 2, and at 3 and 4 is at 0.5 and 0.6.
    EXPECT_NEAR(at(t, 1.0), even ? 0.0 : 0.0375, t.h);
    EXPECT_NEAR(at(t, 2.0), even ? 0.15 : 0.0, t.h);
    EXPECT_NEAR(at(t, 3.0), even ? 0.25 : 0.5, t.h);
    EXPECT_NEAR(at(t, 4.0), even ? 0.0 : 0.6, t.h);
  }
  // Same parity agree closely on the common grid, different parity do not.
  auto grid_diff = [](const Trajectory &a, const Trajectory &b) {
    double d = 0.0;
    for (double t = a.h; t <= 4.0; t += a.h) d = std::max(d, std::abs(at(a, t) - at(b, t)));
    return d;
  };
  EXPECT_LE(grid_diff(tr[0], tr[2]), 2 * tr[0].h);    // 2^-8 vs 2^-10
  EXPECT_LE(grid_diff(tr[1], tr[3]), 2 * tr[1].h);    // 2^-9 vs 2^-11
  EXPECT_GE(grid_diff(tr[0], tr[1]), 0.5);
  EXPECT_GE(grid_diff(tr[2], tr[3]), 0.5);
  // The errors shrink with h within each family.
  EXPECT_LT(max_error(tr[2], q_A), max_error(tr[0], q_A));
  EXPECT_LT(max_error(tr[3], q_B), max_error(tr[1], q_B));
}
