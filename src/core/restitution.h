// Restitution (Newton's law at velocity level): a row that was closing at the start of the step
// faster than vmin (v = n . (u_j - u_i) at u^n, v < -vmin) and that the free motion would close
// within the step is asked to leave with at least e |v|: its target becomes min(D', 0) + h e v
// (D' the gap after the overlap clamp of targets.h), so that g >= 0 reads
// n . (u_j - u_i)^{n+1} >= e |v| and no overlap. Against a moving wall v is relative to the
// wall and the target keeps h n . u_wall, so the rebound is relative to the wall too. The
// rebound speed is exact; the position of the impact within the step is not resolved (an error
// below h |v| in the gap). Rows in resting contact (v ~ 0) stay inelastic; e = 0 is the
// paper's scheme. The target is negative, so the energy test counts its work as allowed
// (residual.h).
#pragma once

#include "contact_problem.h"

#include <vector>

namespace hardcontact {

// Rows first.. of p, after Targets::apply: e per row, u^n per body (ghosts included).
void add_rebound_targets(ContactProblem &p, int first, const std::vector<double> &e,
                         const std::vector<Vec3> &u_start, double vmin);

}    // namespace hardcontact
