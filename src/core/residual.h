// The stopping criterion shared by every solver, so that they compare fairly.
//
// Each row's violation of the complementarity conditions (eq. 17-18) is measured against a
// length scale s_c = min(size_c, h V): the contact size r_i + r_j, or, when the fastest free
// relative approach speed V of the step covers less than a size in one step, the distance h V
// it covers. A gap error e of one row is a relative velocity error e / h; measured against h V
// it is a velocity error relative to V. Against the size alone, small steps would accept
// velocity errors of tol size / h, which feed energy into resting contacts (Prop. 3) and add
// up along chains of contacts.
#pragma once

#include "contact_problem.h"
#include "distributed_ops.h"
#include "dual_operator.h"
#include "laws/normal.h"

#include <vector>

namespace hardcontact {

// Gap errors below this fraction of the size are round-off in D_ij (a difference of
// coordinates): the scale never asks for less.
constexpr double kGapRoundoff = 1.0e-12;
// Relative round-off of a kinetic energy summed over bodies.
constexpr double kEnergyRoundoff = 1.0e-14;

// Violation of the complementarity conditions by a row of the paper's law, in units of its
// scale (laws/normal.h).
inline double row_violation(double g, double mu, double scale)
{
  return NormalLaw::violation(g, mu, scale);
}

// V, over all rows of all processes: the largest normal approach speed
// |n_c . (u_free_j - u_free_i)|. It scales every gap condition (the predicted gap, and with
// friction the normal condition of the cone, De Saxce's shift included).
double free_speed_scale(const ContactProblem &p, DistributedOps &ops);

// V_t, over all rows of all processes: the largest speed of the contact points relative to
// each other, |slip_velocity(c, u_free)| (the problem carries spins; its frames must be
// complete), whose normal part is the approach (a moving wall's normal speed is in its
// target, so only its tangential part counts, as in the slip). With p.contact_speed_scale
// (the fix's `speed contact`) the slip conditions of the frictional laws - a sticking disc's
// slip, a sliding disc's direction against its force - are measured against h max(V, V_t)
// instead of h V (WorkingSet's slip scales; laws/disc_law.h, violation). The fix's default
// with friction since 2026-12-07.
//
// Why: Coulomb's law constrains the slip as well as the approach, and in a packing that
// rearranges spheres slide past one another far faster than they approach, so the approach
// alone asks for slip directions right to a few 1e-4 of the slides. A sphere that rolls
// without slip adds nothing (its contact point does not move), and at rest V_t is V = g h
// (gravity moves every body alike: only wall rows feel it), so a resting packing is solved as
// under the approach alone. The gap conditions keep h V: measured against h V_t as well (the
// option's first form, one scale for every condition), a bed sliding on a floor opened its
// inner contacts by up to tol h V_t per step, lost 100-160 of its 740 contact rows to that
// dilation and came to rest agitated (16 iterations per step, creep 50 x the approach's); with
// the gap conditions at h V it keeps its contacts (727) and rests as quietly as under the
// approach (1.0 iteration per step) after a third of its iterations (bench/friction/README.md,
// "Two scales").
// The normal condition of a sticking contact holds mu |slip| (1 - |m_t| / (mu m_n)) (the
// shift's lift), so a stick well inside its cone is still held to h V in its slip; a slide
// on its cone's edge is held to h V_t in its direction.
double contact_speed_scale(const ContactProblem &p, DistributedOps &ops);

// s_c = min(size_c, h V), but tol s_c never below the round-off of the gap: kGapRoundoff
// size_c, or the host's absolute gap_roundoff (coordinates far larger than the sizes).
inline double row_scale(double size, double h, double speed_scale, double tol,
                        double gap_roundoff = 0.0)
{
  const double s = h * speed_scale < size ? h * speed_scale : size;
  const double roundoff = kGapRoundoff * size > gap_roundoff ? kGapRoundoff * size : gap_roundoff;
  return s * tol > roundoff ? s : roundoff / tol;
}

// Fills scale[c] = row_scale(...) for every row with V = p.speed_scale if the host gave it,
// else free_speed_scale(p); returns V.
double row_scales(const ContactProblem &p, double tol, DistributedOps &ops,
                  std::vector<double> &scale);

// This process's part of sum_c mu_c max(0, -target_c) over its counted rows: the work of
// clearing overlaps present at q^n (and of walls moving towards a sphere, whose h n . u_wall is
// in the target),
// plus the work of a wall sliding under a sphere through friction: the kinetic energy a step
// may gain (energy_within_bound).
// block: multipliers per row (the normal force first).
double clearing_work(const ContactProblem &p, const std::vector<double> &mu, int block = 1);

// The coefficients a law reads for row c (none for the normal law).
template <class Law>
Coefficients law_coefficients(const ContactProblem &p, int c)
{
  return Law::coefficients(p, c);
}

// Largest Law::violation over all rows of all processes, at u = u(mu) (op bound to the
// problem: the gradient of each row, shifts included).
template <class Law>
double residual(const DualOperator &op, const std::vector<double> &mu,
                const std::vector<Vec3> &u, const std::vector<double> &scale)
{
  constexpr int B = Law::block;
  const ContactProblem &p = op.problem();
  double r = 0.0;
  double g[B];
  const int nc = p.n_contacts();
  for (int c = 0; c < nc; ++c) {
    op.gap_block<Law>(c, u, g);
    const double v = Law::violation(g, &mu[static_cast<size_t>(B) * c],
                                    law_coefficients<Law>(p, c), scale[c]);
    r = r > v ? r : v;
  }
  return op.ops().max_all(r);
}

// Prop. 3 for an inexact solve. With A = h^2 G M^-1 G^T and g(mu) = D + h G u(mu),
//   1/2 |u(mu)|_M^2 - 1/2 |u_free|_M^2 = mu.g(mu) - mu.D - 1/2 mu.A mu,
// so the exact solution (mu.g = 0) never gains kinetic energy beyond the work mu.max(0, -D) of
// clearing overlaps present at q^n (none when D >= 0: then 0 is in K_h). An iterate within the
// row tolerance may: true when u gains at most that work plus round-off.
// With friction the kinetic energy includes the spins; the friction's own work is <= 0.
bool energy_within_bound(const ContactProblem &p, const std::vector<double> &mu,
                         const std::vector<Vec3> &u, DistributedOps &ops, int block = 1);

}    // namespace hardcontact
