#include "restitution.h"

#include "targets.h"

namespace hardcontact {

void add_rebound_targets(ContactProblem &p, int first, const std::vector<double> &e,
                         const std::vector<Vec3> &u_start, double vmin)
{
  const int nc = p.n_contacts();
  const double h = p.h;
  for (int c = first; c < nc; ++c) {
    if (e[c] <= 0.0) continue;
    const double d = p.gap[c];
    const double wall_speed = wall_normal_speed(p, c);
    const double v = p.normal_speed(c, u_start) + wall_speed;
    const double v_free = p.normal_speed(c, p.u_free) + wall_speed;
    if (v >= -vmin || d + h * v_free >= 0.0) continue;
    // The target so far is D' + h n . u_wall, and D' <= 0 unless the row is open (D > 0:
    // the clamp leaves it as it is): min(D', 0) + h n . u_wall is then the target itself, or
    // the wall's term alone.
    p.target[c] = (d > 0.0 ? h * wall_speed : p.target[c]) + h * e[c] * v;
  }
}

}    // namespace hardcontact
