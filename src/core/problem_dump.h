// A developer's view of one solve: the frictionless dual problem of eq. 15 as the solver
// receives it (bodies, rows, gaps, tolerance scales, start multipliers), written as text so
// that the operator A = h^2 G M^-1 G^T can be rebuilt and studied outside LAMMPS (its spectrum,
// preconditioners; bench/studies/spectrum). Not a user output: enabled by the environment variable
// HARDCONTACT_DUMP_PROBLEMS (bench/studies/spectrum 10), costs one branch per solve
// otherwise.
#pragma once

#include "contact_problem.h"

#include <string>
#include <vector>

namespace hardcontact {

// Format (one record per line, %.17g):
//   "hardcontact-problem 1" n_bodies n_owned n_rows h tol
//   n_bodies lines: inv_mass u_free.x u_free.y u_free.z
//   n_rows lines:   body_i body_j n.x n.y n.z target size scale mu_start
// (target: the row's affine part as solved, the measured gap unless a target term moved it)
// body_j < 0 is a wall (contact_problem.h). Returns false if the file cannot be written.
bool write_problem(const std::string &path, const ContactProblem &p,
                   const std::vector<double> &scales, const std::vector<double> &mu_start,
                   double tol);

}    // namespace hardcontact
