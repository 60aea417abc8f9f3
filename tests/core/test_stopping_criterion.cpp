// The stopping test every solver shares (residual.h, working_set.h):
//  - row scales: min(size, h V) with V the fastest free normal approach (with friction and
//    `speed contact`, the slip conditions' from the contact points' fastest motion), a
//    round-off floor;
//  - Prop. 3 for inexact solves: with no row overlapping at q^n, a solve stopped at the default
//    tol never returns more kinetic energy than u_free has, from any start (garbage warm
//    starts included), for every iterative solver;
//  - small steps: at rest under gravity the velocity error is tol relative to g h, not
//    tol size / h (the chain of failure (C) of doc/stability.md), so a column of spheres
//    stays at rest to L tol g h.
#include "laws/law_list.h"
#include "residual.h"
#include "solver.h"

#include "core_test_util.h"
#include "random_config.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

using namespace hardcontact;

namespace {

TEST(RowScale, SizeOrDistanceCoveredInOneStep)
{
  EXPECT_DOUBLE_EQ(row_scale(1.0, 0.1, 20.0, 1e-4), 1.0);       // h V = 2 > size
  EXPECT_DOUBLE_EQ(row_scale(1.0, 0.01, 2.0, 1e-4), 0.02);      // h V = 0.02
  EXPECT_DOUBLE_EQ(row_scale(1.0, 0.01, 0.0, 1e-4), 1e-8);      // at rest: round-off floor
  EXPECT_DOUBLE_EQ(row_scale(1.0, 0.01, 0.0, 1e-14), 1e2);      // never below round-off
  EXPECT_DOUBLE_EQ(row_scale(1e-5, 0.01, 0.0, 1e-6, 1e-14), 1e-8);    // host's round-off
}

TEST(RowScale, FreeSpeedScaleIsTheFastestNormalApproach)
{
  SerialOps ops;
  auto p = hctest::make_problem(0.1, {1.0, 1.0, 1.0},
                                {Vec3(1, 0, 0), Vec3(-2, 5, 0), Vec3(0, 0, -0.5)});
  hctest::add_pair(p, 0, 1, Vec3(0, 0, 0), Vec3(1, 0, 0), 0.5, 0.5);    // approach 3 along x
  hctest::add_wall(p, 2, Vec3(0, 0, 0.5), 0.5, Vec3(0, 0, 0), Vec3(0, 0, 1));    // 0.5
  EXPECT_DOUBLE_EQ(free_speed_scale(p, ops), 3.0);
}

// `speed contact` (ContactProblem::contact_speed_scale) with friction: Coulomb's law
// constrains the slip as well as the approach, so the slip conditions are measured against the
// fastest relative motion of the contact points V_t (a moving wall's tangential velocity
// included); a sphere rolling without slip adds nothing, and at rest under gravity V_t is still
// g h (only the walls feel the common kick). V, the gap conditions' speed, stays the approach
// with or without the setting.
TEST(RowScale, ContactSpeedScaleIsTheContactPointsSpeed)
{
  SerialOps ops;
  auto p = hctest::make_problem(0.1, {1.0, 1.0, 1.0}, std::vector<Vec3>(3, Vec3::Zero()));
  hctest::add_pair(p, 0, 1, Vec3(0, 0, 0), Vec3(1, 0, 0), 0.5, 0.5);
  hctest::add_wall(p, 2, Vec3(0, 0, 0.5), 0.5, Vec3(0, 0, 0), Vec3(0, 0, 1));
  hctest::add_friction(p, {0.5, 0.5, 0.5}, 0.5);
  const int n = 3;
  auto set = [&](const std::vector<Vec3> &v, const std::vector<Vec3> &w) {
    for (int b = 0; b < n; ++b) {
      p.u_free[b] = v[b];
      p.u_free[n + b] = w[b];
    }
  };
  auto slip = [&](const std::vector<Vec3> &v, const std::vector<Vec3> &w) {
    set(v, w);
    return contact_speed_scale(p, ops);
  };
  const std::vector<Vec3> still(3, Vec3::Zero());
  // the pair approaches at 3 and slides at 5: V = 3 (with the setting too), V_t = |(-3, 5, 0)|
  set({Vec3(1, 0, 0), Vec3(-2, 5, 0), Vec3::Zero()}, still);
  EXPECT_DOUBLE_EQ(free_speed_scale(p, ops), 3.0);
  p.contact_speed_scale = true;
  EXPECT_DOUBLE_EQ(free_speed_scale(p, ops), 3.0);
  EXPECT_DOUBLE_EQ(slip({Vec3(1, 0, 0), Vec3(-2, 5, 0), Vec3::Zero()}, still), std::sqrt(34.0));
  // sphere 2 rolls at 3 on the floor (spin 6 about y, r 0.5): its contact point is still
  const std::vector<Vec3> rolling = {Vec3::Zero(), Vec3::Zero(), Vec3(3, 0, 0)};
  EXPECT_DOUBLE_EQ(slip(rolling, {Vec3::Zero(), Vec3::Zero(), Vec3(0, 6, 0)}), 0.0);
  EXPECT_DOUBLE_EQ(slip(rolling, still), 3.0);    // the same sphere sliding
  // at rest under gravity: every sphere kicked by -g h alike, V_t = V = g h
  const double gh = 0.01;
  EXPECT_DOUBLE_EQ(slip(std::vector<Vec3>(3, Vec3(0, 0, -gh)), still), gh);
  EXPECT_DOUBLE_EQ(free_speed_scale(p, ops), gh);
  // a belt under sphere 2 moving at 7 along y (its own normal speed would be in the target)
  p.wall_velocity.assign(p.n_contacts(), Vec3::Zero());
  p.wall_velocity[1] = Vec3(0, 7, 0.25);
  EXPECT_DOUBLE_EQ(slip(still, still), 7.0);
}

// A frictional row's violation with two scales (laws/disc_law.h): the gap conditions (g_n and
// the cone's normal condition, the shift included) in units of scale, the slip conditions in
// units of slip_scale. Coulomb, mu 0.5; g = (shifted gap, h v_t1, h v_t2).
TEST(RowScale, SlipConditionsTakeTheSlipScaleGapConditionsTheirOwn)
{
  Coefficients k;
  k.friction = 0.5;
  const double scale = 1e-3, slip_scale = 0.1;
  double shift = 0.0;
  // a slide on the cone's edge (force along -t1) whose slip is 0.01 off its force's line: the
  // direction condition |g_t + |g_t| p| ~ 0.01, the shifted normal condition met exactly
  {
    const double m[3] = {1.0, -0.5, 0.0};
    const double gt = std::hypot(0.1, 0.01);
    const double g[3] = {0.5 * gt, 0.1, 0.01};
    const double d = std::hypot(0.1 - gt, 0.01);
    EXPECT_NEAR(CoulombLaw::violation(g, m, k, scale, slip_scale, shift, -1.0), d / slip_scale,
                1e-12);
    EXPECT_DOUBLE_EQ(shift, 0.5 * gt);
    // one scale for both: the same as the four-argument form
    EXPECT_DOUBLE_EQ(CoulombLaw::violation(g, m, k, scale, scale, shift, -1.0),
                     CoulombLaw::violation(g, m, k, scale));
    EXPECT_NEAR(CoulombLaw::violation(g, m, k, scale), d / scale, 1e-9);
  }
  // a stick deep inside its cone (no tangential force) that slips by 0.01: its slip condition
  // is 0.1 of slip_scale, but the shift lifts its normal condition by mu |g_t| = 0.005, which
  // the gap's scale holds: 5
  {
    const double m[3] = {1.0, 0.0, 0.0};
    const double g[3] = {0.005, 0.01, 0.0};
    EXPECT_NEAR(CoulombLaw::violation(g, m, k, scale, slip_scale, shift, -1.0), 5.0, 1e-12);
  }
  // no force: the dual cone's condition g_n >= mu |g_t| is a gap condition
  {
    const double m[3] = {0.0, 0.0, 0.0};
    const double g[3] = {0.0, 0.02, 0.0};
    EXPECT_NEAR(CoulombLaw::violation(g, m, k, scale, slip_scale, shift, -1.0), 10.0, 1e-12);
  }
}

class EnergyOfInexactSolves : public ::testing::TestWithParam<std::string> {
protected:
  // One solve by the solver under test from the multipliers in mu; true when the kinetic
  // energy of the answer is not above the free motion's (Prop. 3), to round-off.
  bool solve_keeps_energy(const ContactProblem &p, double tol, int maxiter, std::vector<double> &mu)
  {
    std::vector<Vec3> u;
    SerialOps ops;
    SolverSettings s;
    s.tol = tol;
    s.maxiter = maxiter;
    const SolveReport report = make_solver(GetParam())->solve(p, s, ops, mu, u);
    EXPECT_TRUE(report.converged) << GetParam() << " tol " << tol;
    return hctest::energy2(p, u) <= hctest::energy2(p, p.u_free) * (1.0 + 1e-13);
  }
};

TEST_P(EnergyOfInexactSolves, NeverAboveTheFreeEnergyFromAnyStart)
{
  int solves = 0;
  for (unsigned seed = 1; seed <= 4; ++seed) {
    for (const double h : {0.002, 0.02, 0.2}) {
      hctest::RandomConfigOptions o;
      o.n = 150;
      o.h = h;
      auto c = hctest::random_config(seed, o);
      const ContactProblem &p = c.p;
      bool overlap = false;
      for (const double d : p.gap) overlap = overlap || d < 0.0;
      ASSERT_FALSE(overlap) << "the scene must start without overlap (0 in K_h)";
      std::mt19937 gen(seed);
      std::uniform_real_distribution<double> U(0.0, 10.0);
      for (const bool garbage : {false, true}) for (const double tol : {1e-2, 1e-4}) {
        std::vector<double> mu(p.n_contacts(), 0.0);
        if (garbage)
          for (double &m : mu) m = U(gen) / (h * h);
        EXPECT_TRUE(solve_keeps_energy(p, tol, 200000, mu))
            << GetParam() << " seed " << seed << " h " << h << " garbage start " << garbage;
        ++solves;
      }
    }
  }
  EXPECT_EQ(solves, 48);
}

// The case where a row tolerance alone lets energy in: a touching row of spheres with no
// relative motion (exact answer u = u_free) started from wrong warm multipliers, next to a
// distant pair approaching fast (it sets V but does not touch within the step). An iterate
// that leaves mu > 0 on the touching rows with gaps g = A mu within the tolerance has gained
// mu.A mu / 2 > 0: only the energy test (Prop. 3) makes the solver go on until it has not.
TEST_P(EnergyOfInexactSolves, RestingRowFromAWrongWarmStart)
{
  const double h = 0.2;
  const int n = 8;
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  int solves = 0;
  for (const double tol : {1e-1, 1e-2, 1e-4}) {
    for (int trial = 0; trial < 20; ++trial) {
      std::vector<double> w;
      std::vector<Vec3> uf;
      for (int k = 0; k < n; ++k) {
        w.push_back(std::pow(10.0, -2.0 * U(gen)));
        uf.emplace_back(0.3, 0.1, 0.0);
      }
      w.push_back(1.0);
      w.push_back(1.0);
      uf.emplace_back(0.5, 0.0, 0.0);
      uf.emplace_back(-0.5, 0.0, 0.0);
      auto p = hctest::make_problem(h, w, uf);
      for (int k = 0; k + 1 < n; ++k)
        hctest::add_pair(p, k, k + 1, Vec3(k, 0, 0), Vec3(k + 1, 0, 0), 0.5, 0.5);
      hctest::add_pair(p, n, n + 1, Vec3(0, 5, 0), Vec3(1.5, 5, 0), 0.5, 0.5);    // gap 0.5
      std::vector<double> mu(p.n_contacts(), 0.0);
      for (int c = 0; c + 1 < n; ++c) mu[c] = 100.0 * U(gen);
      EXPECT_TRUE(solve_keeps_energy(p, tol, 1000000, mu))
          << GetParam() << " tol " << tol << " trial " << trial;
      ++solves;
    }
  }
  EXPECT_EQ(solves, 60);
}

INSTANTIATE_TEST_SUITE_P(Solvers, EnergyOfInexactSolves,
                         ::testing::Values("uzawa", "apgd", "pgs", "cg", "nsgs", "hybrid"));

class RestingColumn : public ::testing::TestWithParam<std::string> {};

// 40 unit spheres stacked on a floor, touching, all with the free velocity -g h of one
// gravity kick: the exact answer is u = 0. With tol measured against the size alone, each row
// could keep a velocity error tol d / h = 0.01 (h = 0.01), and 40 rows in series 0.4.
TEST_P(RestingColumn, VelocityErrorRelativeToTheKick)
{
  const int n = 40;
  const double h = 0.01, g = 1.0, r = 0.5;
  std::vector<Vec3> uf(n, Vec3(0, 0, -g * h));
  auto p = hctest::make_problem(h, std::vector<double>(n, 1.0), uf);
  hctest::add_wall(p, 0, Vec3(0, 0, r), r, Vec3(0, 0, 0), Vec3(0, 0, 1));
  for (int k = 0; k + 1 < n; ++k)
    hctest::add_pair(p, k, k + 1, Vec3(0, 0, r * (2 * k + 1)), Vec3(0, 0, r * (2 * k + 3)), r, r);
  for (const bool warm : {false, true}) {
    // warm: the exact multipliers (the weight above each contact) times 1.5
    std::vector<double> mu(p.n_contacts(), 0.0);
    if (warm)
      for (int c = 0; c < p.n_contacts(); ++c) mu[c] = 1.5 * (n - c) * g;
    std::vector<Vec3> u;
    SerialOps ops;
    SolverSettings s;
    s.maxiter = 1000000;
    const auto report = make_solver(GetParam())->solve(p, s, ops, mu, u);
    ASSERT_TRUE(report.converged);
    EXPECT_DOUBLE_EQ(report.speed_scale, g * h);
    double vmax = 0.0;
    for (const Vec3 &v : u) vmax = std::max(vmax, v.norm());
    EXPECT_LE(vmax, n * s.tol * g * h) << GetParam() << (warm ? " warm" : " cold");
  }
}

INSTANTIATE_TEST_SUITE_P(Solvers, RestingColumn, ::testing::Values("uzawa", "apgd", "pgs", "cg", "exact", "nsgs", "hybrid"));

}    // namespace
