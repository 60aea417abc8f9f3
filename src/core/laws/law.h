// What every contact law shares. A law is the set the multipliers of one contact may take;
// the solvers are written against this interface (templates, no virtual call per contact):
//   history                 values a contact keeps between steps (src/lammps/contact_history.h)
//   block                   multipliers per contact, and components of g, the gradient of the
//                           dual: the predicted gap first, then (friction) tangential
//                           displacements h t_k . v_slip, then (rolling) h R t_k . (w_j - w_i)
//   project(m, k)           the nearest admissible block m[0..block) (the projection of the
//                           dual method, section 3.3), k: the row's coefficients
//   violation(g, m, k, s)   how far (g, m) is from complementarity, in units of the row scale s
//   violation(g, m, k, s, st, shift, floor)   (friction) the same for a largest one over
//                           rows, its slip conditions in units of st: floor for a row shown
//                           to be at most floor; also shift(g, k)
//   shift(g, k)             the normal target shift that removes the convex relaxation's
//                           lift-off at the fixed point (De Saxce), 0 for the normal law
//   local_solve(m, g, d, k) the law of one contact solved with the others held, from its
//                           unshifted gradient g at m and a diagonal d of its block of A
//                           (nonsmooth Gauss-Seidel, solvers/nsgs.h)
#pragma once

#include "../contact_problem.h"

#include <cmath>

namespace hardcontact {

// |(a, b)| for the tangential pairs of the laws: sqrt(a^2 + b^2), within an ulp of std::hypot,
// whose care for squares beyond the doubles' range (|a| above 1e154 or below 1e-154, far
// outside the forces and displacements of any grain in any LAMMPS units) cost 34 % of a
// frictional pile's solve (968 spheres, apgd, perf) against a few % for the square root.
inline double norm2(double a, double b) { return std::sqrt(a * a + b * b); }

// The coefficients of one row (ContactProblem::friction, ::resistance): what a law reads.
// friction bounds the tangential disc; resistance[r] the disc whose index is r (a
// ResistanceDisc, disc_rows.h: rolling 0, twisting 1, ...).
struct Coefficients {
  double friction = 0.0;
  double resistance[kResistances] = {};
};

}    // namespace hardcontact
