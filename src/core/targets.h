// Target terms: what changes only the affine part each row must reach (eq. 15: the target
// beside the measured gap D), not the set the multipliers may take. Applied in one place, to
// the rows of each solve round before it is solved: the overlap policy and a moving wall's
// velocity (+ h n . u_wall, from ContactProblem::wall_velocity). An effect's own terms follow
// (restitution.h).
#pragma once

#include "contact_problem.h"
#include "kept_overlaps.h"

namespace hardcontact {

struct Targets {
  double recovery_speed;    // largest |h f / m| of the step (Bodies)
  double speed_scale;       // V of the candidate rows (core/residual.h)
  double tol;               // the solver tolerance

  // Kept overlaps (kept_overlaps.h), off while kept_overlaps is null or not active: the warm
  // start multipliers of the rows (block per row; rows beyond it did not push), where a
  // frictionless row that pushed (normal force > 0) keeps an overlap of up to kKeptOverlap tol
  // size.
  const std::vector<double> *warm = nullptr;
  int block = 1;
  KeptOverlaps *kept_overlaps = nullptr;
  // The targets of rows first_row.. of p (added since the last call, or 0: all again), from
  // their gaps.
  void apply(ContactProblem &p, int first_row) const;
  // Whether row c may keep its overlap because it pushed in the last step (its warm normal
  // force > 0) while kept overlaps are active (kept_overlaps.h).
  bool pushed(int c) const;
};

// n . u_wall of row c: the normal speed of its wall at the contact (0 for a pair or a wall at
// rest).
inline double wall_normal_speed(const ContactProblem &p, int c)
{
  return !p.wall_velocity.empty() && is_wall(p.body_j[c]) ? p.normal[c].dot(p.wall_velocity[c])
                                                           : 0.0;
}

}    // namespace hardcontact
