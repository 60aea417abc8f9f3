// Coulomb friction with rolling resistance: per contact the normal force, two tangential
// components and two rolling components, m = (m_n, m_t, m_r) in
//   K = {|m_t| <= mu m_n, |m_r| <= mur m_n}.
// A rolling component is a force m_r whose torque R m_r (R = a_i a_j / (a_i + a_j) from the
// arms, a_i for a wall) opposes the relative rolling of the pair: its row of G reads
// h R t_k . (w_j - w_i), so the rolling torque is at most mur R m_n, as the keyword promises.
// The dual cone of K is {g_n >= mu |g_t| + mur |g_r|}: De Saxce's shift is
// mu |g_t| + mur |g_r| (coulomb.h), which makes a sliding or rolling contact keep g_n = 0 and
// dissipate mu m_n |v_t| + mur m_n R |w_roll|.
#pragma once

#include "disc_law.h"

namespace hardcontact {

// The pair's relative rolling (t_1, t_2 of the relative spin): a force m_r whose torque R m_r
// (R = rolling_radius) opposes it, |m_r| <= mur m_n.
struct RollingDisc : CoupleDisc<0, RollingDisc> {
  static constexpr const char *keyword = "rolling";
  static constexpr const char *usage =
      "rolling mur [I J]: rolling resistance >= 0 (torque at most mur R F_n) for type pairs I J "
      "(all: default)";
  static constexpr const char *bound =
      "a coefficient >= 0 (the rolling torque is at most rolling x R x the normal force)";
  static constexpr int size = 2;
  static const Vec3 &axis(const ContactProblem &p, int c, int k)
  {
    return k == 0 ? p.tangent1[c] : p.tangent2[c];
  }
  // the spins couple each rolling row with the tangential row across it: h^2 R sum a / I
  static constexpr bool coupled = true;
  static double coupling(const ContactProblem &p, int c)
  {
    const int i = p.body_i[c], j = p.body_j[c];
    double couple = p.inv_inertia[i] * p.arm_i[c];
    if (!is_wall(j)) couple += p.inv_inertia[j] * p.arm_j[c];
    return couple * (p.h * p.h * p.rolling_radius(c));
  }
};

// two discs: the tangential force, then the rolling force, |m_r| <= rolling m_n
using RollingLaw = DiscLaw<TangentialDisc, RollingDisc>;

}    // namespace hardcontact
