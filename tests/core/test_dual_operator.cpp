// The product of the Krylov solvers (DualOperator::impulse_velocities_with, then G_c):
// w = h M^-1 G^T m, and h G_c w = (A m)_c with A = h^2 G M^-1 G^T assembled densely from the
// rows' geometry (core_test_util.h), on random packings with walls; a row coupling an owned
// body with a copy owned elsewhere pushes the owned body only.
#include "dual_operator.h"

#include "core_test_util.h"
#include "random_config.h"

#include <gtest/gtest.h>

#include <numeric>
#include <random>

using namespace hardcontact;

namespace {

// (A m)_c for every row through the operator, and the velocity change w it made
std::vector<double> product(DualOperator &op, const std::vector<double> &m, std::vector<Vec3> &w)
{
  const ContactProblem &p = op.problem();
  std::vector<int> rows(p.n_contacts());
  std::iota(rows.begin(), rows.end(), 0);
  op.impulse_velocities_with(rows, [&](int c) { return m[c]; }, w);
  std::vector<double> am(p.n_contacts());
  for (int c = 0; c < p.n_contacts(); ++c) am[c] = p.h * p.normal_speed(c, w);
  return am;
}

}    // namespace

TEST(DualOperator, ImpulseProductIsTheAssembledOperator)
{
  for (const unsigned seed : {3u, 17u, 41u}) {
    hctest::RandomConfigOptions o;
    o.n = 120;
    o.box = 8.0;
    const hctest::RandomConfig cfg = hctest::random_config(seed, o);
    const ContactProblem &p = cfg.p;
    int walls = 0;
    for (int c = 0; c < p.n_contacts(); ++c) walls += is_wall(p.body_j[c]) ? 1 : 0;
    ASSERT_GT(walls, 0);
    ASSERT_GT(p.n_contacts() - walls, 0);

    std::mt19937 gen(seed);
    std::uniform_real_distribution<double> U(-1.0, 1.0);
    std::vector<double> mv(p.n_contacts());
    for (int c = 0; c < p.n_contacts(); ++c) mv[c] = c % 5 == 0 ? 0.0 : U(gen);
    const Eigen::Map<const Eigen::VectorXd> m(mv.data(), p.n_contacts());

    SerialOps ops;
    DualOperator op;
    op.bind(p, ops);
    std::vector<Vec3> w;
    const std::vector<double> am = product(op, mv, w);
    const Eigen::VectorXd ref = hctest::dense_A(p) * m;
    const double scale = ref.cwiseAbs().maxCoeff();
    for (int c = 0; c < p.n_contacts(); ++c) EXPECT_NEAR(am[c], ref[c], 1e-13 * scale) << c;
    // w itself: h M^-1 G^T m (dense_G's rows are G_c)
    const Eigen::VectorXd gtm = hctest::dense_G(p).transpose() * m;
    for (int b = 0; b < p.n_bodies(); ++b)
      for (int a = 0; a < 3; ++a)
        EXPECT_NEAR(w[b][a], p.h * p.inv_mass[b] * gtm[3 * b + a], 1e-13 * scale / p.h) << b;
  }
}

TEST(DualOperator, ARowWithAGhostPushesTheOwnedBodyOnly)
{
  // bodies 0, 1 owned, 2 a copy owned elsewhere; rows 0-1, 1-2 and 0 against a wall
  ContactProblem p = hctest::make_problem(0.1, {1.0, 0.5, 2.0},
                                          {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()});
  p.n_owned = 2;
  hctest::add_pair(p, 0, 1, Vec3(0, 0, 0), Vec3(1, 0, 0), 0.5, 0.5);
  hctest::add_pair(p, 1, 2, Vec3(1, 0, 0), Vec3(1, 1, 0), 0.5, 0.5);
  hctest::add_wall(p, 0, Vec3(0, 0, 0), 0.5, Vec3(0, 0, -0.6), Vec3(0, 0, 1));
  SerialOps ops;
  DualOperator op;
  op.bind(p, ops);
  // the ghost's entry is its owner's to compute (the host forwards it; SerialOps does not):
  // a marker there must stay as it is
  const Vec3 marker(7.0, -7.0, 7.0);
  std::vector<Vec3> w(p.n_dof(), marker);
  product(op, {2.0, 3.0, 5.0}, w);
  // impulse h m n on j, its opposite on i: n_01 = +x, n_12 = +y, the wall's normal -z
  const double h = 0.1;
  EXPECT_EQ(w[0], Vec3(-h * 2.0 * 1.0, 0.0, h * 5.0 * 1.0));
  EXPECT_EQ(w[1], Vec3(h * 2.0 * 0.5, -h * 3.0 * 0.5, 0.0));
  EXPECT_EQ(w[2], marker);
}
