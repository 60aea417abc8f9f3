// A fixed number of iterations of every registered solver (solvers/registry.cpp), per law it
// has, from the law's warm start: what a solver costs per iteration once its prologue (working
// set, bound, start velocities) is shared by the solve's iterations. One iteration per solve
// shows the prologue itself; twenty, the iteration.
#include "problems.h"
#include "registration.h"
#include "throughput.h"

#include "solver.h"

#include <benchmark/benchmark.h>

#include <memory>
#include <string>
#include <vector>

namespace micro {

namespace {

// No solver reaches it in a few iterations of a problem of thousands of rows, so each solve
// does all of them (above 0: the row scales divide by it, residual.h).
constexpr double kUnreachableTol = 1.0e-12;
constexpr int kIterationsPerSolve[] = {1, 20};

void solver_iterations(benchmark::State &state, const std::string &name, ContactLaw law)
{
  const LawProblem &lp = problem(law);
  std::unique_ptr<hardcontact::Solver> solver = hardcontact::make_solver(name, law);
  hardcontact::SolverSettings s;
  s.tol = kUnreachableTol;
  s.maxiter = static_cast<int>(state.range(0));
  hardcontact::SerialOps ops;
  std::vector<double> mu;
  std::vector<Vec3> u;
  double iterations = 0.0;
  for (auto _ : state) {
    mu = lp.warm;    // every solve from the same start (a copy: a fraction of one pass)
    const hardcontact::SolveReport r = solver->solve(lp.p, s, ops, mu, u);
    iterations += r.iterations;
    benchmark::DoNotOptimize(u.data());
  }
  report_throughput(state, lp.p.n_contacts(), iterations * lp.p.n_contacts());
  // the solver's own count: a frictional solve may spend some on moving the shifts
  state.counters["iterations"] = benchmark::Counter(iterations, benchmark::Counter::kAvgIterations);
}

}    // namespace

void register_solver_benchmarks()
{
  for (const std::string &name : hardcontact::solver_names())
    for (const ContactLaw law : kLaws) {
      const std::unique_ptr<hardcontact::Solver> solver = hardcontact::make_solver(name, law);
      // a direct solver has no iteration to count (exact: the reference, not a contender)
      if (!solver || !solver->traits().iterative) continue;
      benchmark::internal::Benchmark *b = benchmark::RegisterBenchmark(
          ("solver/" + name + "/" + law_name(law)).c_str(), solver_iterations, name, law);
      for (const int k : kIterationsPerSolve) b->Arg(k);
      b->Unit(benchmark::kMicrosecond);
    }
}

}    // namespace micro
