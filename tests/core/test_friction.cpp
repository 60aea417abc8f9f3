// Coulomb friction (laws/coulomb.h) in the core, against analytic single-step outcomes:
//  - a sphere sliding on a floor loses mu g h of speed per step and spins up by
//    5 mu g h / (2 r), with no lift-off (De Saxce's shift at its fixed point);
//  - a slow sphere sticks: it leaves the step rolling at 5/7 of its speed;
//  - an oblique pair: tangential impulse <= mu x normal impulse, sticking below and sliding
//    above the analytic threshold v_t / v_n = 7/2 mu; linear and angular momentum exact;
//  - random packings: hybrid, apgd, pgs, uzawa and nsgs agree, kinetic energy (spins included) never grows,
//    no overlap, every multiplier in its cone; under the convex cone too (and its lift-off is
//    mu |slip|), and the lagged cone is the exact law from the exact answer and from rest;
//    nsgs solves the exact law under the lagged cone from a warm start whose caps are not it.
#include "core_test_util.h"
#include "random_config.h"

#include "solver.h"
#include "laws/rolling.h"

#include <random>

#include <gtest/gtest.h>

#include <cmath>

namespace {

using hardcontact::ContactProblem;
using hardcontact::SerialOps;
using hardcontact::SolverSettings;
using hardcontact::Vec3;

using hctest::add_friction;

struct Solved {
  std::vector<double> mu;
  std::vector<Vec3> u;
  hardcontact::SolveReport report;
};

Solved solve(const ContactProblem &p, const std::string &name, double tol = 1e-8,
             SolverSettings::Cone cone = SolverSettings::Cone::Lagged,
             const std::vector<double> &warm = {})
{
  auto solver = hardcontact::make_solver(name, hardcontact::ContactLaw::Coulomb);
  EXPECT_TRUE(solver) << name;
  SerialOps ops;
  SolverSettings s;
  s.tol = tol;
  s.cone = cone;
  s.maxiter = 200000;
  Solved out;
  out.mu = warm;
  out.report = solver->solve(p, s, ops, out.mu, out.u);
  if (getenv("HC_VERBOSE")) printf("%s it %d res %g\n", name.c_str(), out.report.iterations, out.report.residual);
  EXPECT_TRUE(out.report.converged) << name << " residual " << out.report.residual;
  return out;
}

// One sphere of mass 1, radius r on the floor z = 0, moving along x at v0 with no spin.
ContactProblem sphere_on_floor(double v0, double mu, double h, double g, double r)
{
  ContactProblem p = hctest::make_problem(h, {1.0}, {Vec3(v0, 0.0, -g * h)});
  hctest::add_wall(p, 0, Vec3(0.0, 0.0, r), r, Vec3::Zero(), Vec3(0.0, 0.0, 1.0));
  add_friction(p, {r}, mu);
  return p;
}

TEST(Friction, SlidingSphereDeceleratesAndSpinsUp)
{
  const double h = 0.01, g = 1.0, r = 0.5, mu = 0.3, v0 = 1.0;
  for (const char *name : {"hybrid", "apgd", "pgs", "uzawa", "nsgs"}) {
    const ContactProblem p = sphere_on_floor(v0, mu, h, g, r);
    const Solved s = solve(p, name);
    const Vec3 u = s.u[0], w = s.u[1];
    EXPECT_NEAR(u.z(), 0.0, 1e-9) << name;                        // no lift-off, no sinking
    EXPECT_NEAR(s.mu[0], g, 1e-7) << name;                        // normal force m g
    EXPECT_NEAR(u.x(), v0 - mu * g * h, 1e-9) << name;            // Coulomb: mu m g
    EXPECT_NEAR(w.y(), 5.0 * mu * g * h / (2.0 * r), 1e-8) << name;
    EXPECT_NEAR(u.y(), 0.0, 1e-12) << name;
    EXPECT_NEAR(std::hypot(s.mu[1], s.mu[2]), mu * s.mu[0], 1e-9) << name;
  }
}

TEST(Friction, SlowSphereSticksAndRolls)
{
  const double h = 0.01, g = 1.0, r = 0.5, mu = 0.5;
  const double v0 = 0.5 * 3.5 * mu * g * h;    // half the speed one step of friction can stop
  for (const char *name : {"hybrid", "apgd", "pgs", "uzawa", "nsgs"}) {
    const ContactProblem p = sphere_on_floor(v0, mu, h, g, r);
    const Solved s = solve(p, name, 1e-10);
    EXPECT_NEAR(s.u[0].x(), 5.0 / 7.0 * v0, 1e-9) << name;
    EXPECT_NEAR(s.u[1].y() * r, s.u[0].x(), 1e-9) << name;    // rolling: no slip
    EXPECT_LT(std::hypot(s.mu[1], s.mu[2]), mu * s.mu[0]) << name;
  }
}

// Two equal spheres touching along x; sphere 0 moves at (vn, vt) against sphere 1 at rest.
TEST(Friction, ObliquePairStickBelowSlideAboveThreshold)
{
  const double h = 0.05, r = 0.5, mu = 0.4, vn = 1.0;
  for (const double ratio : {0.5, 2.0}) {    // v_t / v_n against the threshold 7/2 mu
    const double vt = ratio * 3.5 * mu * vn;
    const std::vector<Vec3> q = {Vec3::Zero(), Vec3(2 * r, 0.0, 0.0)};
    ContactProblem p =
        hctest::make_problem(h, {1.0, 1.0}, {Vec3(vn, vt, 0.0), Vec3::Zero()});
    hctest::add_pair(p, 0, 1, q[0], q[1], r, r);
    add_friction(p, {r, r}, mu);
    for (const char *name : {"hybrid", "apgd", "pgs", "uzawa", "nsgs"}) {
      const Solved s = solve(p, name, 1e-10);
      const double jn = s.mu[0], jt = std::hypot(s.mu[1], s.mu[2]);
      EXPECT_NEAR(jn * h, 0.5 * vn, 1e-9) << name;    // inelastic: m_red v_n
      EXPECT_LE(jt, mu * jn * (1.0 + 1e-9)) << name;
      const Vec3 slip = p.slip_velocity(0, s.u);
      if (ratio < 1.0) {
        EXPECT_NEAR(jt * h, vt / 7.0, 1e-9) << name;    // sticks: slip stopped
        EXPECT_NEAR(slip.y(), 0.0, 1e-9) << name;
      } else {
        EXPECT_NEAR(jt, mu * jn, 1e-9 * jn) << name;    // slides: on the cone
        EXPECT_LT(slip.y(), 0.0) << name;    // slip v_j - v_i keeps its sign
      }
      // momentum and angular momentum about the origin (I w + m x cross v)
      const Vec3 P = s.u[0] + s.u[1];
      EXPECT_NEAR((P - Vec3(vn, vt, 0.0)).norm(), 0.0, 1e-13) << name;
      const double I = 0.4 * r * r;
      const Vec3 L = q[0].cross(s.u[0]) + q[1].cross(s.u[1]) + I * (s.u[2] + s.u[3]);
      EXPECT_NEAR((L - q[0].cross(Vec3(vn, vt, 0.0))).norm(), 0.0, 1e-13) << name;
    }
  }
}

// A pair that closes within the step (gap > 0 at q^n): the impulses act at the contact point
// between the centres (arms in the ratio of the radii), so angular momentum about any point
// stays exact.
TEST(Friction, AngularMomentumExactForAClosingPair)
{
  const double h = 0.1, mu = 0.8;
  const std::vector<double> r = {0.5, 0.3};
  const std::vector<Vec3> q = {Vec3(0.1, -0.2, 0.3), Vec3(0.1 + 0.9, -0.2 + 0.05, 0.3)};
  ContactProblem p = hctest::make_problem(h, {1.0, 0.4}, {Vec3(2.0, 1.0, -0.5), Vec3(-1, 0, 0.3)});
  hctest::add_pair(p, 0, 1, q[0], q[1], r[0], r[1]);
  ASSERT_GT(p.gap[0], 0.0);
  add_friction(p, r, mu, {Vec3(1.0, -2.0, 0.5), Vec3(0.0, 3.0, 1.0)});
  const double I0 = 0.4 * r[0] * r[0] / p.inv_mass[0], I1 = 0.4 * r[1] * r[1] / p.inv_mass[1];
  auto angular = [&](const std::vector<Vec3> &u, const std::vector<Vec3> &w) {
    return Vec3(q[0].cross(u[0]) / p.inv_mass[0] + q[1].cross(u[1]) / p.inv_mass[1] + I0 * w[0] +
                I1 * w[1]);
  };
  const Vec3 L0 = angular(p.u_free, std::vector<Vec3>(p.u_free.begin() + p.n_bodies(), p.u_free.end()));
  for (const char *name : {"hybrid", "apgd", "pgs", "uzawa", "nsgs"}) {
    const Solved s = solve(p, name, 1e-10);
    ASSERT_GT(s.mu[0], 0.0) << name;
    const Vec3 L = angular({s.u[0], s.u[1]}, {s.u[2], s.u[3]});
    EXPECT_NEAR((L - L0).norm(), 0.0, 1e-14 * L0.norm()) << name;
  }
}

double kinetic2(const ContactProblem &p, const std::vector<Vec3> &u)
{
  const int n = p.n_bodies();
  double e = 0.0;
  for (int b = 0; b < n; ++b) {
    e += u[b].squaredNorm() / p.inv_mass[b];
    e += u[n + b].squaredNorm() / p.inv_inertia[b];
  }
  return e;
}

// 60 spheres of a random packing (masses over a decade), each spinning, friction mu on every
// row; e_free: the kinetic energy (spins included) of the free motion.
struct SpinningPacking {
  hctest::RandomConfig c;
  double e_free;
};
SpinningPacking spinning_packing(unsigned seed, double mu)
{
  hctest::RandomConfigOptions o;
  o.n = 60;
  o.box = 6.0;
  o.mass_decades = 1.0;
  SpinningPacking k{hctest::random_config(seed, o), 0.0};
  std::vector<Vec3> w(k.c.p.n_bodies());
  for (int b = 0; b < k.c.p.n_bodies(); ++b) w[b] = Vec3(std::sin(b), std::cos(3 * b), 0.5);
  add_friction(k.c.p, k.c.r, mu, w);
  std::vector<Vec3> u_free(k.c.p.u_free);
  u_free.insert(u_free.end(), w.begin(), w.end());
  k.e_free = kinetic2(k.c.p, u_free);
  return k;
}

TEST(Friction, SolversAgreeOnRandomPackings)
{
  const double tol = getenv("HC_TOL") ? atof(getenv("HC_TOL")) : 1e-7;
  for (unsigned seed : {3u, 11u}) {
    const SpinningPacking k = spinning_packing(seed, 0.5);
    const hctest::RandomConfig &c = k.c;
    const double e_free = k.e_free;
    const Solved a = solve(c.p, "apgd", tol);
    for (const char *name : {"hybrid", "apgd", "pgs", "uzawa", "nsgs"}) {
      const Solved s = solve(c.p, name, tol);
      EXPECT_LE(kinetic2(c.p, s.u), e_free * (1.0 + 1e-12)) << name;
      double worst = 0.0;
      for (size_t d = 0; d < s.u.size(); ++d) worst = std::max(worst, (s.u[d] - a.u[d]).norm());
      EXPECT_LT(worst, 1e-5) << name << " seed " << seed;
      for (int r = 0; r < c.p.n_contacts(); ++r) {
        // the law within tol of the scale, and the shifts within tol of their fixed point
        EXPECT_GE(c.p.predicted_gap(r, s.u), -2.0 * tol * c.p.size[r]) << name;
        EXPECT_LE(std::hypot(s.mu[3 * r + 1], s.mu[3 * r + 2]), 0.5 * s.mu[3 * r] * (1 + 1e-12) + 1e-300) << s.mu[3 * r];
      }
    }
  }
}

// The cones (SolverSettings::Cone) on the random packings:
//  - convex (no shift): every solver reaches the same answer, the relaxation's: no overlap,
//    and every pushing contact's gap at least mu |slip| h (its lift-off), energy never grows;
//  - lagged from the exact answer as its warm start: the caps are the exact shifts, so the
//    answer is the exact one (Coulomb's law wherever the slip does not grow);
//  - lagged from a cold start is exact: a contact that did not push has no cap;
//  - lagged from another problem's answer: no overlap, and no pushing contact lifts off by
//    more than 3 tol of its scale.
TEST(Friction, ConesOnRandomPackings)
{
  using Cone = SolverSettings::Cone;
  const double tol = 1e-7, mu = 0.5;
  for (unsigned seed : {3u, 11u}) {
    const SpinningPacking k = spinning_packing(seed, mu);
    const hctest::RandomConfig &c = k.c;
    const double e_free = k.e_free;
    const Solved convex = solve(c.p, "apgd", tol, Cone::Convex);
    const Solved exact = solve(c.p, "apgd", tol, Cone::Exact);
    double lift = 0.0;    // the relaxation's largest lift-off: it differs from Coulomb's law
    for (const char *name : {"hybrid", "apgd", "pgs", "uzawa", "nsgs"}) {
      const Solved s = solve(c.p, name, tol, Cone::Convex);
      EXPECT_LE(kinetic2(c.p, s.u), e_free * (1.0 + 1e-12)) << name;
      double worst = 0.0;
      for (size_t d = 0; d < s.u.size(); ++d) worst = std::max(worst, (s.u[d] - convex.u[d]).norm());
      EXPECT_LT(worst, 1e-5) << name << " seed " << seed;
      for (int r = 0; r < c.p.n_contacts(); ++r) {
        const double gap = c.p.predicted_gap(r, s.u);
        const Vec3 v = c.p.slip_velocity(r, s.u);
        const double slip = c.p.h * (v - v.dot(c.p.normal[r]) * c.p.normal[r]).norm();
        EXPECT_GE(gap, -2.0 * tol * c.p.size[r]) << name;
        if (s.mu[3 * r] > 1e-6) {
          EXPECT_NEAR(gap, mu * slip, 1e-5 * c.p.size[r]) << name << " row " << r;
          lift = std::max(lift, gap / c.p.size[r]);
        }
      }
    }
    EXPECT_GT(lift, 1e-3) << "seed " << seed;    // the relaxation is not Coulomb's law here
    double off = 0.0;
    for (size_t d = 0; d < exact.u.size(); ++d) off = std::max(off, (exact.u[d] - convex.u[d]).norm());
    EXPECT_GT(off, 1e-3) << "seed " << seed;
    // a warm start from another problem (half the free velocities): slips grow beyond what it
    // predicts, and a pushing contact may lift off by at most 3 tol of its scale (<= size)
    ContactProblem half = c.p;
    for (auto &v : half.u_free) v *= 0.5;    // the velocities and the spins
    const Solved other = solve(half, "apgd", tol, Cone::Exact);
    // (nsgs: its sweeps solve Coulomb's law itself under either cone)
    for (const char *name : {"hybrid", "apgd", "pgs", "uzawa"}) {
      const Solved s = solve(c.p, name, tol, Cone::Lagged, other.mu);
      for (int r = 0; r < c.p.n_contacts(); ++r) {
        const double gap = c.p.predicted_gap(r, s.u);
        EXPECT_GE(gap, -2.0 * tol * c.p.size[r]) << name;
        if (s.mu[3 * r] > 0.0) {
          EXPECT_LE(gap, 5.0 * tol * c.p.size[r]) << name << " row " << r;
        }
      }
    }
    // nsgs from that warm start under the lagged cone: Coulomb's law itself, the exact
    // cone's answer, in sweeps (the caps the warm start sets are not its law: measured
    // against them the solve froze at 3 tol until maxiter)
    {
      const Solved s = solve(c.p, "nsgs", tol, Cone::Lagged, other.mu);
      EXPECT_LT(s.report.iterations, 20000) << "seed " << seed;
      double worst = 0.0;
      for (size_t d = 0; d < exact.u.size(); ++d) worst = std::max(worst, (s.u[d] - exact.u[d]).norm());
      EXPECT_LT(worst, 1e-5) << "nsgs seed " << seed;
    }
    for (const char *name : {"hybrid", "apgd", "pgs", "uzawa"}) {
      const Solved warm = solve(c.p, name, tol, Cone::Lagged, exact.mu);
      const Solved cold = solve(c.p, name, tol, Cone::Lagged);
      double worst = 0.0;
      for (size_t d = 0; d < exact.u.size(); ++d)
        worst = std::max({worst, (warm.u[d] - exact.u[d]).norm(), (cold.u[d] - exact.u[d]).norm()});
      EXPECT_LT(worst, 1e-5) << name << " seed " << seed;
    }
  }
}

// The local solve on the unshifted cone (DiscLaw::local_solve_convex) is the projection of
// m - D^-1 g onto K in the metric of D: (m' - m + D^-1 g)^T D (z - m') >= 0 for every z in K,
// with one disc and with two.
template <class Law>
void convex_local_solve_is_the_projection(double rolling, double twisting = 0.0)
{
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  hardcontact::Coefficients k;
  k.friction = 0.4;
  k.resistance[0] = rolling;
  k.resistance[1] = twisting;
  constexpr int B = Law::block;
  for (int trial = 0; trial < 500; ++trial) {
    double d[B], m[B], g[B], next[B];
    for (int q = 0; q < B; ++q) {
      d[q] = q == 0 ? 0.5 + 0.4 * uni(rng) : 1.75 + uni(rng);
      // equal within a disc (the two-component ones come first; the last of an even block,
      // twisting's, is a disc of its own)
      if (q >= 2 && q % 2 == 0) d[q] = d[q - 1];
      m[q] = uni(rng);
      g[q] = uni(rng);
    }
    Law::project(m, k);
    for (int q = 0; q < B; ++q) next[q] = m[q];
    Law::local_solve_convex(next, g, d, k);
    double in[B];
    for (int q = 0; q < B; ++q) in[q] = next[q];
    Law::project(in, k);
    for (int q = 0; q < B; ++q) EXPECT_NEAR(in[q], next[q], 1e-12);    // in K
    for (int probe = 0; probe < 50; ++probe) {
      double z[B];
      for (int q = 0; q < B; ++q) z[q] = 2.0 * uni(rng);
      Law::project(z, k);
      double vi = 0.0;
      for (int q = 0; q < B; ++q) vi += (next[q] - m[q] + g[q] / d[q]) * d[q] * (z[q] - next[q]);
      EXPECT_GE(vi, -1e-12);
    }
  }
}

TEST(Friction, ConvexLocalSolveIsTheMetricProjection)
{
  convex_local_solve_is_the_projection<hardcontact::CoulombLaw>(0.0);
  convex_local_solve_is_the_projection<hardcontact::RollingLaw>(0.2);
  convex_local_solve_is_the_projection<hardcontact::TwistingLaw>(0.0, 0.3);
  convex_local_solve_is_the_projection<hardcontact::RollingTwistingLaw>(0.2, 0.3);
}

// For 2000 random points m and coefficients k: Law::project(m) has the normal value that
// minimises dist2(m, k, n) (for each n the discs project independently, and the distance is
// convex in n: ternary search); check(p, k, trial) then looks at the projected point.
template <class Law, class Dist, class Check>
void projection_matches_search(unsigned seed, Dist &&dist2, Check &&check)
{
  constexpr int B = Law::block;
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> U(-2.0, 2.0), C(0.0, 1.0);
  for (int trial = 0; trial < 2000; ++trial) {
    hardcontact::Coefficients k;    // rolling and twisting: 0 every 7th trial
    k.friction = C(gen);
    for (int r = 0; r < 2; ++r) k.resistance[r] = trial % 7 == 0 ? 0.0 : C(gen);
    double m[B], p[B];
    for (double &v : m) v = U(gen);
    std::copy(m, m + B, p);
    Law::project(p, k);
    double lo = 0.0, hi = 8.0;
    for (int it = 0; it < 200; ++it) {
      const double a = lo + (hi - lo) / 3.0, b = hi - (hi - lo) / 3.0;
      if (dist2(m, k, a) <= dist2(m, k, b)) hi = b;
      else lo = a;
    }
    EXPECT_NEAR(p[0], 0.5 * (lo + hi), 1e-7) << trial;
    check(p, k, trial);
  }
}

// The projection onto {|t| <= mu n, |r| <= mur n}: the same point as the search, inside the set.
TEST(Friction, RollingProjectionIsTheNearestPoint)
{
  auto clip = [](const double *v, double cap, double *out) {
    const double len = std::hypot(v[0], v[1]);
    const double f = len > cap ? (len > 0.0 ? cap / len : 0.0) : 1.0;
    out[0] = f * v[0];
    out[1] = f * v[1];
  };
  projection_matches_search<hardcontact::RollingLaw>(
      5,
      [&](const double *m, const hardcontact::Coefficients &k, double n) {
        double q[5] = {n};
        clip(m + 1, k.friction * n, q + 1);
        clip(m + 3, k.resistance[0] * n, q + 3);
        double d = 0.0;
        for (int a = 0; a < 5; ++a) d += (q[a] - m[a]) * (q[a] - m[a]);
        return d;
      },
      [](const double *p, const hardcontact::Coefficients &k, int trial) {
        EXPECT_LE(std::hypot(p[1], p[2]), k.friction * p[0] * (1 + 1e-12) + 1e-300) << trial;
        EXPECT_LE(std::hypot(p[3], p[4]), k.resistance[0] * p[0] * (1 + 1e-12) + 1e-300) << trial;
      });
}

// Every frictional solver on one random packing under a law with resistances (rolling and
// twisting coefficients per row): the same velocities as apgd within 1e-4, kinetic energy not
// above the free one, momentum and angular momentum exact, no gap below -2 tol.
void resistance_solvers_agree(hardcontact::ContactLaw law, double rolling, double twisting)
{
  hctest::RandomConfigOptions o;
  o.n = 50;
  o.box = 6.0;
  o.mass_decades = 1.0;
  o.walls = false;
  hctest::RandomConfig c = hctest::random_config(5, o);
  std::vector<Vec3> w(c.p.n_bodies());
  for (int b = 0; b < c.p.n_bodies(); ++b) w[b] = Vec3(std::sin(b), std::cos(3 * b), 0.5);
  add_friction(c.p, c.r, 0.5, w);
  c.p.resistance[0].assign(c.p.n_contacts(), rolling);
  c.p.resistance[1].assign(c.p.n_contacts(), twisting);
  std::vector<Vec3> u_free(c.p.u_free);
  u_free.insert(u_free.end(), w.begin(), w.end());
  const double e_free = kinetic2(c.p, u_free);
  const double tol = 1e-8;
  auto run = [&](const char *name) {
    auto solver = hardcontact::make_solver(name, law);
    SerialOps ops;
    SolverSettings s;
    s.tol = tol;
    s.maxiter = 400000;
    Solved out;
    out.report = solver->solve(c.p, s, ops, out.mu, out.u);
    EXPECT_TRUE(out.report.converged) << name << " " << out.report.residual;
    return out;
  };
  const Solved a = run("apgd");
  const int n = c.p.n_bodies();
  Vec3 P0 = Vec3::Zero(), L0 = Vec3::Zero();
  for (int b = 0; b < n; ++b) {
    const double m = 1.0 / c.p.inv_mass[b];
    P0 += m * c.p.u_free[b];
    L0 += m * c.q[b].cross(c.p.u_free[b]) + w[b] / c.p.inv_inertia[b];
  }
  for (const char *name : {"hybrid", "apgd", "pgs", "uzawa", "nsgs"}) {
    const Solved s = run(name);
    EXPECT_LE(kinetic2(c.p, s.u), e_free * (1.0 + 1e-12)) << name;
    double worst = 0.0;
    for (size_t d = 0; d < s.u.size(); ++d) worst = std::max(worst, (s.u[d] - a.u[d]).norm());
    EXPECT_LT(worst, 1e-4) << name;
    Vec3 P = Vec3::Zero(), L = Vec3::Zero();
    for (int b = 0; b < n; ++b) {
      const double m = 1.0 / c.p.inv_mass[b];
      P += m * s.u[b];
      L += m * c.q[b].cross(s.u[b]) + s.u[n + b] / c.p.inv_inertia[b];
    }
    EXPECT_LT((P - P0).norm(), 1e-11 * P0.norm() + 1e-11) << name;
    EXPECT_LT((L - L0).norm(), 1e-11 * L0.norm() + 1e-11) << name;
    for (int r = 0; r < c.p.n_contacts(); ++r)
      EXPECT_GE(c.p.predicted_gap(r, s.u), -2.0 * tol * c.p.size[r]) << name;
  }
}

TEST(Friction, RollingSolversAgreeAndConserveMomentum)
{
  resistance_solvers_agree(hardcontact::ContactLaw::Rolling, 0.2, 0.0);
}

TEST(Friction, TwistingSolversAgreeAndConserveMomentum)
{
  resistance_solvers_agree(hardcontact::ContactLaw::Twisting, 0.0, 0.2);
  resistance_solvers_agree(hardcontact::ContactLaw::RollingTwisting, 0.2, 0.2);
}

TEST(Friction, ExactSolverHasNoFriction)
{
  EXPECT_FALSE(hardcontact::make_solver("exact", hardcontact::ContactLaw::Coulomb));
  EXPECT_FALSE(hardcontact::solver_has_friction("exact"));
  EXPECT_TRUE(hardcontact::solver_has_friction("apgd"));
}

}    // namespace

// The local solve of nonsmooth Gauss-Seidel (CoulombLaw::local_solve) against the three cases
// of Coulomb's law for one contact with a diagonal block D = diag(dn, dt, dt): from any start
// m and gradient g at m, the answer m' gives g' = g + D (m' - m) with
//   take-off: m' = 0 and g'_n >= 0;  stick: g' = 0, |m'_t| <= mu m'_n;
//   slide: g'_n = 0, |m'_t| = mu m'_n, m'_t opposite to g'_t.
TEST(Friction, CoulombLocalSolveMeetsTheLaw)
{
  using hardcontact::CoulombLaw;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  hardcontact::Coefficients k;
  k.friction = 0.4;
  int cases[3] = {0, 0, 0};
  for (int trial = 0; trial < 2000; ++trial) {
    const double d[3] = {0.5 + uni(rng) * 0.4, 1.75 + uni(rng), 0.0};
    const double dd[3] = {d[0], d[1], d[1]};
    double m[3] = {std::abs(uni(rng)), 0.3 * uni(rng), 0.3 * uni(rng)};
    CoulombLaw::project(m, k);
    const double g[3] = {uni(rng), uni(rng), uni(rng)};
    double next[3] = {m[0], m[1], m[2]};
    CoulombLaw::local_solve(next, g, dd, k);
    double gn[3];
    for (int q = 0; q < 3; ++q) gn[q] = g[q] + dd[q] * (next[q] - m[q]);
    const double t = std::hypot(next[1], next[2]), gt = std::hypot(gn[1], gn[2]);
    if (next[0] == 0.0) {
      ++cases[0];
      EXPECT_EQ(t, 0.0);
      EXPECT_GE(gn[0], -1e-12);
    } else if (t < k.friction * next[0] * (1.0 - 1e-12)) {
      ++cases[1];
      EXPECT_NEAR(gt, 0.0, 1e-12);
      EXPECT_NEAR(gn[0], 0.0, 1e-12);
    } else {
      ++cases[2];
      EXPECT_NEAR(gn[0], 0.0, 1e-12);
      EXPECT_NEAR(t, k.friction * next[0], 1e-12);
      // the force opposes the slip: m_t = -mu m_n g_t / |g_t|
      EXPECT_NEAR(next[1] * gt + k.friction * next[0] * gn[1], 0.0, 1e-12);
      EXPECT_NEAR(next[2] * gt + k.friction * next[0] * gn[2], 0.0, 1e-12);
    }
  }
  for (int c : cases) EXPECT_GT(c, 100);    // every case met
}

// Three discs, {|t| <= mu n, |r| <= mur n, |s| <= mut n}: the same point as the search.
TEST(Friction, RollingTwistingProjectionIsTheNearestPoint)
{
  auto shrink = [](double len, double cap) { return len > cap ? (len > 0.0 ? cap / len : 0.0) : 1.0; };
  projection_matches_search<hardcontact::RollingTwistingLaw>(
      13,
      [&](const double *m, const hardcontact::Coefficients &k, double n) {
        const double ft = shrink(std::hypot(m[1], m[2]), k.friction * n);
        const double fr = shrink(std::hypot(m[3], m[4]), k.resistance[0] * n);
        const double s = std::max(-k.resistance[1] * n, std::min(k.resistance[1] * n, m[5]));
        const double q[6] = {n, ft * m[1], ft * m[2], fr * m[3], fr * m[4], s};
        double d = 0.0;
        for (int a = 0; a < 6; ++a) d += (q[a] - m[a]) * (q[a] - m[a]);
        return d;
      },
      [](const double *p, const hardcontact::Coefficients &k, int trial) {
        EXPECT_LE(std::hypot(p[1], p[2]), k.friction * p[0] * (1 + 1e-12) + 1e-300) << trial;
        EXPECT_LE(std::hypot(p[3], p[4]), k.resistance[0] * p[0] * (1 + 1e-12) + 1e-300) << trial;
        EXPECT_LE(std::abs(p[5]), k.resistance[1] * p[0] * (1 + 1e-12) + 1e-300) << trial;
      });
}

// A disc of one component, twisting's (a torque about the normal, |m| <= coef m_n):
// TwistingLaw projects onto {|t| <= mu n, |s| <= c n} as the search over the normal value
// finds, its local solve clamps the component to [-c n, c n], and its violation is 0 at a
// solution of the law (sliding on both discs) and > 0 off it.
namespace {
using OneComponentLaw = hardcontact::TwistingLaw;
}    // namespace

TEST(Friction, OneComponentDiscProjectsAndSolves)
{
  static_assert(OneComponentLaw::block == 4, "normal, two tangential, one more");
  projection_matches_search<OneComponentLaw>(
      11,
      [](const double *m, const hardcontact::Coefficients &k, double n) {
        const double len = std::hypot(m[1], m[2]), cap = k.friction * n;
        const double f = len > cap ? (len > 0.0 ? cap / len : 0.0) : 1.0;
        const double s = std::max(-k.resistance[1] * n, std::min(k.resistance[1] * n, m[3]));
        return (n - m[0]) * (n - m[0]) + (f * m[1] - m[1]) * (f * m[1] - m[1]) +
               (f * m[2] - m[2]) * (f * m[2] - m[2]) + (s - m[3]) * (s - m[3]);
      },
      [](const double *p, const hardcontact::Coefficients &k, int trial) {
        EXPECT_LE(std::hypot(p[1], p[2]), k.friction * p[0] * (1 + 1e-12) + 1e-300) << trial;
        EXPECT_LE(std::abs(p[3]), k.resistance[1] * p[0] * (1 + 1e-12) + 1e-300) << trial;
      });
  // local solve: the normal closes its gap, the one-component disc slides at its bound
  const hardcontact::Coefficients k{0.5, {0.0, 0.2}};
  double mm[4] = {1.0, 0.0, 0.0, 0.0};
  const double g[4] = {-1.0, 0.0, 0.0, -5.0}, d[4] = {1.0, 1.0, 1.0, 1.0};
  OneComponentLaw::local_solve(mm, g, d, k);
  EXPECT_DOUBLE_EQ(mm[0], 2.0);
  EXPECT_DOUBLE_EQ(mm[3], 0.2 * 2.0);    // clamped to c n, against its motion
  // violation: a contact sliding on both discs (force on each edge, against its motion, gap
  // closed by the shift) meets the law; turning the one-component force around does not
  const double m_ok[4] = {2.0, 1.0, 0.0, 0.4};
  const double g_ok[4] = {0.5 * 0.3 + 0.2 * 0.7, -0.3, 0.0, -0.7};
  EXPECT_NEAR(OneComponentLaw::violation(g_ok, m_ok, k, 1.0), 0.0, 1e-15);
  const double m_bad[4] = {2.0, 1.0, 0.0, -0.4};
  EXPECT_GT(OneComponentLaw::violation(g_ok, m_bad, k, 1.0), 0.1);
}
