// Uzawa (section 3.3) on configurations whose answer is known from mechanics alone: a pair
// of spheres (restitution 0, no friction: the normal velocities become equal, or just close
// the gap; the tangential ones are untouched; momentum is conserved), a sphere on a wall or on
// an immovable body, and chains of touching spheres (perfectly inelastic: one common velocity,
// total momentum / total mass), checked against pool-adjacent-violators as an exact oracle.
#include "uzawa.h"

#include "core_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace hardcontact;
using hctest::add_pair;
using hctest::add_wall;
using hctest::make_problem;

namespace {

constexpr double kEps = 2.220446049250313e-16;

SolveReport run_uzawa(const ContactProblem &p, std::vector<double> &mu, std::vector<Vec3> &u,
                      double tol = 1e-13, int maxiter = 1000000)
{
  Uzawa solver;
  SerialOps ops;
  SolverSettings s;
  s.tol = tol;
  s.maxiter = maxiter;
  return solver.solve(p, s, ops, mu, u);
}

// A pair that does not meet within the step, started from the multiplier mu0: the answer is the
// free motion exactly and the multiplier 0 (the force cannot pull).
SolveReport expect_free_motion_from(const ContactProblem &p, double mu0)
{
  std::vector<double> mu{mu0};
  std::vector<Vec3> u;
  const SolveReport r = run_uzawa(p, mu, u);
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(mu[0], 0.0);
  EXPECT_EQ(u[0], p.u_free[0]);
  EXPECT_EQ(u[1], p.u_free[1]);
  return r;
}

Vec3 tangential(const Vec3 &v, const Vec3 &n) { return v - v.dot(n) * n; }

// Two spheres of masses mi, mj, radii 1 (size 2), centres along the unit vector n with the
// given gap, free velocities vi, vj. Expectations from mechanics only:
//  - free predicted gap g0 = gap + h n.(vj - vi) >= 0: nothing happens (mu = 0, 0 updates);
//  - otherwise the normal relative velocity after the step is exactly -gap/h (the pair just
//    closes the gap: restitution 0), the normal momentum P = mi vn_i + mj vn_j is kept, so
//    vn_i' = (P + mj gap/h) / (mi + mj), vn_j' = (P - mi gap/h) / (mi + mj) (for gap = 0: the
//    momentum-weighted mean), tangential components are unchanged, and the impulse h mu is
//    the normal momentum given by j to i: h mu = mi (vn_i - vn_i').
void check_pair(double mi, double mj, const Vec3 &n_in, double gap, const Vec3 &vi,
                const Vec3 &vj, double h)
{
  const Vec3 n = n_in.normalized();
  const Vec3 qi(0.3, -0.2, 0.1);
  const Vec3 qj = qi + (2.0 + gap) * n;
  ContactProblem p = make_problem(h, {1.0 / mi, 1.0 / mj}, {vi, vj});
  add_pair(p, 0, 1, qi, qj, 1.0, 1.0);
  ASSERT_NEAR(p.gap[0], gap, 1e-14);
  // Expectations use the gap as computed from the centres (it differs from the nominal one
  // by round-off, which the division by h would amplify).
  gap = p.gap[0];

  std::vector<double> mu;
  std::vector<Vec3> u;
  const SolveReport r = run_uzawa(p, mu, u);
  ASSERT_TRUE(r.converged);
  ASSERT_EQ(mu.size(), 1u);
  ASSERT_EQ(u.size(), 2u);

  const double vni = vi.dot(n), vnj = vj.dot(n);
  const double g0 = gap + h * (vnj - vni);
  const double scale = std::abs(vni) + std::abs(vnj) + std::abs(gap / h);

  // Untouched when the free motion keeps the pair apart (up to the solver tolerance, here
  // 1e-13 * size: a touching pair's gap computed from centres is 0 only to round-off).
  if (g0 >= -1e-13 * p.size[0]) {
    EXPECT_EQ(mu[0], 0.0);
    EXPECT_EQ(r.iterations, 0);
    EXPECT_EQ(u[0], vi);
    EXPECT_EQ(u[1], vj);
    return;
  }
  const double M = mi + mj, P = mi * vni + mj * vnj;
  const double ui_n = (P + mj * gap / h) / M, uj_n = (P - mi * gap / h) / M;
  EXPECT_NEAR(u[0].dot(n), ui_n, 64 * kEps * scale);
  EXPECT_NEAR(u[1].dot(n), uj_n, 64 * kEps * scale);
  EXPECT_LE((tangential(u[0], n) - tangential(vi, n)).norm(), 8 * kEps * (vi.norm() + scale));
  EXPECT_LE((tangential(u[1], n) - tangential(vj, n)).norm(), 8 * kEps * (vj.norm() + scale));
  // The pair ends the step exactly in contact: not overlapping, not apart.
  EXPECT_GE(p.predicted_gap(0, u), -1e-13 * p.size[0]);
  EXPECT_NEAR(p.predicted_gap(0, u), 0.0, 1e-13 * p.size[0]);
  // Momentum, all three components, to round-off.
  const Vec3 dP = mi * u[0] + mj * u[1] - (mi * vi + mj * vj);
  EXPECT_LE(dP.norm(), 8 * kEps * (mi * vi.norm() + mj * vj.norm() + M * scale));
  // The multiplier is the contact force: impulse = momentum transferred (and it pushes).
  EXPECT_GT(mu[0], 0.0);
  EXPECT_NEAR(h * mu[0], mi * (vni - ui_n), 16 * kEps * M * scale);
  // rho = 1/L is exact for an isolated pair: one multiplier update.
  EXPECT_EQ(r.iterations, 1);
}

}    // namespace

TEST(UzawaPair, HeadOnEqualMassesTouchingStopBoth)
{
  // Equal and opposite: the momentum-weighted normal velocity is 0.
  check_pair(1.0, 1.0, Vec3(1, 0, 0), 0.0, Vec3(1, 0, 0), Vec3(-1, 0, 0), 0.1);
}

TEST(UzawaPair, HeadOnEqualMassesOneAtRest)
{
  check_pair(2.0, 2.0, Vec3(0, 0, 1), 0.0, Vec3(0, 0, 3), Vec3(0, 0, 0), 0.05);
}

TEST(UzawaPair, HeadOnUnequalMasses)
{
  // m 1 at +5 onto m 4 at rest: common normal velocity 5 * 1/5 = 1.
  ContactProblem p = make_problem(0.01, {1.0, 0.25}, {Vec3(5, 0, 0), Vec3(0, 0, 0)});
  add_pair(p, 0, 1, Vec3(0, 0, 0), Vec3(2, 0, 0), 1.0, 1.0);
  std::vector<double> mu;
  std::vector<Vec3> u;
  ASSERT_TRUE(run_uzawa(p, mu, u).converged);
  EXPECT_NEAR(u[0].x(), 1.0, 1e-14);
  EXPECT_NEAR(u[1].x(), 1.0, 1e-14);
  EXPECT_NEAR(0.01 * mu[0], 4.0, 1e-13);    // impulse = 4 units of momentum
  check_pair(1.0, 4.0, Vec3(1, 0, 0), 0.0, Vec3(5, 0, 0), Vec3(0, 0, 0), 0.01);
  check_pair(1000.0, 1.0, Vec3(1, 0, 0), 0.0, Vec3(0.5, 0, 0), Vec3(-2, 0, 0), 0.2);
}

TEST(UzawaPair, ObliqueIn3DKeepsTangentialVelocities)
{
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  std::uniform_real_distribution<double> logm(0.0, 3.0);
  for (int trial = 0; trial < 50; ++trial) {
    const Vec3 n(U(gen), U(gen), U(gen));
    if (n.norm() < 0.1) continue;
    const Vec3 nn = n.normalized();
    // Tangential parts random; normal parts approaching (i towards j).
    const Vec3 vi = Vec3(U(gen), U(gen), U(gen)) + (1.0 + std::abs(U(gen))) * nn;
    const Vec3 vj = Vec3(U(gen), U(gen), U(gen)) - (1.0 + std::abs(U(gen))) * nn;
    const double mi = std::pow(10.0, logm(gen)), mj = std::pow(10.0, logm(gen));
    SCOPED_TRACE(trial);
    check_pair(mi, mj, n, 0.0, vi, vj, 0.1);
  }
}

TEST(UzawaPair, ApproachingWithGapJustClosesIt)
{
  // Gap 0.05 closed at relative speed 2 within h = 0.1: the relative normal velocity becomes
  // -gap/h = -0.5 (not 0: the scheme lets them meet exactly at the end of the step).
  check_pair(1.0, 1.0, Vec3(1, 0, 0), 0.05, Vec3(1, 0, 0), Vec3(-1, 0, 0), 0.1);
  check_pair(3.0, 7.0, Vec3(1, 2, -1), 0.05, Vec3(1, 0.5, 0), Vec3(-1, 0, 0.3), 0.1);
  // Overlapping pair (gap < 0) approaching: pushed apart at gap/h relative velocity.
  check_pair(1.0, 2.0, Vec3(0, 1, 0), -0.02, Vec3(0, 0.1, 0), Vec3(0, 0, 0), 0.1);
}

TEST(UzawaPair, SeparatingOrOutOfReachPairIsUntouched)
{
  // Touching and separating.
  check_pair(1.0, 1.0, Vec3(1, 0, 0), 0.0, Vec3(-1, 0, 0), Vec3(1, 0, 0), 0.1);
  // Touching, same velocity (no relative motion).
  check_pair(1.0, 5.0, Vec3(1, 1, 0), 0.0, Vec3(0.3, 0.2, 0.1), Vec3(0.3, 0.2, 0.1), 0.1);
  // Approaching but too far to meet within the step: gap 0.5 > h * 2 = 0.2.
  check_pair(1.0, 1.0, Vec3(1, 0, 0), 0.5, Vec3(1, 0, 0), Vec3(-1, 0, 0), 0.1);
  // Overlapping but separating fast enough to be clear at the end of the step.
  check_pair(1.0, 1.0, Vec3(0, 0, 1), -0.01, Vec3(0, 0, -1), Vec3(0, 0, 1), 0.1);

  // Report and multipliers explicitly, with a warm start of 0.
  ContactProblem p = make_problem(0.1, {1.0, 1.0}, {Vec3(-1, 0, 0), Vec3(1, 0, 0)});
  add_pair(p, 0, 1, Vec3(0, 0, 0), Vec3(2, 0, 0), 1.0, 1.0);
  const SolveReport r = expect_free_motion_from(p, 0.0);
  EXPECT_EQ(r.iterations, 0);
  EXPECT_EQ(r.residual, 0.0);
}

TEST(UzawaPair, StaleWarmStartOnSeparatingPairIsReleased)
{
  // A positive start multiplier on a pair that now separates must be dropped to 0, giving back
  // u_free exactly (the force cannot pull).
  ContactProblem p = make_problem(0.1, {1.0, 0.5}, {Vec3(-1, 0, 0), Vec3(1, 0, 0)});
  add_pair(p, 0, 1, Vec3(0, 0, 0), Vec3(2, 0, 0), 1.0, 1.0);
  expect_free_motion_from(p, 50.0);
}

// A sphere of radius r above a wall: after the step n.u = gap/h towards the wall at most, i.e.
// the sphere just reaches the wall, whatever its mass; tangential velocity kept.
TEST(UzawaWall, SphereOntoWallJustReachesIt)
{
  const double h = 0.1, r = 0.5;
  struct Case {
    Vec3 nw, x0;    // plane normal into the domain, a point of the plane
    double gap;
    Vec3 v;
    double mass;
  };
  const Case cases[] = {
      {Vec3(0, 0, 1), Vec3(0, 0, 0), 0.0, Vec3(0.3, -0.2, -2.0), 1.0},       // resting on it
      {Vec3(0, 0, 1), Vec3(0, 0, 0), 0.05, Vec3(0.3, -0.2, -2.0), 1000.0},    // arriving
      {Vec3(1, -1, 2).normalized(), Vec3(1, 2, 3), 0.01, Vec3(-1, 1, -1), 7.0},
      {Vec3(0, 0, 1), Vec3(0, 0, 0), -0.03, Vec3(0.1, 0, 0), 2.0},    // overlapping: pushed out
  };
  for (const Case &c : cases) {
    SCOPED_TRACE(c.gap);
    const Vec3 q = c.x0 + Vec3(0.7, -0.4, 0.2).cross(c.nw) + (r + c.gap) * c.nw;
    ContactProblem p = make_problem(h, {1.0 / c.mass}, {c.v});
    add_wall(p, 0, q, r, c.x0, c.nw);
    ASSERT_NEAR(p.gap[0], c.gap, 1e-14);
    std::vector<double> mu;
    std::vector<Vec3> u;
    const SolveReport rep = run_uzawa(p, mu, u);
    ASSERT_TRUE(rep.converged);
    // Component along the wall normal: -gap/h (towards the wall by exactly the gap).
    EXPECT_NEAR(u[0].dot(c.nw), -c.gap / h, 1e-13);
    EXPECT_LE((tangential(u[0], c.nw) - tangential(c.v, c.nw)).norm(), 1e-14);
    EXPECT_NEAR(p.predicted_gap(0, u), 0.0, 1e-13 * r);
    // The wall pushes (mu > 0) with the impulse that took the normal momentum away.
    EXPECT_NEAR(h * mu[0], c.mass * (u[0] - c.v).dot(c.nw), 1e-12 * c.mass);
    EXPECT_GT(mu[0], 0.0);
  }
}

TEST(UzawaWall, SphereLeavingWallIsUntouched)
{
  ContactProblem p = make_problem(0.1, {1.0}, {Vec3(1, 2, 0.5)});
  add_wall(p, 0, Vec3(0, 0, 0.5), 0.5, Vec3(0, 0, 0), Vec3(0, 0, 1));
  std::vector<double> mu;
  std::vector<Vec3> u;
  const SolveReport r = run_uzawa(p, mu, u);
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.iterations, 0);
  EXPECT_EQ(mu[0], 0.0);
  EXPECT_EQ(u[0], p.u_free[0]);
}

TEST(UzawaWall, ImmovableBodyActsLikeAMovingWall)
{
  // Body 1 has inv_mass 0 and a prescribed velocity V (an obstacle). Sphere 0 hits it: the
  // obstacle keeps V exactly, the sphere ends with the obstacle's normal velocity (minus
  // gap/h), tangential velocity kept.
  const double h = 0.05;
  const Vec3 n = Vec3(1, 1, 0).normalized();
  const Vec3 V(0.2, -0.1, 0.4), v(3, 1, -1);
  for (double gap : {0.0, 0.01}) {
    ContactProblem p = make_problem(h, {0.5, 0.0}, {v, V});
    add_pair(p, 0, 1, Vec3(0, 0, 0), (2.0 + gap) * n, 1.0, 1.0);
    std::vector<double> mu;
    std::vector<Vec3> u;
    ASSERT_TRUE(run_uzawa(p, mu, u).converged);
    EXPECT_EQ(u[1], V);
    EXPECT_NEAR(u[0].dot(n), V.dot(n) + gap / h, 1e-13);
    EXPECT_LE((tangential(u[0], n) - tangential(v, n)).norm(), 1e-14);
  }
}

namespace {

// N spheres of radius 1 on a line along e, neighbours at the given gaps, one row per
// neighbour pair (in 1D only neighbours can meet first, Remark 1 / Remark 7).
ContactProblem chain(const std::vector<double> &mass, const std::vector<double> &gaps,
                     const std::vector<Vec3> &u_free, const Vec3 &e, double h)
{
  std::vector<double> w;
  for (double m : mass) w.push_back(1.0 / m);
  ContactProblem p = make_problem(h, w, u_free);
  Vec3 q = Vec3(1.0, -2.0, 0.5);
  for (size_t k = 0; k + 1 < mass.size(); ++k) {
    const Vec3 qn = q + (2.0 + gaps[k]) * e;
    add_pair(p, static_cast<int>(k), static_cast<int>(k + 1), q, qn, 1.0, 1.0);
    q = qn;
  }
  return p;
}

}    // namespace

TEST(UzawaChain, FirstOfEqualTouchingSpheresStruckAllLeaveWithVOverN)
{
  const double v = 1.7, h = 0.1;
  const Vec3 e = Vec3(2, -1, 1).normalized();
  for (int N : {2, 3, 5, 10, 20}) {
    SCOPED_TRACE(N);
    std::vector<Vec3> uf(N, Vec3::Zero());
    uf[0] = v * e;
    ContactProblem p = chain(std::vector<double>(N, 3.0), std::vector<double>(N - 1, 0.0), uf, e, h);
    std::vector<double> mu;
    std::vector<Vec3> u;
    const SolveReport r = run_uzawa(p, mu, u);
    ASSERT_TRUE(r.converged) << r.iterations << " " << r.residual;
    for (int k = 0; k < N; ++k) EXPECT_LE((u[k] - (v / N) * e).norm(), 1e-10 * v) << k;
    const Vec3 dP = hctest::momentum(p, u) - hctest::momentum(p, uf);
    EXPECT_LE(dP.norm(), 64 * kEps * 3.0 * v);
    for (double m : mu) EXPECT_GE(m, 0.0);
  }
}

TEST(UzawaChain, UnequalMassesCommonVelocityIsTotalMomentumOverTotalMass)
{
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> logm(0.0, 3.0);    // masses 1 .. 1000
  const Vec3 e(1, 0, 0);
  const int N = 12;
  std::vector<double> m(N);
  for (double &x : m) x = std::pow(10.0, logm(gen));
  // Struck at the first body, and squeezed from both ends: every neighbour pair approaches,
  // so all merge (restitution 0) into one body of velocity P / M.
  for (int variant = 0; variant < 2; ++variant) {
    std::vector<Vec3> uf(N, Vec3::Zero());
    uf[0] = Vec3(2.0, 0.3, 0.0);    // y component: tangential, must survive
    if (variant == 1) uf[N - 1] = Vec3(-5.0, 0.0, -0.2);
    double P = 0.0, M = 0.0, pmax = 0.0;
    for (int k = 0; k < N; ++k) {
      P += m[k] * uf[k].x();
      M += m[k];
      pmax = std::max(pmax, m[k] * uf[k].norm());
    }
    ContactProblem p = chain(m, std::vector<double>(N - 1, 0.0), uf, e, 0.1);
    std::vector<double> mu;
    std::vector<Vec3> u;
    const SolveReport r = run_uzawa(p, mu, u);
    ASSERT_TRUE(r.converged) << r.iterations << " " << r.residual;
    for (int k = 0; k < N; ++k) {
      EXPECT_NEAR(u[k].x(), P / M, 1e-10) << k;
      EXPECT_EQ(u[k].y(), uf[k].y());
      EXPECT_EQ(u[k].z(), uf[k].z());
    }
    EXPECT_LE((hctest::momentum(p, u) - hctest::momentum(p, uf)).norm(), 1e-13 * pmax * N);
  }
}

TEST(UzawaChain, ArbitraryVelocitiesAndGapsMatchPoolAdjacentViolators)
{
  // General 1D chains: some pairs merge, some separate, some just close their gap. The exact
  // projection is the isotonic regression of u + (cumulative gap)/h (core_test_util.h).
  std::mt19937 gen(21);
  std::uniform_real_distribution<double> U(-1.0, 1.0), logm(0.0, 3.0), G(0.0, 0.2);
  const double h = 0.1;
  for (int trial = 0; trial < 20; ++trial) {
    SCOPED_TRACE(trial);
    const int N = 30;
    std::vector<double> m(N), gaps(N - 1), ufx(N);
    for (double &x : m) x = std::pow(10.0, logm(gen));
    for (double &x : gaps) x = (U(gen) < 0.0) ? 0.0 : G(gen);
    for (double &x : ufx) x = 2.0 * U(gen);
    std::vector<Vec3> uf(N);
    for (int k = 0; k < N; ++k) uf[k] = Vec3(ufx[k], U(gen), U(gen));
    ContactProblem p = chain(m, gaps, uf, Vec3(1, 0, 0), h);
    std::vector<double> mu;
    std::vector<Vec3> u;
    const SolveReport r = run_uzawa(p, mu, u, 1e-13, 5000000);
    ASSERT_TRUE(r.converged) << r.iterations << " " << r.residual;
    const std::vector<double> ref = hctest::chain_projection(ufx, gaps, m, h);
    for (int k = 0; k < N; ++k) {
      EXPECT_NEAR(u[k].x(), ref[k], 1e-9) << k;
      EXPECT_EQ(u[k].y(), uf[k].y());
      EXPECT_EQ(u[k].z(), uf[k].z());
    }
  }
}
