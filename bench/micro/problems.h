// The contact problems the micro-benchmarks run on: one random packing made by the core unit
// tests' generator (tests/core/random_config.h), the same spheres and rows for every law, so
// that the laws' numbers differ by the cost of their blocks alone.
#pragma once

#include "contact_problem.h"
#include "solver.h"

#include <string>
#include <vector>

namespace micro {

using hardcontact::ContactLaw;
using hardcontact::ContactProblem;
using hardcontact::Vec3;

// A problem with the law's fields, and a start near its solution: a solver at work on a
// simulation starts from the last step's multipliers, so the benchmarks start there too.
struct LawProblem {
  ContactProblem p;
  std::vector<double> warm;     // multipliers, block(law) per row
  std::vector<Vec3> u;          // velocities at warm (eq. 16)
  double warm_residual = 0.0;   // of warm, by the solver that made it
  int warm_iterations = 0;
};

// Spheres of the packing (the --spheres option); set before the first problem() call.
void set_spheres(int n);
int spheres();

// Built on first use, then shared by every benchmark of the law.
const LawProblem &problem(ContactLaw law);

const char *law_name(ContactLaw law);
constexpr ContactLaw kLaws[] = {ContactLaw::Normal, ContactLaw::Coulomb, ContactLaw::Rolling};

}    // namespace micro
