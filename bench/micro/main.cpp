// hardcontact_micro: Google Benchmark's command line (--benchmark_filter, --benchmark_min_time,
// --benchmark_format, --benchmark_out, ...) plus --spheres=N, the size of the generated
// packing (default 3000; the ctest smoke run uses a small one).
#include "problems.h"
#include "registration.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

namespace {

// Takes --spheres=N out of argv (Google Benchmark rejects options it does not know).
bool take_spheres(int &argc, char **argv)
{
  const char *prefix = "--spheres=";
  const size_t len = std::strlen(prefix);
  int kept = 1;
  for (int a = 1; a < argc; ++a) {
    if (std::strncmp(argv[a], prefix, len) != 0) {
      argv[kept++] = argv[a];
      continue;
    }
    char *end = nullptr;
    const long n = std::strtol(argv[a] + len, &end, 10);
    if (end == argv[a] + len || *end != '\0' || n < 2 || n > 10000000) {
      std::fprintf(stderr, "hardcontact_micro: --spheres wants a count of at least 2, got '%s'\n",
                   argv[a] + len);
      return false;
    }
    micro::set_spheres(static_cast<int>(n));
  }
  argc = kept;
  argv[argc] = nullptr;
  return true;
}

// The CPU's model name (Linux), for the context of a recorded run: Google Benchmark gives
// only counts and clock rates.
std::string cpu_model()
{
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) {
      const size_t colon = line.find(':');
      if (colon != std::string::npos) return line.substr(line.find_first_not_of(' ', colon + 1));
    }
  return "unknown";
}

}    // namespace

int main(int argc, char **argv)
{
  if (!take_spheres(argc, argv)) return 2;
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  // the problems before the run, so that the context printed first can describe them
  benchmark::AddCustomContext("cpu_model", cpu_model());
  benchmark::AddCustomContext("spheres", std::to_string(micro::spheres()));
  for (const micro::ContactLaw law : micro::kLaws) {
    const micro::LawProblem &lp = micro::problem(law);
    const int nc = lp.p.n_contacts();
    const size_t block = nc > 0 ? lp.warm.size() / nc : 1;
    int pushing = 0;
    for (int c = 0; c < nc; ++c) pushing += lp.warm[block * c] > 0.0;
    char line[200];
    std::snprintf(line, sizeof line,
                  "%d rows (%d pushing), warm start: apgd %d iterations, residual %.3g", nc,
                  pushing, lp.warm_iterations, lp.warm_residual);
    benchmark::AddCustomContext(std::string("problem_") + micro::law_name(law), line);
  }
  micro::register_operator_benchmarks();
  micro::register_solver_benchmarks();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
