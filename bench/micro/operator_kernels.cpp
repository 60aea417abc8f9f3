// The per-iteration kernels every solver is made of, each over every row of a law's problem:
// the two products with G (DualOperator: u(mu) = u_free + h M^-1 G^T mu, and the gradient
// blocks g_c = D_c + h G_c u), the Krylov product of cg, the stopping test's residual, and
// the law's projection. A solver's iteration costs a few of these passes, so their rates
// bound its own.
#include "problems.h"
#include "registration.h"
#include "throughput.h"

#include "dual_operator.h"
#include "laws/coulomb.h"
#include "laws/normal.h"
#include "laws/rolling.h"
#include "residual.h"

#include <benchmark/benchmark.h>

#include <numeric>
#include <random>
#include <string>
#include <vector>

namespace micro {

namespace {

using hardcontact::DualOperator;
using hardcontact::SerialOps;

// u = u_free + h M^-1 G^T mu over every row (eq. 16), mu the warm start: G^T.
template <class Law>
void velocities(benchmark::State &state, ContactLaw law)
{
  const LawProblem &lp = problem(law);
  SerialOps ops;
  DualOperator op;
  op.bind(lp.p, ops);
  std::vector<Vec3> u;
  for (auto _ : state) {
    op.velocities<Law>(lp.warm, u);
    benchmark::DoNotOptimize(u.data());
    benchmark::ClobberMemory();
  }
  report_throughput(state, lp.p.n_contacts(), double(lp.p.n_contacts()) * state.iterations());
}

// The gradient blocks of every row at the warm start's velocities: G.
template <class Law>
void gaps(benchmark::State &state, ContactLaw law)
{
  constexpr int B = Law::block;
  const LawProblem &lp = problem(law);
  SerialOps ops;
  DualOperator op;
  op.bind(lp.p, ops);
  const int nc = lp.p.n_contacts();
  std::vector<double> g(static_cast<size_t>(B) * nc);
  for (auto _ : state) {
    for (int c = 0; c < nc; ++c) op.gap_block<Law>(c, lp.u, &g[static_cast<size_t>(B) * c]);
    benchmark::DoNotOptimize(g.data());
    benchmark::ClobberMemory();
  }
  report_throughput(state, nc, double(nc) * state.iterations());
}

// cg's product (normal law): w = h M^-1 G^T m from rest, over every row.
void impulse_velocities(benchmark::State &state)
{
  const LawProblem &lp = problem(ContactLaw::Normal);
  SerialOps ops;
  DualOperator op;
  op.bind(lp.p, ops);
  std::vector<int> rows(lp.p.n_contacts());
  std::iota(rows.begin(), rows.end(), 0);
  std::vector<Vec3> w;
  for (auto _ : state) {
    op.impulse_velocities_with(rows, [&](int c) { return lp.warm[c]; }, w);
    benchmark::DoNotOptimize(w.data());
    benchmark::ClobberMemory();
  }
  report_throughput(state, lp.p.n_contacts(), double(lp.p.n_contacts()) * state.iterations());
}

// The stopping test's pass (residual.h): G, then each row's violation of the law.
template <class Law>
void residual(benchmark::State &state, ContactLaw law)
{
  const LawProblem &lp = problem(law);
  SerialOps ops;
  DualOperator op;
  op.bind(lp.p, ops);
  std::vector<double> scale;
  hardcontact::row_scales(lp.p, 1.0e-4, ops, scale);
  for (auto _ : state) {
    double r = hardcontact::residual<Law>(op, lp.warm, lp.u, scale);
    benchmark::DoNotOptimize(r);
  }
  report_throughput(state, lp.p.n_contacts(), double(lp.p.n_contacts()) * state.iterations());
}

// The law's projection of every block, from blocks a gradient step would give: the warm
// start moved by up to its mean normal force in every component, so that blocks fall inside
// the set, in its polar cone and outside both, in no order a branch predictor could learn.
template <class Law>
void project(benchmark::State &state, ContactLaw law)
{
  constexpr int B = Law::block;
  const LawProblem &lp = problem(law);
  const int nc = lp.p.n_contacts();
  double mean = 0.0;
  for (int c = 0; c < nc; ++c) mean += lp.warm[static_cast<size_t>(B) * c];
  mean = nc > 0 && mean > 0.0 ? mean / nc : 1.0;
  std::mt19937 gen(11u);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  std::vector<double> stepped(lp.warm);
  for (double &m : stepped) m += mean * U(gen);
  std::vector<double> m(stepped.size());
  for (auto _ : state) {
    // projected out of place: the input stays unprojected for the next pass
    for (int c = 0; c < nc; ++c) {
      const size_t at = static_cast<size_t>(B) * c;
      for (int k = 0; k < B; ++k) m[at + k] = stepped[at + k];
      Law::project(&m[at], hardcontact::law_coefficients<Law>(lp.p, c));
    }
    benchmark::DoNotOptimize(m.data());
    benchmark::ClobberMemory();
  }
  report_throughput(state, nc, double(nc) * state.iterations());
}

template <class Law>
void register_law(ContactLaw law)
{
  const std::string name = law_name(law);
  benchmark::RegisterBenchmark(("operator/velocities/" + name).c_str(), velocities<Law>, law);
  benchmark::RegisterBenchmark(("operator/gaps/" + name).c_str(), gaps<Law>, law);
  if (law == ContactLaw::Normal)
    benchmark::RegisterBenchmark("operator/impulse_velocities/normal", impulse_velocities);
  benchmark::RegisterBenchmark(("residual/" + name).c_str(), residual<Law>, law);
  benchmark::RegisterBenchmark(("project/" + name).c_str(), project<Law>, law);
}

}    // namespace

void register_operator_benchmarks()
{
  register_law<hardcontact::NormalLaw>(ContactLaw::Normal);
  register_law<hardcontact::CoulombLaw>(ContactLaw::Coulomb);
  register_law<hardcontact::RollingLaw>(ContactLaw::Rolling);
}

}    // namespace micro
