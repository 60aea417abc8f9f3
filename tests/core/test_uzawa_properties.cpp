// Properties of section 4 checked on random packings (random_config.h: fixed seeds, 300
// spheres in a box, near-contacts and small overlaps, masses 1..1000):
//  - the KKT conditions of eq. 15-18 (the solution is the projection), against a dense
//    assembly of eq. 16 and an independent solver (projected Gauss-Seidel);
//  - Prop. 3 (kinetic energy does not increase), Prop. 4 / Remark 10 (momentum is exact even
//    for an unconverged solve), Lemma 1 / Prop. 5 (u unique, mu not, in a redundant packing),
//    independence of the starting multipliers;
//  - the step size: dual_operator_bound(p) bounds the largest eigenvalue of
//    A = h^2 G M^-1 G^T (dense, Eigen) and is within a factor max-degree of it; rho = 1/bound;
//    a rho above 2 / lambda_max does not converge.
#include "dual_operator.h"
#include "uzawa.h"

#include "core_test_util.h"
#include "random_config.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <map>
#include <random>

using namespace hardcontact;
using hctest::RandomConfig;
using hctest::RandomConfigOptions;

namespace {

constexpr double kTol = 1e-10;

struct Solved {
  RandomConfig c;
  std::vector<double> mu;
  std::vector<Vec3> u;
  SolveReport report;
};

SolveReport solve(const ContactProblem &p, std::vector<double> &mu, std::vector<Vec3> &u,
                  double tol = kTol, int maxiter = 5000000, double rho = 0.0)
{
  Uzawa solver;
  SerialOps ops;
  SolverSettings s;
  s.tol = tol;
  s.maxiter = maxiter;
  s.rho = rho;
  return solver.solve(p, s, ops, mu, u);
}

enum Kind {
  kWallsNoOverlap,      // non-overlapping packing in a closed box (0 is feasible)
  kNoWallsNoOverlap,    // same without walls (momentum is conserved)
  kNoWallsOverlap,      // pairs overlapping by up to 0.1 (0 is not feasible), no walls
  kWallsOverlap,
};

RandomConfigOptions options(Kind k)
{
  RandomConfigOptions o;
  o.walls = (k == kWallsNoOverlap || k == kWallsOverlap);
  o.max_overlap = (k == kNoWallsOverlap || k == kWallsOverlap) ? 0.1 : 0.0;
  return o;
}

// Solved once per (kind, seed), shared by the tests of this file.
const Solved &solved(Kind k, unsigned seed)
{
  static std::map<std::pair<int, unsigned>, Solved> cache;
  auto key = std::make_pair(static_cast<int>(k), seed);
  auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  Solved s;
  s.c = hctest::random_config(seed, options(k));
  s.report = solve(s.c.p, s.mu, s.u);
  return cache.emplace(key, std::move(s)).first->second;
}

void expect_kkt(const ContactProblem &p, const std::vector<double> &mu,
                const std::vector<Vec3> &u, double tol)
{
  ASSERT_EQ(static_cast<int>(mu.size()), p.n_contacts());
  ASSERT_EQ(static_cast<int>(u.size()), p.n_bodies());
  double sum_mu_g = 0.0, sum_mu_size = 0.0, fscale = 0.0;
  for (int c = 0; c < p.n_contacts(); ++c) {
    const double g = p.predicted_gap(c, u);
    EXPECT_GE(mu[c], 0.0) << c;                   // eq. 17: the contact can only push
    EXPECT_GE(g, -tol * p.size[c]) << c;          // eq. 15: no predicted overlap
    if (mu[c] > 0.0) {
      EXPECT_LE(std::abs(g), tol * p.size[c]) << c;    // eq. 18
    }
    sum_mu_g += mu[c] * std::abs(g);
    sum_mu_size += mu[c] * p.size[c];
    fscale += p.h * mu[c];
  }
  EXPECT_LE(sum_mu_g, tol * sum_mu_size);    // complementarity, summed
  // Stationarity: eq. 16 re-assembled densely, independent of dual_operator.cpp.
  fscale += hctest::momentum_scale(p, p.u_free) / p.n_bodies();
  EXPECT_LE(hctest::eq16_defect(p, mu, u), 1e-13 * fscale);
}

}    // namespace

// ---------------------------------------------------------------------------------------
// KKT conditions at convergence (tol 1e-10).

class UzawaRandom : public ::testing::TestWithParam<std::pair<Kind, unsigned>> {};

TEST_P(UzawaRandom, ConvergesToAKktPoint)
{
  const Solved &s = solved(GetParam().first, GetParam().second);
  ASSERT_GE(s.c.p.n_bodies(), 250);
  ASSERT_TRUE(s.report.converged) << s.report.iterations << " " << s.report.residual;
  EXPECT_LE(s.report.residual, kTol);
  // The configuration is not trivial: many rows, many of them pushing.
  int active = 0;
  for (double m : s.mu) active += (m > 0.0);
  EXPECT_GT(active, 100);
  expect_kkt(s.c.p, s.mu, s.u, kTol);
}

INSTANTIATE_TEST_SUITE_P(Packings, UzawaRandom,
                         ::testing::Values(std::make_pair(kWallsNoOverlap, 1u),
                                           std::make_pair(kNoWallsNoOverlap, 2u),
                                           std::make_pair(kNoWallsOverlap, 2u),
                                           std::make_pair(kWallsOverlap, 2u)));

TEST(UzawaProperties, SameVelocitiesAsProjectedGaussSeidel)
{
  // The scheme does not depend on the solver (section 3.3): an unrelated exact method on the
  // dense dual gives the same u. Smaller packings, so that dense PGS is cheap.
  for (unsigned seed : {4u, 5u}) {
    RandomConfigOptions o;
    o.n = 60;
    o.box = 7.0;
    o.max_overlap = (seed == 5u) ? 0.1 : 0.0;
    const RandomConfig c = hctest::random_config(seed, o);
    std::vector<double> mu;
    std::vector<Vec3> u;
    ASSERT_TRUE(solve(c.p, mu, u, 1e-12).converged);
    std::vector<double> mu_pgs;
    const std::vector<Vec3> u_pgs = hctest::pgs_solve(c.p, 20000, &mu_pgs);
    EXPECT_LE(hctest::max_diff(u, u_pgs), 1e-8) << seed;
  }
}

// ---------------------------------------------------------------------------------------
// Prop. 3: u is the M-projection of u_free onto a convex set; when every gap is >= 0 that set
// contains 0, hence |u|_M^2 + |u - u_free|_M^2 <= |u_free|_M^2 (in particular the kinetic
// energy does not increase).

TEST(UzawaProperties, KineticEnergyDoesNotIncreaseWhenZeroIsFeasible)
{
  for (Kind k : {kWallsNoOverlap, kNoWallsNoOverlap}) {
    const Solved &s = solved(k, k == kWallsNoOverlap ? 1u : 2u);
    for (double g : s.c.p.gap) ASSERT_GE(g, 0.0);
    ASSERT_TRUE(s.report.converged);
    const double e_free = hctest::energy2(s.c.p, s.c.p.u_free);
    const double e = hctest::energy2(s.c.p, s.u);
    const double d = hctest::dist2_M(s.c.p, s.u, s.c.p.u_free);
    EXPECT_LT(e, e_free);
    EXPECT_GT(d, 1e-3 * e_free);    // the contacts did something
    EXPECT_LE(e + d, e_free * (1.0 + 1e-9));
  }
}

// ---------------------------------------------------------------------------------------
// Prop. 4 / Remark 10: with no walls (and no immovable body) every row pushes its two bodies
// with opposite impulses, so sum m u = sum m u_free whatever mu is, converged or not.

TEST(UzawaProperties, MomentumExactEvenWhenUnconverged)
{
  for (Kind k : {kNoWallsNoOverlap, kNoWallsOverlap}) {
    const RandomConfig c = hctest::random_config(2u, options(k));
    const Vec3 P0 = hctest::momentum(c.p, c.p.u_free);
    for (int maxiter : {0, 1, 2, 5, 50, 5000000}) {
      SCOPED_TRACE(maxiter);
      std::vector<double> mu;
      std::vector<Vec3> u;
      const SolveReport r = solve(c.p, mu, u, kTol, maxiter);
      EXPECT_LE(r.iterations, maxiter);
      if (maxiter <= 50) {
        EXPECT_FALSE(r.converged);
        EXPECT_EQ(r.iterations, maxiter);
      }
      double impulses = 0.0;
      for (double m : mu) impulses += c.p.h * m;
      if (maxiter > 0) {
        EXPECT_GT(impulses, 0.0);
      }
      const double scale = hctest::momentum_scale(c.p, c.p.u_free) + impulses;
      EXPECT_LE((hctest::momentum(c.p, u) - P0).norm(), 1e-14 * scale);
    }
  }
}

TEST(UzawaProperties, WallsTakeMomentumAway)
{
  // The control for the test above: with walls, momentum does change (by the wall impulses,
  // exactly: sum m u - sum m u_free = -h sum_wall-rows mu n).
  const Solved &s = solved(kWallsOverlap, 2u);
  const ContactProblem &p = s.c.p;
  Vec3 wall_impulse = Vec3::Zero();
  for (int c = 0; c < p.n_contacts(); ++c)
    if (p.body_j[c] < 0) wall_impulse -= p.h * s.mu[c] * p.normal[c];
  ASSERT_GT(wall_impulse.norm(), 1.0);
  const Vec3 dP = hctest::momentum(p, s.u) - hctest::momentum(p, p.u_free);
  EXPECT_LE((dP - wall_impulse).norm(), 1e-12 * hctest::momentum_scale(p, p.u_free));
}

// ---------------------------------------------------------------------------------------
// Uniqueness of u (strict convexity) whatever the start multipliers (warm start).

TEST(UzawaProperties, SolutionDoesNotDependOnStartMultipliers)
{
  for (Kind k : {kWallsNoOverlap, kNoWallsOverlap}) {
    SCOPED_TRACE(k);
    const unsigned seed = (k == kWallsNoOverlap) ? 1u : 2u;
    const Solved &s = solved(k, seed);
    std::mt19937 gen(99);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    double mu_max = 0.0;
    for (double m : s.mu) mu_max = std::max(mu_max, m);
    std::vector<std::vector<double>> starts;
    if (k == kWallsNoOverlap) {
      std::vector<double> m0(s.mu.size());
      for (double &x : m0) x = 2.0 * mu_max * U(gen);    // random, every row pushing
      starts.push_back(m0);
      starts.push_back(std::vector<double>(s.mu.size() / 2, mu_max));    // short: rest are 0
    } else {
      std::vector<double> m0 = s.mu;
      for (double &x : m0) x *= 3.0;    // the solution's pattern, wrong size
      starts.push_back(m0);
    }
    for (size_t t = 0; t < starts.size(); ++t) {
      SCOPED_TRACE(t);
      std::vector<double> mu = starts[t];
      std::vector<Vec3> u;
      const SolveReport r = solve(s.c.p, mu, u);
      ASSERT_TRUE(r.converged);
      expect_kkt(s.c.p, mu, u, kTol);
      EXPECT_LE(hctest::max_diff(u, s.u), 1e-8);
    }
    // And a warm start from the solution itself is already converged.
    std::vector<double> mu = s.mu;
    std::vector<Vec3> u;
    const SolveReport r = solve(s.c.p, mu, u);
    EXPECT_TRUE(r.converged);
    EXPECT_EQ(r.iterations, 0);
    EXPECT_EQ(mu, s.mu);
    EXPECT_LE(hctest::max_diff(u, s.u), 1e-14);    // same mu; u summed in another row order
  }
}

// ---------------------------------------------------------------------------------------
// Lemma 1 / Prop. 5: a hexagonal packing of equal discs (in the plane z = 0) pressed down onto
// the floor y = 0 has about 3 rows per disc but only 2 in-plane degrees of freedom: the
// multipliers are not unique, the velocities are.

namespace {

// rows x cols discs of radius 1; even rows at x = 1 + 2k, odd rows at x = 2 + 2k, row spacing
// sqrt(3), all moving down at 1. Rows for every touching pair and the floor; with side walls
// (x = 0 and x = 2 cols + 1) the packing is jammed.
ContactProblem hex_packing(int rows, int cols, bool side_walls, double h)
{
  std::vector<Vec3> q;
  for (int r = 0; r < rows; ++r)
    for (int k = 0; k < cols; ++k) q.emplace_back((r % 2 ? 2.0 : 1.0) + 2.0 * k, 1.0 + std::sqrt(3.0) * r, 0.0);
  const int n = static_cast<int>(q.size());
  ContactProblem p =
      hctest::make_problem(h, std::vector<double>(n, 1.0), std::vector<Vec3>(n, Vec3(0, -1, 0)));
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if ((q[j] - q[i]).norm() < 2.0 + 1e-9) hctest::add_pair(p, i, j, q[i], q[j], 1.0, 1.0);
  for (int i = 0; i < n; ++i) {
    if (q[i].y() < 1.0 + 1e-9) hctest::add_wall(p, i, q[i], 1.0, Vec3::Zero(), Vec3(0, 1, 0));
    if (side_walls && q[i].x() < 1.0 + 1e-9)
      hctest::add_wall(p, i, q[i], 1.0, Vec3::Zero(), Vec3(1, 0, 0));
    if (side_walls && q[i].x() > 2.0 * cols - 1e-9)
      hctest::add_wall(p, i, q[i], 1.0, Vec3(2.0 * cols + 1.0, 0, 0), Vec3(-1, 0, 0));
  }
  return p;
}

}    // namespace

TEST(UzawaLemma1, RedundantHexPackingUniqueVelocitiesNotMultipliers)
{
  for (bool side_walls : {true, false}) {
    SCOPED_TRACE(side_walls);
    const ContactProblem p = hex_packing(8, 8, side_walls, 0.1);
    const int n = p.n_bodies();
    // More rows than in-plane degrees of freedom; G^T has a kernel (dense rank).
    ASSERT_GT(p.n_contacts(), 2 * n);
    const Eigen::MatrixXd G = hctest::dense_G(p);
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(G);
    const int kernel = p.n_contacts() - static_cast<int>(qr.rank());
    EXPECT_GE(kernel, p.n_contacts() - 2 * n);

    std::vector<double> mu_a, mu_b(p.n_contacts());
    std::mt19937 gen(3);
    std::uniform_real_distribution<double> U(0.0, 200.0);
    for (double &x : mu_b) x = U(gen);
    std::vector<Vec3> u_a, u_b;
    const SolveReport ra = solve(p, mu_a, u_a, 1e-12);
    const SolveReport rb = solve(p, mu_b, u_b, 1e-12);
    ASSERT_TRUE(ra.converged) << ra.iterations << " " << ra.residual;
    ASSERT_TRUE(rb.converged) << rb.iterations << " " << rb.residual;
    expect_kkt(p, mu_a, u_a, 1e-12);
    expect_kkt(p, mu_b, u_b, 1e-12);
    // The same velocities, and so the same net contact force on every body ...
    EXPECT_LE(hctest::max_diff(u_a, u_b), 1e-9);
    // ... and those of an unrelated exact solver.
    EXPECT_LE(hctest::max_diff(u_a, hctest::pgs_solve(p, 20000)), 1e-8);
    if (side_walls) {
      // Jammed: nothing can move down, nothing can move sideways: u = 0.
      for (const Vec3 &v : u_a) EXPECT_LE(v.norm(), 1e-9);
    } else {
      // Open sides: the bottom discs are pushed apart, the pile spreads; it still cannot
      // go through the floor: every floor disc ends with u_y = 0 (gap 0, pushed by mu > 0).
      double spread = 0.0;
      for (const Vec3 &v : u_a) spread = std::max(spread, std::abs(v.x()));
      EXPECT_GT(spread, 1e-3);
      for (int c = 0; c < p.n_contacts(); ++c) {
        if (p.body_j[c] < 0 && mu_a[c] > 0.0) {
          EXPECT_NEAR(u_a[p.body_i[c]].y(), 0.0, 1e-9);
        }
      }
    }
    // The multipliers found from the two starts. In the jammed packing they differ by O(1):
    // two valid multiplier vectors (both pass the KKT check above) for one u, which is the
    // non-uniqueness of Lemma 1 / Prop. 5 made concrete. In the open packing the rows that
    // stay active are independent and the two coincide; only reported.
    double dmu = 0.0, mu_scale = 0.0;
    for (int c = 0; c < p.n_contacts(); ++c) {
      dmu = std::max(dmu, std::abs(mu_a[c] - mu_b[c]));
      mu_scale = std::max(mu_scale, mu_a[c]);
    }
    if (side_walls) {
      EXPECT_GT(dmu, 0.1 * mu_scale);
    }
    RecordProperty(side_walls ? "mu_difference_closed" : "mu_difference_open",
                   std::to_string(dmu / mu_scale));
    std::cout << "[ info ] hex packing " << (side_walls ? "closed" : "open") << ": " << n
              << " discs, " << p.n_contacts() << " rows, kernel of G^T " << kernel
              << ", max |mu_a - mu_b| / max mu = " << dmu / mu_scale << "\n";
  }
}

// ---------------------------------------------------------------------------------------
// The step size: Gershgorin bound of the dual operator (dual_operator.h).

TEST(StepSize, BoundsLargestEigenvalueWithinMaxDegree)
{
  SerialOps ops;
  for (unsigned seed = 10; seed < 16; ++seed) {
    SCOPED_TRACE(seed);
    RandomConfigOptions o;
    o.n = 120;
    o.box = 9.0;
    o.walls = (seed % 2 == 0);
    o.max_overlap = (seed % 3 == 0) ? 0.1 : 0.0;
    o.h = 0.05 * (1 + seed % 4);
    RandomConfig c = hctest::random_config(seed, o);
    if (seed == 15)    // a few immovable bodies (obstacles) too
      for (int b = 0; b < c.p.n_bodies(); b += 7) c.p.inv_mass[b] = 0.0;
    const ContactProblem &p = c.p;
    ASSERT_GT(p.n_contacts(), 100);
    const double L = hardcontact::dual_operator_bound(p, ops);
    const double lmax = hctest::lambda_max(hctest::dense_A(p));
    std::vector<int> deg(p.n_bodies(), 0);
    for (int r = 0; r < p.n_contacts(); ++r) {
      ++deg[p.body_i[r]];
      if (p.body_j[r] >= 0) ++deg[p.body_j[r]];
    }
    const int max_deg = *std::max_element(deg.begin(), deg.end());
    EXPECT_GE(L, lmax * (1.0 - 1e-12));
    EXPECT_LE(L, max_deg * lmax * (1.0 + 1e-12));
    // The same holds for the principal submatrix of any subset of rows (a working set).
    std::mt19937 gen(seed);
    for (int trial = 0; trial < 3; ++trial) {
      std::vector<int> rows;
      for (int c = 0; c < p.n_contacts(); ++c)
        if (gen() % 3 == 0) rows.push_back(c);
      const Eigen::MatrixXd A = hctest::dense_A(p);
      Eigen::MatrixXd sub(rows.size(), rows.size());
      for (size_t a = 0; a < rows.size(); ++a)
        for (size_t b = 0; b < rows.size(); ++b) sub(a, b) = A(rows[a], rows[b]);
      const double Ls = hardcontact::dual_operator_bound(p, rows, ops);
      const double ls = hctest::lambda_max(sub);
      EXPECT_GE(Ls, ls * (1.0 - 1e-12));
      EXPECT_LE(Ls, L * (1.0 + 1e-15));    // fewer rows, smaller bound
      EXPECT_LE(Ls, max_deg * ls * (1.0 + 1e-12));
    }
    // The solver's default step is 1 / bound of the rows it iterates on (its working set,
    // working_set.h: rows with a start multiplier > 0 or whose gap the free relative speed
    // can close within the step; with maxiter = 0 no row is added). It is never below 1/L.
    std::vector<int> initial;
    for (int c = 0; c < p.n_contacts(); ++c) {
      const int j = p.body_j[c];
      const Vec3 du = (j >= 0 ? p.u_free[j] : Vec3::Zero()) - p.u_free[p.body_i[c]];
      if (p.gap[c] <= p.h * du.norm()) initial.push_back(c);
    }
    std::vector<double> mu;
    std::vector<Vec3> u;
    SolveReport r = solve(p, mu, u, 1e-4, 0);
    EXPECT_DOUBLE_EQ(r.rho, 1.0 / hardcontact::dual_operator_bound(p, initial, ops));
    EXPECT_GE(r.rho, 1.0 / L);
    mu.clear();
    r = solve(p, mu, u, 1e-6);
    EXPECT_TRUE(r.converged);
    EXPECT_GE(r.rho, 1.0 / L);
  }
}

TEST(StepSize, MonodisperseLatticeMatchesRemark8)
{
  // Remark 8: equal masses m and kappa rows per body give 2 kappa h^2 / m. In the open hex
  // packing interior discs have kappa = 6 neighbours.
  const double h = 0.1;
  ContactProblem p = hex_packing(6, 6, false, h);
  for (double &w : p.inv_mass) w = 0.5;    // m = 2
  SerialOps ops;
  EXPECT_NEAR(hardcontact::dual_operator_bound(p, ops), 2 * 6 * h * h / 2.0, 1e-15);
  // No rows: bound 0, solver leaves u_free alone, converged, rho reported 0.
  ContactProblem empty = hctest::make_problem(h, {1.0, 1.0}, {Vec3(1, 2, 3), Vec3(-1, 0, 0)});
  EXPECT_EQ(hardcontact::dual_operator_bound(empty, ops), 0.0);
  std::vector<double> mu;
  std::vector<Vec3> u;
  const SolveReport r = solve(empty, mu, u);
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.rho, 0.0);
  EXPECT_EQ(u[0], empty.u_free[0]);
  EXPECT_EQ(u[1], empty.u_free[1]);
}

TEST(StepSize, RhoAboveTwoOverLambdaMaxDoesNotConverge)
{
  // Both ends of a chain of 8 equal touching discs pushed in: every row is active at the
  // solution, so near it the iteration is linear with factor 1 - rho lambda, and the bound on
  // rho matters: 1.9 / lambda_max converges, 2.2 / lambda_max does not.
  const int N = 8;
  const double h = 0.1;
  std::vector<Vec3> uf(N, Vec3::Zero());
  uf[0] = Vec3(1, 0, 0);
  uf[N - 1] = Vec3(-1, 0, 0);
  ContactProblem p = hctest::make_problem(h, std::vector<double>(N, 1.0), uf);
  for (int k = 0; k + 1 < N; ++k)
    hctest::add_pair(p, k, k + 1, Vec3(2.0 * k, 0, 0), Vec3(2.0 * k + 2, 0, 0), 1.0, 1.0);
  const double lmax = hctest::lambda_max(hctest::dense_A(p));

  std::vector<double> mu;
  std::vector<Vec3> u;
  SolveReport r = solve(p, mu, u, 1e-10, 100000, 1.9 / lmax);
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.rho, 1.9 / lmax);
  for (const Vec3 &v : u) EXPECT_NEAR(v.x(), 0.0, 1e-8);

  mu.clear();
  r = solve(p, mu, u, 1e-10, 100000, 2.2 / lmax);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.iterations, 100000);
  EXPECT_GT(r.residual, 1e-3);

  // Isolated pair: rho = 1/A is exact in one step, 2.5/A cycles for ever.
  ContactProblem pair = hctest::make_problem(h, {1.0, 1.0}, {Vec3(1, 0, 0), Vec3(-1, 0, 0)});
  hctest::add_pair(pair, 0, 1, Vec3(0, 0, 0), Vec3(2, 0, 0), 1.0, 1.0);
  const double a = h * h * 2.0;
  mu.clear();
  r = solve(pair, mu, u, 1e-10, 1000, 2.5 / a);
  EXPECT_FALSE(r.converged);
  EXPECT_GT(r.residual, 0.01);
}
