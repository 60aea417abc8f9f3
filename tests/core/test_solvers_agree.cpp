// Section 3.3: "the time-stepping scheme does not depend on the solver". Every solver of the
// registry, on the random packings of random_config.h, reaches the KKT point of eq. 15 and
// the same velocities as Uzawa (the paper's algorithm), and keeps momentum exactly even when
// stopped early (Remark 10: any mu gives opposite impulses).
#include "solver.h"

#include "core_test_util.h"
#include "random_config.h"

#include <gtest/gtest.h>

using namespace hardcontact;

namespace {

struct Result {
  std::vector<double> mu;
  std::vector<Vec3> u;
  SolveReport report;
};

Result run(const std::string &name, const ContactProblem &p, double tol, int maxiter)
{
  std::unique_ptr<Solver> s = make_solver(name);
  SerialOps ops;
  SolverSettings set;
  set.tol = tol;
  set.maxiter = maxiter;
  Result r;
  r.report = s->solve(p, set, ops, r.mu, r.u);
  return r;
}

hctest::RandomConfig config(unsigned seed, bool walls, double overlap)
{
  hctest::RandomConfigOptions o;
  o.n = 150;
  o.box = 9.5;
  o.walls = walls;
  o.max_overlap = overlap;
  return hctest::random_config(seed, o);
}

}    // namespace

TEST(SolversAgree, SameVelocitiesAndKktOnRandomPackings)
{
  const double tol = 1e-10;
  for (unsigned seed : {31u, 32u}) {
    const hctest::RandomConfig c = config(seed, seed == 31u, seed == 32u ? 0.1 : 0.0);
    const ContactProblem &p = c.p;
    const Result ref = run("uzawa", p, tol, 5000000);
    ASSERT_TRUE(ref.report.converged);
    for (const std::string &name : solver_names()) {
      SCOPED_TRACE(name + " seed " + std::to_string(seed));
      const Result r = run(name, p, tol, 5000000);
      ASSERT_TRUE(r.report.converged) << r.report.iterations << " " << r.report.residual;
      EXPECT_LE(r.report.residual, tol);
      for (int k = 0; k < p.n_contacts(); ++k) {
        const double g = p.predicted_gap(k, r.u);
        EXPECT_GE(r.mu[k], 0.0);
        EXPECT_GE(g, -tol * p.size[k]);
        if (r.mu[k] > 0.0) {
          EXPECT_LE(std::abs(g), tol * p.size[k]);
        }
      }
      double fscale = 0.0;
      for (double m : r.mu) fscale += p.h * m;
      EXPECT_LE(hctest::eq16_defect(p, r.mu, r.u), 1e-13 * fscale);
      EXPECT_LE(hctest::max_diff(r.u, ref.u), 1e-8);
    }
  }
}

TEST(SolversAgree, MomentumExactWhenStoppedEarly)
{
  const hctest::RandomConfig c = config(33u, false, 0.1);
  const ContactProblem &p = c.p;
  const Vec3 P0 = hctest::momentum(p, p.u_free);
  for (const std::string &name : solver_names())
    for (int maxiter : {1, 3, 10}) {
      SCOPED_TRACE(name + " maxiter " + std::to_string(maxiter));
      const Result r = run(name, p, 1e-10, maxiter);    // (a direct solver may converge)
      double impulses = 0.0;
      for (double m : r.mu) impulses += p.h * m;
      EXPECT_GT(impulses, 0.0);
      EXPECT_LE((hctest::momentum(p, r.u) - P0).norm(),
                1e-14 * (hctest::momentum_scale(p, p.u_free) + impulses));
    }
}

// Known gap (reported, not fixed here: src/ belongs to the core): a negative start multiplier
// on a row outside the working set is returned unchanged by uzawa, apgd and pgs (the working
// set only takes rows with mu > 0 or closable gaps; velocities ignore the rest), so the
// "converged" result holds mu < 0 that u does not reflect. Hosts warm-start from earlier
// results (always >= 0), so this only bites a caller passing negative start values.
// Enable with --gtest_also_run_disabled_tests.
TEST(SolversAgree, NegativeStartMultipliersAreNotReturned)
{
  for (const std::string &name : solver_names()) {
    SCOPED_TRACE(name);
    // Apart (gap 0.5) and separating: nothing to do, mu must come back 0.
    ContactProblem p = hctest::make_problem(0.1, {1.0, 1.0}, {Vec3(-1, 0, 0), Vec3(1, 0, 0)});
    hctest::add_pair(p, 0, 1, Vec3(0, 0, 0), Vec3(2.5, 0, 0), 1.0, 1.0);
    std::unique_ptr<Solver> s = make_solver(name);
    SerialOps ops;
    SolverSettings set;
    set.tol = 1e-12;
    std::vector<double> mu{-5.0};
    std::vector<Vec3> u;
    EXPECT_TRUE(s->solve(p, set, ops, mu, u).converged);
    EXPECT_GE(mu[0], 0.0);
    EXPECT_EQ(u[0], p.u_free[0]);
  }
}
