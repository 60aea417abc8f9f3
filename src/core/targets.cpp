#include "targets.h"

#include <algorithm>

namespace hardcontact {

// Overlap policy: a pair overlapping at q^n (D < 0) is asked to separate by no more than h
// times the largest velocity the external forces give in one step (g h under gravity), plus
// twice the solver tolerance on its row scale (residual.h). The first part does not feed on
// itself: clearing overlaps adds at most about m (g h)^2 per atom and step, and with no force
// large overlaps stay as they are. The second clears what a solve stopped at tol leaves (at
// most tol times the scale per step), so such overlaps never add up. For D >= 0, the normal
// case, this is eq. 15 unchanged.
void Targets::apply(ContactProblem &p, int first_row) const
{
  const int nc = p.n_contacts();
  const double h = p.h;
  for (int c = first_row; c < nc; ++c) {
    if (p.gap[c] >= 0.0) continue;
    // the row scale without its round-off floor: at rest with no force nothing may move
    const double s = std::min(p.size[c], h * speed_scale);
    p.gap[c] = std::max(p.gap[c], -(h * recovery_speed + 2.0 * tol * s));
  }
}

}    // namespace hardcontact
