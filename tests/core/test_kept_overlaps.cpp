// Kept overlaps (core/kept_overlaps.h, Targets::keeps): a frictionless row whose warm-start
// force is > 0 and whose overlap is within tol x min(size / 10, size - s) gets the target 0;
// rows that did not push, deeper rows, frictional rows and rows beyond the warm start are
// targeted as by the paper's policy; the gaps stay as measured; after undo() the targets
// written again are exactly the paper's; after an
// undo the next 1, 2, 4, ... 256 steps clear from the start; the budget follows the cleared
// steps' iterations; save_state()/load_state() carry the back-off and the budget (restart
// files), and a damaged state loads as a fresh one.
#include "kept_overlaps.h"
#include "targets.h"

#include "core_test_util.h"

#include <gtest/gtest.h>

#include <limits>

using namespace hardcontact;

namespace {

constexpr double kTol = 1e-4;

// Rows of size 1 on body 0 against a wall, with the given gaps.
ContactProblem rows(const std::vector<double> &gaps)
{
  ContactProblem p = hctest::make_problem(0.01, {1.0}, {Vec3::Zero()});
  for (const double d : gaps) p.add_contact(0, wall_body(0), Vec3(0, 0, -1), d, 1.0);
  return p;
}

// V = 0.01: s = h V = 1e-4 of the size, tol s = 1e-8; at most tol size / 10 = 1e-5 is kept
// Targets with V = speed_scale that may keep overlaps of rows with a warm force > 0, recording
// them in kept (begun: a step that may keep)
Targets keeping(KeptOverlaps &kept, const std::vector<double> &warm, double speed_scale = 0.01)
{
  kept.begin_step();
  Targets t{1.0, speed_scale, kTol};
  t.warm = &warm;
  t.kept_overlaps = &kept;
  return t;
}

const std::vector<double> kGaps = {-5e-6, -5e-6, -3e-5, 2e-6, -1e-5, -5e-6};
const std::vector<double> kWarm = {0.3, 0.0, 0.3, 0.3, 0.3};    // the last row: beyond it

TEST(KeptOverlaps, RowsThatPushedKeepShallowOverlaps)
{
  KeptOverlaps kept;
  const Targets t = keeping(kept, kWarm);
  ASSERT_TRUE(kept.active());
  ContactProblem p = rows(kGaps);
  t.apply(p, 0);
  EXPECT_DOUBLE_EQ(p.target[0], 0.0);      // pushed, within tol size / 10: may not deepen
  EXPECT_DOUBLE_EQ(p.target[1], -5e-6);    // did not push: cleared
  EXPECT_DOUBLE_EQ(p.target[2], -3e-5);    // deeper than the tenth: cleared, all of it
  EXPECT_DOUBLE_EQ(p.target[3], 2e-6);     // open: eq. 15 unchanged
  EXPECT_DOUBLE_EQ(p.target[4], 0.0);      // exactly the tenth: kept
  EXPECT_DOUBLE_EQ(p.target[5], -5e-6);    // no warm start (a row of a later round): cleared
  EXPECT_EQ(kept.rows_raised(), 2);
  for (int c = 0; c < p.n_contacts(); ++c) EXPECT_EQ(p.gap[c], kGaps[c]) << "row " << c;
}

TEST(KeptOverlaps, UndoGivesThePapersTargets)
{
  KeptOverlaps kept;
  const Targets t = keeping(kept, kWarm);
  ContactProblem p = rows(kGaps);
  t.apply(p, 0);
  kept.undo();
  EXPECT_EQ(kept.rows_raised(), 0);
  t.apply(p, 0);    // the targets again, from the gaps beside them (step.cpp)
  ContactProblem q = rows(kGaps);
  const Targets paper{1.0, 0.01, kTol};
  paper.apply(q, 0);
  for (int c = 0; c < p.n_contacts(); ++c) EXPECT_EQ(p.target[c], q.target[c]) << "row " << c;
  EXPECT_FALSE(kept.active());
  EXPECT_EQ(kept.undone(), 1);
}

TEST(KeptOverlaps, NothingIsKeptWhileInactiveOrWithoutAWarmStart)
{
  Targets t{1.0, 0.01, kTol};
  KeptOverlaps kept;    // begin_step() not called: inactive
  t.warm = &kWarm;
  t.kept_overlaps = &kept;
  ContactProblem p = rows(kGaps);
  t.apply(p, 0);
  EXPECT_DOUBLE_EQ(p.target[0], -5e-6);
  kept.begin_step();
  t.warm = nullptr;
  ContactProblem q = rows(kGaps);
  t.apply(q, 0);
  EXPECT_DOUBLE_EQ(q.target[0], -5e-6);
  EXPECT_EQ(kept.rows_raised(), 0);
}

TEST(KeptOverlaps, FrictionalRowsFollowTheirOwnPolicy)
{
  // with a coefficient > 0 the friction policy keeps the tenth whether the row pushed or not
  // (targets.cpp) and records no raise: undo() does not touch it
  KeptOverlaps kept;
  const std::vector<double> warm = {0.0, 0.3};
  const Targets t = keeping(kept, warm);
  ContactProblem p = rows({-5e-6, -5e-6});
  p.friction = {0.5, 0.0};
  t.apply(p, 0);
  EXPECT_DOUBLE_EQ(p.target[0], 0.0);
  EXPECT_DOUBLE_EQ(p.target[1], 0.0);
  EXPECT_EQ(kept.rows_raised(), 1);    // only the frictionless one
}

TEST(KeptOverlaps, LessIsKeptAsTheRowScaleNearsTheSize)
{
  // h V = 0.95 of the size: at most tol (size - s) = 5e-6 may be kept
  KeptOverlaps kept;
  const std::vector<double> warm = {0.3, 0.3};
  const Targets t = keeping(kept, warm, 95.0);
  ContactProblem p = rows({-4e-6, -6e-6});
  t.apply(p, 0);
  EXPECT_DOUBLE_EQ(p.target[0], 0.0);
  EXPECT_DOUBLE_EQ(p.target[1], -6e-6);
}

TEST(KeptOverlaps, BackOffDoublesUpTo256Steps)
{
  KeptOverlaps kept;
  ContactProblem p = rows({});
  std::vector<int> cleared;    // steps cleared from the start after each undo
  for (int round = 0; round < 11; ++round) {
    ASSERT_TRUE(kept.begin_step()) << "round " << round;
    kept.undo();
    int n = 0;
    while (!kept.begin_step()) ++n;
    cleared.push_back(n);
  }
  EXPECT_EQ(cleared, (std::vector<int>{1, 2, 4, 8, 16, 32, 64, 128, 256, 256, 256}));
  EXPECT_EQ(kept.undone(), 11);
}

TEST(KeptOverlaps, BudgetIsATenthOfMaxiterBeforeAnyClearedStep)
{
  KeptOverlaps kept;
  EXPECT_EQ(kept.budget(10000), 1000);
  EXPECT_EQ(kept.budget(10), 1);
  EXPECT_EQ(kept.budget(5), 1);
}

TEST(KeptOverlaps, BudgetFollowsWhatClearingCosts)
{
  KeptOverlaps kept;
  kept.cleared(40);    // 4 x 40
  EXPECT_EQ(kept.budget(10000), 160);
  EXPECT_EQ(kept.budget(1000), 100);    // never above a tenth of maxiter
  EXPECT_EQ(kept.budget(5), 1);
  kept.cleared(3);    // the measure halves to 20 (more than 3): 4 x 20 = 80
  EXPECT_EQ(kept.budget(10000), 80);
  kept.cleared(0);    // it halves to 10: 4 x 10 = 40, below the floor
  EXPECT_EQ(kept.budget(10000), KeptOverlaps::kMinBudget);
  kept.cleared(600);    // a costlier step raises it at once: 2400
  EXPECT_EQ(kept.budget(100000), 2400);
  EXPECT_EQ(kept.budget(10000), 1000);
  kept.cleared(2000000000);    // 4 x that does not overflow
  EXPECT_EQ(kept.budget(2000000000), 200000000);
}

TEST(KeptOverlaps, StateCarriesTheBackOffAndTheBudget)
{
  KeptOverlaps a;
  ContactProblem p = rows({});
  a.cleared(70);
  for (int k = 0; k < 3; ++k) {    // three stops: back-offs of 1, 2, then 4 steps under way
    ASSERT_TRUE(a.begin_step());
    a.undo();
    while (!a.begin_step()) {
    }
  }
  ASSERT_TRUE(a.begin_step());
  a.undo();             // a back-off of 8 steps begins
  ASSERT_FALSE(a.begin_step());    // and one of them is done
  double state[KeptOverlaps::kStateSize];
  a.save_state(state);
  KeptOverlaps b;    // a new fix after read_restart
  b.load_state(state);
  EXPECT_EQ(b.budget(10000), 280);    // 4 x 70, not a tenth of maxiter
  EXPECT_EQ(b.undone(), 0);           // counted since the fix was defined
  // the same steps clear as in the unsplit run: the 7 left of this back-off, then 16 after
  // the next stop
  for (KeptOverlaps *k : {&a, &b}) {
    int n = 0;
    while (!k->begin_step()) ++n;
    EXPECT_EQ(n, 7);
    k->undo();
    n = 0;
    while (!k->begin_step()) ++n;
    EXPECT_EQ(n, 16);
  }
}

TEST(KeptOverlaps, DamagedStateLoadsAsFresh)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double bad[KeptOverlaps::kStateSize] = {-3.0, 1e9, nan};
  KeptOverlaps k;
  k.load_state(bad);
  EXPECT_EQ(k.budget(10000), 1000);    // no measure: a tenth of maxiter
  EXPECT_TRUE(k.begin_step());         // no back-off under way
  ContactProblem p = rows({});
  k.undo();
  int n = 0;
  while (!k.begin_step()) ++n;
  EXPECT_EQ(n, 1);    // the back-off starts at 1 again
}

}    // namespace
