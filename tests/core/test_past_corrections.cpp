// The subspace start's bookkeeping (solvers/past_corrections.h): the move to the best point
// in the span of the past corrections is kept only if the dual objective fell, and after a
// refused move the next 1, 2, 4, ... 16 solves do not try it; a kept move tries again at once.
// One row whose dual is the scalar phi(mu) = 1/2 a mu^2 + b mu (g = a mu + b), one correction
// w = 1 with its product a w: the best point of the span is the minimum -b / a.
#include "solvers/past_corrections.h"

#include "core_test_util.h"

#include <gtest/gtest.h>

using namespace hardcontact;

namespace {

constexpr double kA = 2.0, kB = -3.0;    // minimum at mu = 1.5

struct OneRow {
  ContactProblem p = hctest::make_problem(0.01, {1.0}, {Vec3::Zero()});
  SerialOps ops;
  PastCorrections past{1};
  std::vector<int> rows{0};
  std::vector<Vec3> u{Vec3::Zero()};

  OneRow()
  {
    p.add_contact(0, wall_body(0), Vec3(0, 0, -1), 0.0, 1.0);
    p.renumbered = false;
    past.follow(p, ops);
    past.record({1.0}, {kA}, p, 10);
  }
  // one solve's start from mu0: returns the start the solve would take
  double start(double mu0)
  {
    std::vector<double> mu{mu0}, g{kA * mu0 + kB};
    past.improve_start(
        p, rows, ops, mu, g, u, [](int, double *m) { m[0] = m[0] > 0.0 ? m[0] : 0.0; },
        [](const std::vector<double> &m, std::vector<double> &gg, std::vector<Vec3> &) {
          gg[0] = kA * m[0] + kB;
        });
    return mu[0];
  }
};

TEST(PastCorrections, AMoveThatLowersTheObjectiveIsKept)
{
  OneRow r;
  ASSERT_TRUE(r.past.due());
  EXPECT_DOUBLE_EQ(r.start(0.0), 1.5);
  EXPECT_TRUE(r.past.due());    // kept: the next solve tries again
}

TEST(PastCorrections, RefusedMovesBackOffOneTwoFourUpToSixteenSolves)
{
  OneRow r;
  std::vector<int> tried;
  for (int solve = 0; solve < 60; ++solve)
    if (r.past.due()) {
      tried.push_back(solve);
      // at the minimum already: the best point is the start, phi does not fall, refused
      EXPECT_DOUBLE_EQ(r.start(1.5), 1.5);
    }
  EXPECT_EQ(tried, (std::vector<int>{0, 2, 5, 10, 19, 36, 53}));
}

TEST(PastCorrections, AKeptMoveEndsTheBackOff)
{
  OneRow r;
  for (int solve = 0; solve < 6; ++solve)    // tries at 0, 2, 5, all refused
    if (r.past.due()) r.start(1.5);
  int skipped = 0;
  while (!r.past.due()) ++skipped;
  EXPECT_EQ(skipped, 4);    // the 4 after the try at 5
  EXPECT_DOUBLE_EQ(r.start(0.0), 1.5);    // kept
  EXPECT_TRUE(r.past.due());
  EXPECT_DOUBLE_EQ(r.start(0.0), 1.5);
}

TEST(PastCorrections, NoCorrectionsNothingToTry)
{
  PastCorrections past{1};
  EXPECT_FALSE(past.due());
}

}    // namespace
