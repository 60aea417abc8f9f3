// The `solver` keyword's table (solver_registry.cpp): known names build a working solver,
// unknown names give nullptr, and solver_names() lists what make_solver accepts.
#include "solver.h"

#include "core_test_util.h"
#include "random_config.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace hardcontact;

namespace {

// A working solver, not just a non-null pointer: two unit spheres touching, one at rest, one
// arriving at 1: restitution 0 leaves both at 1/2.
void expect_touching_pair_solved(Solver &s, double accuracy)
{
  ContactProblem p = hctest::make_problem(0.1, {1.0, 1.0}, {Vec3(1, 0, 0), Vec3(0, 0, 0)});
  hctest::add_pair(p, 0, 1, Vec3(0, 0, 0), Vec3(2, 0, 0), 1.0, 1.0);
  SerialOps ops;
  SolverSettings set;
  set.tol = 1e-12;
  std::vector<double> mu;
  std::vector<Vec3> u;
  EXPECT_TRUE(s.solve(p, set, ops, mu, u).converged);
  ASSERT_EQ(u.size(), 2u);
  EXPECT_NEAR(u[0].x(), 0.5, accuracy);
  EXPECT_NEAR(u[1].x(), 0.5, accuracy);
}

}  // namespace

TEST(SolverRegistry, UzawaIsRegisteredAndSolves)
{
  std::unique_ptr<Solver> s = make_solver("uzawa");
  ASSERT_NE(s, nullptr);
  expect_touching_pair_solved(*s, 1e-14);
}

TEST(SolverRegistry, UnknownNameGivesNullptr)
{
  EXPECT_EQ(make_solver("no-such-solver"), nullptr);
  EXPECT_EQ(make_solver(""), nullptr);
  EXPECT_EQ(make_solver("Uzawa"), nullptr);    // names are case-sensitive
  EXPECT_EQ(make_solver("uzawa "), nullptr);
}

TEST(SolverRegistry, NamesListUzawaAndEveryNameBuilds)
{
  const std::vector<std::string> names = solver_names();
  EXPECT_NE(std::find(names.begin(), names.end(), "uzawa"), names.end());
  for (const std::string &n : names) {
    std::unique_ptr<Solver> s = make_solver(n);
    ASSERT_NE(s, nullptr) << n;
    // Each registered solver solves the touching pair of the first test: 1 onto 1 at rest.
    SCOPED_TRACE(n);
    expect_touching_pair_solved(*s, 1e-11);
  }
  // Names are unique, and each call gives a fresh object.
  std::vector<std::string> sorted = names;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end());
  EXPECT_NE(make_solver("uzawa").get(), make_solver("uzawa").get());
}

// memory_usage() feeds LAMMPS's per-rank memory line: an iterative solver keeps per-row
// scratch between solves (at least its gaps and working set: 2 doubles per row), the exact
// solver keeps nothing.
TEST(SolverRegistry, MemoryUsageCountsThePerRowScratch)
{
  hctest::RandomConfigOptions o;
  o.n = 150;
  o.box = 9.5;
  const hctest::RandomConfig c = hctest::random_config(31u, o);
  const double rows = c.p.n_contacts();
  ASSERT_GT(rows, 50);
  for (const std::string &name : solver_names()) {
    SCOPED_TRACE(name);
    std::unique_ptr<Solver> s = make_solver(name);
    EXPECT_EQ(s->memory_usage(), 0.0);    // nothing before the first solve
    SerialOps ops;
    std::vector<double> mu;
    std::vector<Vec3> u;
    s->solve(c.p, SolverSettings{}, ops, mu, u);
    if (name == "exact") {
      EXPECT_EQ(s->memory_usage(), 0.0);
    } else {
      EXPECT_GE(s->memory_usage(), 2.0 * sizeof(double) * rows);
      EXPECT_LE(s->memory_usage(), 64.0 * sizeof(double) * (rows + c.p.n_bodies()));
    }
  }
}
