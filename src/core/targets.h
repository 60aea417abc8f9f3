// Target terms: what changes only the affine part each row must reach (the gap D of eq. 15),
// not the set the multipliers may take. Applied in one place, to the rows of each solve round
// before it is solved: the overlap policy, a moving wall's velocity (+ h n . u_wall, from
// ContactProblem::wall_velocity) and restitution (clamp geometric overlaps first, then add
// velocity terms).
#pragma once

#include "contact_problem.h"
#include "kept_overlaps.h"

namespace hardcontact {

struct Targets {
  double recovery_speed;    // largest |h f / m| of the step (Bodies)
  double speed_scale;       // V of the candidate rows (core/residual.h)
  double tol;               // the solver tolerance

  // Restitution (Newton's law at velocity level), off while u_start is null: u^n per body
  // (ghosts included), the coefficient e of each row, and the approach speed below which
  // contacts stay inelastic.
  const std::vector<Vec3> *u_start = nullptr;
  const std::vector<double> *restitution = nullptr;
  double bounce_vmin = 0.0;
  // Kept overlaps (kept_overlaps.h), off while kept_overlaps is null or not active: the warm
  // start multipliers of the rows (block per row; rows beyond it did not push), where a
  // frictionless row that pushed (normal force > 0) keeps an overlap of up to kKeptOverlap tol
  // size.
  const std::vector<double> *warm = nullptr;
  int block = 1;
  KeptOverlaps *kept_overlaps = nullptr;
  // Rows first_row.. of p, added since the last call.
  void apply(ContactProblem &p, int first_row) const;
  // Whether row c may keep its overlap because it pushed in the last step (its warm normal
  // force > 0) while kept overlaps are active (kept_overlaps.h).
  bool pushed(int c) const;
};

}    // namespace hardcontact
