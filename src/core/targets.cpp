#include "targets.h"

#include <algorithm>

namespace hardcontact {

namespace {
// With friction, an overlap shallower than kKeptOverlap tol size is kept rather than cleared
// (its target is 0: it may not deepen), and near s = size less, so that a solve leaves at most
// tol size (f_ID[7] <= tol). A packing at rest is held by static friction: pushing apart the
// overlaps a solve left at tol asks for a motion its sticking contacts forbid, the problem
// then nearly has no solution, its forces drift without bound and solves stall at maxiter
// (bench/studies/friction_rest: a tray under a sphere of 1000 x the
// mass, at rest, 1869 -> 46 iterations per step and 23 -> 0 of 200 solves at maxiter; a
// 968-sphere pile at rest 102 -> 47).
// Without friction clearing stays for every row but those that pushed in the last step (the
// warm start's force > 0), and only while that keeps solves short (kept_overlaps.h): keeping
// every frictionless overlap, a frictionless tray under a heavy sphere needed more iterations
// (27 -> 62 per step: rows at a target of 0 that do not push carry no force uniquely), and
// keeping in every step stalls the solves of tight crystals (bench/studies/subspace_default, kept_overlaps).
// A tenth: on the tray a hundredth still stalled (510 iterations
// per step, a solve at maxiter), 0.3 and all of tol size gave the same iterations, and with
// all of it curved walls, whose linearisation errs by (v h)^2 / (2 R) on top, went past tol
// size in the drum (1.4e-4 at tol 1e-4; a tenth: 4.8e-5). What a tenth costs in accuracy: a
// resting frictional sphere sinks up to tol size / 10 into its support, and its rolling radius
// is shorter by as much (tests/integration/test_phys_friction.py, HEIGHT and ROLL_V).
constexpr double kKeptOverlap = 0.1;
}    // namespace

// Overlap policy: a pair overlapping at q^n (D < 0) is asked to separate by no more than h
// times the largest velocity the external forces give in one step (g h under gravity), plus
// twice the solver tolerance on its row scale (residual.h). The first part does not feed on
// itself: clearing overlaps adds at most about m (g h)^2 per atom and step, and with no force
// large overlaps stay as they are. The second clears what a solve stopped at tol leaves (at
// most tol times the scale per step), so such overlaps never add up. For D >= 0, the normal
// case, this is eq. 15 unchanged.
// A moving wall: its velocity over the step enters as + h n . u_wall, after the overlap clamp
// (the wall's motion is not an overlap to limit), so that g >= 0 keeps the sphere clear of
// where the wall will be; the work the wall does is allowed as a negative target (residual.h).
// The measured gap D stays as it is: the targets are written beside it, so they can be written
// again from it (KeptOverlaps::undo) and an effect's term can read both (restitution.h).
void Targets::apply(ContactProblem &p, int first_row) const
{
  const int nc = p.n_contacts();
  const double h = p.h;
  p.target.resize(nc);
  for (int c = first_row; c < nc; ++c) {
    const double d = p.gap[c];
    double target = d;
    if (d < 0.0) {
      // the row scale without its round-off floor: at rest with no force nothing may move
      const double s = std::min(p.size[c], h * speed_scale);
      // what may be kept: up to kKeptOverlap tol size, and never more than tol (size - s):
      // with the solve's own tol s on top, at most tol size is left (f_ID[7])
      const double shallow = tol * std::min(kKeptOverlap * p.size[c], p.size[c] - s);
      // a frictional row keeps that much of any overlap
      const bool frictional = !p.friction.empty() && p.friction[c] > 0.0;
      target = std::max(std::min(0.0, d + (frictional ? shallow : 0.0)),
                        -(h * recovery_speed + 2.0 * tol * s));
      // a frictionless row that pushed keeps all of a shallow overlap: the paper's target is
      // raised to 0 (KeptOverlaps::undo has them written again with the paper's)
      if (!frictional && -d <= shallow && pushed(c)) {
        kept_overlaps->raised();
        target = 0.0;
      }
    }
    // a moving wall: g = D + h n . (u_wall - u_i), the gap to where the wall will be
    const double wall_speed = wall_normal_speed(p, c);
    if (wall_speed != 0.0) target += h * wall_speed;
    p.target[c] = target;
  }
}

bool Targets::pushed(int c) const
{
  if (kept_overlaps == nullptr || !kept_overlaps->active() || warm == nullptr) return false;
  const size_t at = static_cast<size_t>(block) * c;
  return at < warm->size() && (*warm)[at] > 0.0;
}

}    // namespace hardcontact
