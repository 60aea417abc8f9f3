// The overlap policy of core/targets.cpp: an overlap present at q^n is pushed apart by at most
// h times the recovery speed plus 2 tol s per step (s = min(size, h V), the row scale without
// its round-off floor); with friction an overlap within a tenth of tol x the contact size is
// kept (target 0), only the deeper part is pushed apart, and less is kept as s nears the size,
// so that what a solve leaves stays within tol x size. Rows without friction, and rows with a
// coefficient of 0, are cleared as before.
#include "restitution.h"
#include "targets.h"

#include "core_test_util.h"

#include <gtest/gtest.h>

using namespace hardcontact;

namespace {

constexpr double kTol = 1e-4;

// Rows of size 1 on body 0 against a wall, with the given gaps and friction coefficients.
ContactProblem rows(const std::vector<double> &gaps, const std::vector<double> &friction)
{
  ContactProblem p = hctest::make_problem(0.01, {1.0}, {Vec3::Zero()});
  for (const double d : gaps) p.add_contact(0, wall_body(0), Vec3(0, 0, -1), d, 1.0);
  p.friction = friction;
  return p;
}

TEST(Targets, FrictionalRowsKeepOverlapsWithinATenthOfTol)
{
  // V = 0.01: s = h V = 1e-4 of the size; recovery speed 1: the clamp is far below
  const Targets t{1.0, 0.01, kTol};
  ContactProblem p = rows({-5e-6, -5e-6, -3e-5, -5e-6, 1e-3, -5e-6},
                          {0.0, 0.5, 0.5, 0.0, 0.5, 0.5});
  t.apply(p, 0);
  EXPECT_DOUBLE_EQ(p.target[0], -5e-6);    // no friction: pushed apart
  EXPECT_DOUBLE_EQ(p.target[1], 0.0);      // within tol size / 10: kept, may not deepen
  EXPECT_NEAR(p.target[2], -2e-5, 1e-20);  // deeper: only what lies beyond the tenth
  EXPECT_DOUBLE_EQ(p.target[3], -5e-6);    // a coefficient of 0 is frictionless
  EXPECT_DOUBLE_EQ(p.target[4], 1e-3);     // open rows: eq. 15 unchanged
  EXPECT_DOUBLE_EQ(p.target[5], 0.0);
}

TEST(Targets, NoFrictionAtAllIsTheFrictionlessPolicy)
{
  const Targets t{1.0, 0.01, kTol};
  ContactProblem p = rows({-5e-6, -3e-5}, {});
  t.apply(p, 0);
  EXPECT_DOUBLE_EQ(p.target[0], -5e-6);
  EXPECT_DOUBLE_EQ(p.target[1], -3e-5);
}

TEST(Targets, LessIsKeptAsTheRowScaleNearsTheSize)
{
  // h V = 0.95 of the size: at most tol (size - s) = 5e-6 is kept; h V >= size: nothing
  ContactProblem p = rows({-8e-6}, {0.5});
  const Targets near{1.0, 95.0, kTol};
  near.apply(p, 0);
  EXPECT_NEAR(p.target[0], -3e-6, 1e-18);
  ContactProblem q = rows({-8e-6}, {0.5});
  const Targets fast{1.0, 200.0, kTol};
  fast.apply(q, 0);
  EXPECT_DOUBLE_EQ(q.target[0], -8e-6);
}

TEST(Targets, DeepOverlapsAreStillClearedAtTheBoundedRate)
{
  // no recovery speed and V = 0.01: a deep overlap is asked to open by 2 tol s = 2e-8 per step,
  // with friction or without (the kept tenth is far above that and does not add to it)
  const Targets t{0.0, 0.01, kTol};
  ContactProblem p = rows({-0.1, -0.1}, {0.0, 0.5});
  t.apply(p, 0);
  EXPECT_NEAR(p.target[0], -2e-8, 1e-22);
  EXPECT_NEAR(p.target[1], -2e-8, 1e-22);
}

TEST(Targets, ARowClosingFastLeavesAtERelativeToItsWall)
{
  // h = 0.01; body 0 falls at 2 onto a floor (n = -z): v = n . (0 - u) = -2, and the free
  // motion closes the gap 1e-3 within the step. e = 0.5: the target asks for
  // n . (u_wall - u)^{n+1} >= 1, i.e. min(D, 0) + h e v = -0.01 (with the gap as measured
  // beside it). A floor rising at 0.5 (n . u_wall = -0.5): v = -2.5 relative to it, and the
  // target keeps the wall's term, h (-0.5) + h e (-2.5). A row closing slower than vmin, or
  // one the free motion keeps open, stays inelastic.
  const std::vector<Vec3> u0 = {Vec3(0, 0, -2)};
  ContactProblem p = hctest::make_problem(0.01, {1.0}, u0);
  p.add_contact(0, wall_body(0), Vec3(0, 0, -1), 1e-3, 1.0);
  p.add_contact(0, wall_body(0), Vec3(0, 0, -1), 0.5, 1.0);    // stays open
  const Targets t{1.0, 2.0, kTol};
  t.apply(p, 0);
  add_rebound_targets(p, 0, {0.5, 0.5}, u0, 0.0);
  EXPECT_DOUBLE_EQ(p.target[0], 0.01 * 0.5 * -2.0);
  EXPECT_DOUBLE_EQ(p.gap[0], 1e-3);
  EXPECT_DOUBLE_EQ(p.target[1], 0.5);
  ContactProblem slow = hctest::make_problem(0.01, {1.0}, u0);
  slow.add_contact(0, wall_body(0), Vec3(0, 0, -1), 1e-3, 1.0);
  t.apply(slow, 0);
  add_rebound_targets(slow, 0, {0.5}, u0, 2.5);    // vmin above the approach speed
  EXPECT_DOUBLE_EQ(slow.target[0], 1e-3);
  ContactProblem moving = hctest::make_problem(0.01, {1.0}, u0);
  moving.add_contact(0, wall_body(0), Vec3(0, 0, -1), 1e-3, 1.0);
  moving.wall_velocity = {Vec3(0, 0, 0.5)};
  t.apply(moving, 0);
  EXPECT_DOUBLE_EQ(moving.target[0], 1e-3 + 0.01 * -0.5);    // the wall's term
  add_rebound_targets(moving, 0, {0.5}, u0, 0.0);
  EXPECT_DOUBLE_EQ(moving.target[0], 0.01 * -0.5 + 0.01 * 0.5 * -2.5);
}

}    // namespace
