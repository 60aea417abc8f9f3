// The project's throughput unit, contact-iterations per second (doc/performance.md section 3:
// rows x iterations / time), as Google Benchmark counters: one pass of a kernel over every
// row counts one contact-iteration per row, so a kernel's rate and a solver's read alike.
#pragma once

#include <benchmark/benchmark.h>

namespace micro {

// After the timed loop: rows of the problem, and the contact-iterations done in all of it.
inline void report_throughput(benchmark::State &state, int rows, double contact_iterations)
{
  state.counters["rows"] = rows;
  state.counters["contact_its"] =
      benchmark::Counter(contact_iterations, benchmark::Counter::kIsRate);
}

}    // namespace micro
