// Coulomb friction with twisting resistance: per contact the normal force, two tangential
// components and one twisting component, m = (m_n, m_t, m_w) in
//   K = {|m_t| <= mu m_n, |m_w| <= mut m_n}.
// The twisting component is a force-like multiplier m_w whose torque R m_w n about the normal
// (R = rolling_radius: a_i a_j / (a_i + a_j) from the arms, a_i on a wall) opposes the pair's
// relative spin about the normal: its row of G reads h R n . (w_j - w_i), so the twisting
// torque is at most mut R m_n, as the keyword promises. n is orthogonal to both tangents,
// so the spins do not couple this row with the tangential or rolling ones (a disc of its own,
// uncoupled). De Saxce's shift gains mut |g_w|: a contact that twists keeps g_n = 0 and
// dissipates mut m_n R |n . (w_j - w_i)| (disc_law.h).
#pragma once

#include "disc_law.h"
#include "rolling.h"

namespace hardcontact {

// The pair's relative spin about the normal: a torque R m_w n on j (its opposite on i),
// |m_w| <= mut m_n.
struct TwistingDisc : ResistanceDisc<1> {
  static constexpr const char *keyword = "twisting";
  static constexpr const char *usage =
      "twisting mut [I J]: twisting resistance >= 0 (torque about the normal at most mut R F_n) "
      "for type pairs I J (all: default)";
  static constexpr const char *bound =
      "a coefficient >= 0 (the twisting torque is at most twisting x R x the normal force)";
  static constexpr int size = 1;
  static constexpr bool own_torque = true;
  static const Vec3 &axis(const ContactProblem &p, int c, int) { return p.normal[c]; }
  // h R n . (w_j - w_i)
  static void gap(const ContactProblem &p, int c, const std::vector<Vec3> &u, const Vec3 &,
                  double *g)
  {
    g[0] = (p.h * p.rolling_radius(c)) * p.normal[c].dot(p.relative_spin(c, u));
  }
  static void add_linear(const ContactProblem &, int, const double *, Vec3 &) {}
  // the angular impulse h R m_w n on j, its opposite on i
  static void push_spins(const ContactProblem &p, int c, const double *m, double h, int i, int j,
                         Vec3 *spin_i, Vec3 *spin_j)
  {
    const Vec3 twist = (h * p.rolling_radius(c) * m[0]) * p.normal[c];
    if (spin_i) *spin_i -= p.inv_inertia[i] * twist;
    if (spin_j) *spin_j += p.inv_inertia[j] * twist;
  }
  static void add_torque(const ContactProblem &p, int c, const double *m, Vec3 &ti, Vec3 &tj)
  {
    const Vec3 twist = (p.rolling_radius(c) * m[0]) * p.normal[c];
    ti -= twist;
    tj += twist;
  }
  // h^2 R^2 (1/I_i + 1/I_j)
  static void diagonals(const ContactProblem &p, int c, const RowBodies &b, double *d)
  {
    const double r = p.rolling_radius(c);
    d[0] = b.h2 * r * r * (p.inv_inertia[b.i] + (b.wall ? 0.0 : p.inv_inertia[b.j]));
  }
  static double angular_trace(const ContactProblem &p, int c, double)
  {
    const double r = p.rolling_radius(c);
    return r * r;
  }
  // n is orthogonal to the tangents: no entry of A couples this row with the others
  static constexpr bool coupled = false;
  static double coupling(const ContactProblem &, int) { return 0.0; }
  // h m_w R n . (w_j - w_i), mean spin of the step
  static double work(const ContactProblem &p, int c, const double *m, const std::vector<Vec3> &u,
                     const std::vector<Vec3> &u_free)
  {
    const Vec3 spin = 0.5 * (p.relative_spin(c, u) + p.relative_spin(c, u_free));
    return p.h * p.rolling_radius(c) * m[0] * p.normal[c].dot(spin);
  }
};

// two discs: the tangential force, then the twisting one, |m_w| <= twisting m_n
using TwistingLaw = DiscLaw<TangentialDisc, TwistingDisc>;
// three: the tangential force, the rolling force, the twisting one
using RollingTwistingLaw = DiscLaw<TangentialDisc, RollingDisc, TwistingDisc>;

}    // namespace hardcontact
