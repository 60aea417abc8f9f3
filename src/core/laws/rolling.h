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
struct RollingDisc : ResistanceDisc<0> {
  static constexpr const char *keyword = "rolling";
  static constexpr const char *usage =
      "rolling mur [I J]: rolling resistance >= 0 (torque at most mur R F_n) for type pairs I J "
      "(all: default)";
  static constexpr const char *bound =
      "a coefficient >= 0 (the rolling torque is at most rolling x R x the normal force)";
  static constexpr int size = 2;
  static constexpr bool own_torque = true;
  static const Vec3 &axis(const ContactProblem &p, int c, int k)
  {
    return k == 0 ? p.tangent1[c] : p.tangent2[c];
  }
  // h R t_k . (w_j - w_i)
  static void gap(const ContactProblem &p, int c, const std::vector<Vec3> &u, const Vec3 &,
                  double *g)
  {
    const Vec3 roll = (p.h * p.rolling_radius(c)) * p.relative_spin(c, u);
    g[0] = p.tangent1[c].dot(roll);
    g[1] = p.tangent2[c].dot(roll);
  }
  static void add_linear(const ContactProblem &, int, const double *, Vec3 &) {}
  // the angular impulse h R (m_r1 t_1 + m_r2 t_2) on j, its opposite on i
  static void push_spins(const ContactProblem &p, int c, const double *m, double h, int i, int j,
                         Vec3 *spin_i, Vec3 *spin_j)
  {
    const Vec3 twist = (h * p.rolling_radius(c)) * (m[0] * p.tangent1[c] + m[1] * p.tangent2[c]);
    if (spin_i) *spin_i -= p.inv_inertia[i] * twist;
    if (spin_j) *spin_j += p.inv_inertia[j] * twist;
  }
  static void add_torque(const ContactProblem &p, int c, const double *m, Vec3 &ti, Vec3 &tj)
  {
    const Vec3 twist = p.rolling_radius(c) * (m[0] * p.tangent1[c] + m[1] * p.tangent2[c]);
    ti -= twist;
    tj += twist;
  }
  // h^2 R^2 (1/I_i + 1/I_j)
  static void diagonals(const ContactProblem &p, int c, const RowBodies &b, double *d)
  {
    const double r = p.rolling_radius(c);
    d[0] = d[1] = b.h2 * r * r * (p.inv_inertia[b.i] + (b.wall ? 0.0 : p.inv_inertia[b.j]));
  }
  static double angular_trace(const ContactProblem &p, int c, double)
  {
    const double r = p.rolling_radius(c);
    return 2.0 * (r * r);
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
  // h m_r . R (w_j - w_i), mean spin of the step
  static double work(const ContactProblem &p, int c, const double *m, const std::vector<Vec3> &u,
                     const std::vector<Vec3> &u_free)
  {
    const Vec3 fr = m[0] * p.tangent1[c] + m[1] * p.tangent2[c];
    const Vec3 roll = 0.5 * (p.relative_spin(c, u) + p.relative_spin(c, u_free));
    return p.h * p.rolling_radius(c) * fr.dot(roll);
  }
};

// two discs: the tangential force, then the rolling force, |m_r| <= rolling m_n
using RollingLaw = DiscLaw<TangentialDisc, RollingDisc>;

}    // namespace hardcontact
