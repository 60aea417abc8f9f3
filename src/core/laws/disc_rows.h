// The discs a frictional law composes (disc_law.h), each with its rows of G: what its
// components read from the bodies' velocities (eq. 15 extended by the contact point's motion)
// and what its multipliers push (eq. 16), its entries of the block A_cc = h^2 G_c M^-1 G_c^T,
// the coefficient bounding it and the work it dissipates. DualOperator applies any law through
// these, without knowing which discs it holds. TangentialDisc (Coulomb) is here; a resistance
// (rolling.h, twisting.h) is a struct deriving from ResistanceDisc<index> (or CoupleDisc, a
// resistance whose multipliers are a couple about its axes: every row member but the axes and
// the coupling), in its law's file, with a line in law_list.h (HARDCONTACT_RESISTANCES): its
// coefficient, its keyword and its per-row values then come from that index.
//
// Members (p the problem, c the row, m or g the disc's own components):
//   size                         components (2: a plane such as the tangential one; 1: an axis)
//   resistance_bit               1 << index for a resistance, 0 for the tangential disc
//   coefficient(k)               its bound coef in |m_q| <= coef m_n (a reference: apgd scales it)
//   row_coefficient(p, c)        the row's coefficient from the problem
//   axis(p, c, k)                component k's direction in the box frame (the contact history
//                                keeps a disc as the vector sum_k m_k axis_k)
//   gap(p, c, u, v, g)           its components of h G_c u, with v = h v_slip (contact_problem.h)
//   add_linear(p, c, m, f)       adds the force of its multipliers at the contact point (on j)
//   own_torque                   true if its multipliers are a torque of their own (else only
//                                its force's, through the arms)
//   push_spins(p, c, m, h, i, j, spin_i, spin_j)
//                                the spins' change of an impulse h m that is a torque of its own
//                                (spin_i, spin_j: the bodies' spins, null when not owned here)
//   add_torque(p, c, m, ti, tj)  the same torque, added to the bodies' torques
//   diagonals(p, c, b, d)        its entries of A_cc (d[0..size)); b: the row's bodies and h^2
//   angular_trace(p, c, arm)     its rows' share of the trace of A_cc per unit of 1 / I of a body
//                                whose arm is arm (rows along the arms: 2 arm^2)
//   coupled, coupling(p, c)      whether the spins couple its rows with the tangential ones, and
//                                the off-diagonal entries that do (h^2 times)
//   work(p, c, m, u, u_free)     h m . (its mean rate over the step): what it dissipates
#pragma once

#include "../contact_problem.h"
#include "law.h"

namespace hardcontact {

// What every disc's entries of A_cc read, found once per row.
struct RowBodies {
  int i, j;
  bool wall;
  double h2;    // h^2
};

// The contact point's slip (t_1, t_2): Coulomb friction, |m_t| <= mu m_n.
struct TangentialDisc {
  static constexpr int size = 2;
  static constexpr unsigned resistance_bit = 0;
  static constexpr bool own_torque = false;
  static double coefficient(const Coefficients &k) { return k.friction; }
  static double &coefficient(Coefficients &k) { return k.friction; }
  static double row_coefficient(const ContactProblem &p, int c) { return p.friction[c]; }
  static const Vec3 &axis(const ContactProblem &p, int c, int k)
  {
    return k == 0 ? p.tangent1[c] : p.tangent2[c];
  }
  static void gap(const ContactProblem &p, int c, const std::vector<Vec3> &, const Vec3 &v,
                  double *g)
  {
    g[0] = p.tangent1[c].dot(v);
    g[1] = p.tangent2[c].dot(v);
  }
  // one term at a time: the sum n m_n + t_1 m_1 + t_2 m_2 in that order
  static void add_linear(const ContactProblem &p, int c, const double *m, Vec3 &f)
  {
    f += m[0] * p.tangent1[c];
    f += m[1] * p.tangent2[c];
  }
  // its torque is the arms' (DualOperator: the force at -a_j n on j, +a_i n on i)
  static void push_spins(const ContactProblem &, int, const double *, double, int, int, Vec3 *,
                         Vec3 *)
  {
  }
  static void add_torque(const ContactProblem &, int, const double *, Vec3 &, Vec3 &) {}
  // h^2 sum (w + a^2 / I) on both: n, t_1, t_2 are orthonormal and n x n = 0, so the block of
  // the normal and tangential rows is diagonal
  static void diagonals(const ContactProblem &p, int c, const RowBodies &b, double *d)
  {
    double t = p.inv_mass[b.i] + p.inv_inertia[b.i] * p.arm_i[c] * p.arm_i[c];
    if (!b.wall) t += p.inv_mass[b.j] + p.inv_inertia[b.j] * p.arm_j[c] * p.arm_j[c];
    d[0] = d[1] = b.h2 * t;
  }
  // The largest entry of the block when it is this disc's alone (the tangential entry).
  static double largest(const ContactProblem &p, int c)
  {
    const int i = p.body_i[c], j = p.body_j[c];
    double d = p.inv_mass[i];
    if (p.rotates()) d += p.inv_inertia[i] * p.arm_i[c] * p.arm_i[c];
    if (!is_wall(j)) {
      d += p.inv_mass[j];
      if (p.rotates()) d += p.inv_inertia[j] * p.arm_j[c] * p.arm_j[c];
    }
    return p.h * p.h * d;
  }
  static double angular_trace(const ContactProblem &, int, double arm) { return 2.0 * arm * arm; }
  static constexpr bool coupled = false;
  static double coupling(const ContactProblem &, int) { return 0.0; }
  // h F_t . (mean slip of the step): the work Coulomb's force does (<= 0: it opposes the slip)
  static double work(const ContactProblem &p, int c, const double *m, const std::vector<Vec3> &u,
                     const std::vector<Vec3> &u_free)
  {
    const Vec3 ft = m[0] * p.tangent1[c] + m[1] * p.tangent2[c];
    const Vec3 slip = 0.5 * (p.slip_velocity(c, u) + p.slip_velocity(c, u_free));
    return p.h * ft.dot(slip);
  }
};

// A resistance beyond Coulomb's: its coefficient is resistance[Index] of the row's
// Coefficients and of ContactProblem (per type pair in the adapter: its keyword, `keyword mu
// [I J]`, from the derived disc's keyword, usage and bound).
template <int Index>
struct ResistanceDisc {
  static_assert(Index >= 0 && Index < kResistances, "a resistance index below kResistances");
  static constexpr int index = Index;
  static constexpr unsigned resistance_bit = 1u << Index;
  static double coefficient(const Coefficients &k) { return k.resistance[Index]; }
  static double &coefficient(Coefficients &k) { return k.resistance[Index]; }
  static double row_coefficient(const ContactProblem &p, int c) { return p.resistance[Index][c]; }
};

// A resistance whose multipliers are a couple of its own: m_k along its orthonormal axes
// (Disc::axis, Disc::size of them) with moment R = rolling_radius, opposing the pair's
// relative spin along those axes (rolling: the tangents, twisting: the normal). Its rows read
// h R axis_k . (w_j - w_i), it pushes no force, and its entries of A_cc are
// h^2 R^2 (1/I_i + 1/I_j) on every axis. Disc gives the axes, the texts and the coupling.
template <int Index, class Disc>
struct CoupleDisc : ResistanceDisc<Index> {
  static constexpr bool own_torque = true;
  // sum_k m_k axis_k
  static Vec3 along_axes(const ContactProblem &p, int c, const double *m)
  {
    if constexpr (Disc::size == 2)
      return m[0] * Disc::axis(p, c, 0) + m[1] * Disc::axis(p, c, 1);
    else
      return m[0] * Disc::axis(p, c, 0);
  }
  // h R axis_k . (w_j - w_i)
  static void gap(const ContactProblem &p, int c, const std::vector<Vec3> &u, const Vec3 &,
                  double *g)
  {
    const Vec3 turn = (p.h * p.rolling_radius(c)) * p.relative_spin(c, u);
    g[0] = Disc::axis(p, c, 0).dot(turn);
    if constexpr (Disc::size == 2) g[1] = Disc::axis(p, c, 1).dot(turn);
  }
  static void add_linear(const ContactProblem &, int, const double *, Vec3 &) {}
  // the angular impulse h R sum_k m_k axis_k on j, its opposite on i
  static void push_spins(const ContactProblem &p, int c, const double *m, double h, int i, int j,
                         Vec3 *spin_i, Vec3 *spin_j)
  {
    const Vec3 twist = (h * p.rolling_radius(c)) * along_axes(p, c, m);
    if (spin_i) *spin_i -= p.inv_inertia[i] * twist;
    if (spin_j) *spin_j += p.inv_inertia[j] * twist;
  }
  static void add_torque(const ContactProblem &p, int c, const double *m, Vec3 &ti, Vec3 &tj)
  {
    const Vec3 twist = p.rolling_radius(c) * along_axes(p, c, m);
    ti -= twist;
    tj += twist;
  }
  // h^2 R^2 (1/I_i + 1/I_j)
  static void diagonals(const ContactProblem &p, int c, const RowBodies &b, double *d)
  {
    const double r = p.rolling_radius(c);
    d[0] = b.h2 * r * r * (p.inv_inertia[b.i] + (b.wall ? 0.0 : p.inv_inertia[b.j]));
    if constexpr (Disc::size == 2) d[1] = d[0];
  }
  static double angular_trace(const ContactProblem &p, int c, double)
  {
    const double r = p.rolling_radius(c);
    return Disc::size * (r * r);
  }
  // h R m . (w_j - w_i), mean spin of the step
  static double work(const ContactProblem &p, int c, const double *m, const std::vector<Vec3> &u,
                     const std::vector<Vec3> &u_free)
  {
    const Vec3 spin = 0.5 * (p.relative_spin(c, u) + p.relative_spin(c, u_free));
    return p.h * p.rolling_radius(c) * along_axes(p, c, m).dot(spin);
  }
};

}    // namespace hardcontact
