// The benchmarks main() registers, in the order they run and print.
#pragma once

namespace micro {

// operator/<product>/<law>, residual/<law>, project/<law> (operator_kernels.cpp)
void register_operator_benchmarks();
// solver/<name>/<law>/<iterations per solve> (solver_iterations.cpp)
void register_solver_benchmarks();

}    // namespace micro
