// Coulomb friction as a cone complementarity law: per contact the normal force and two
// tangential components, m = (m_n, m_t) in the cone K = {|m_t| <= coef m_n}. The dual of the
// paper's projection (section 3.3) keeps its form with G extended by the tangential rows of
// the contact points' relative velocity (rotations through the arms, contact_problem.h):
// minimise 1/2 m.A m + b.m over K, gradient g = (gap, h v_t) in displacement units.
//
// Its optimality (m in K, g in the dual cone, m.g = 0) alone would make a sliding contact
// separate by h coef |v_t| per step (the convex relaxation). De Saxce's bipotential removes
// it: the normal target is shifted by s = coef |g_t| (DualOperator::shift), and s is brought to
// a fixed point by the solver (IterativeSolver), so that a sliding contact has g_n = 0 and
// the contact does the work -coef m_n |v_t| <= 0.
#pragma once

#include "law.h"

#include <algorithm>
#include <cmath>

namespace hardcontact {

struct CoulombLaw {
  static constexpr int block = 3;
  // values a contact keeps between steps (the contact history): the force as a box-frame
  // vector, which survives a new tangent frame
  static constexpr int history = 3;

  // Euclidean projection onto K: itself inside, 0 in the polar cone (coef |t| <= -n), else
  // onto the cone's surface along the normal of the boundary.
  static void project(double *m, const Coefficients &k) { project_cone(m, k.friction); }
  // Euclidean projection of (m[0], m[1], m[2]) onto {|m_t| <= coef m_n}.
  static void project_cone(double *m, double coef)
  {
    const double n = m[0];
    const double t = norm2(m[1], m[2]);
    if (t <= coef * n) return;
    if (coef * t <= -n) {
      m[0] = m[1] = m[2] = 0.0;
      return;
    }
    const double a = (n + coef * t) / (1.0 + coef * coef);
    const double f = coef * a / t;
    m[0] = a;
    m[1] *= f;
    m[2] *= f;
  }

  // g = (g_n + s, g_t): the shifted gap and the tangential displacement of the step.
  // No force: g must lie in the dual cone (g_n >= coef |g_t|; with s at its fixed point, the
  // real gap >= 0). A pushing contact: stick (|m_t| < coef m_n) asks g_t = 0 and g_n = 0;
  // slide asks g_t against m_t and g_n = coef |g_t|. With q = m_t / (coef m_n) both read
  //   d_t = g_t + |g_t| q = 0,   d_n = g_n - coef |g_t| |q| = 0.
  static double violation(const double *g, const double *m, const Coefficients &k, double scale)
  {
    double unused;
    return violation(g, m, k, scale, unused, -1.0);
  }
  // The same for a largest violation over rows: a row at most floor may return floor instead
  // (most rows of a solve are far below the largest, and a bound without the norms of q and
  // d_t shows it: with |q| <= |q1| + |q2|, d_n <= |g_n| + coef |g_t| |q| and
  // |d_t| <= |g_t| (1 + |q|); the margin covers the round-off of either side, so the largest is
  // the same to the bit). Also gives shift(g, k) from the same |g_t|: the solver needs both
  // every iteration (IterativeSolver::law_shift_).
  static double violation(const double *g, const double *m, const Coefficients &k, double scale,
                          double &shift, double floor)
  {
    const double coef = k.friction;
    const double gt = norm2(g[1], g[2]);
    shift = coef * gt;
    if (m[0] <= 0.0) {
      const double v = coef * gt - g[0];
      return (v > 0.0 ? v : 0.0) / scale;
    }
    const double cap = coef * m[0];
    if (cap <= 0.0) return std::abs(g[0]) / scale;    // frictionless row: the normal law
    const double q1 = m[1] / cap, q2 = m[2] / cap;
    const double q = std::abs(q1) + std::abs(q2);
    const double bound = std::max(std::abs(g[0]) + coef * gt * q, gt + gt * q) / scale;
    if (bound * (1.0 + 1e-12) <= floor) return floor;
    const double dn = std::abs(g[0] - coef * gt * norm2(q1, q2));
    const double dt = norm2(g[1] + gt * q1, g[2] + gt * q2);
    return (dn > dt ? dn : dt) / scale;
  }

  static double shift(const double *g, const Coefficients &k)
  {
    return k.friction * norm2(g[1], g[2]);
  }

  // The exact solve of one contact's true Coulomb law with the other contacts held
  // (nonsmooth Gauss-Seidel, solvers/nsgs.h), no shift needed. g: the unshifted gradient
  // (gap, h v_t) at m; d: the diagonal of the contact's block of A, which is diagonal with
  // equal tangential entries (DualOperator::block_diagonals), so the block decouples. With
  // q = g - D m the gradient of the other contacts, the three cases of Coulomb's law are:
  // take-off (m = 0) when the free gap q_n >= 0; else the normal force closes the gap,
  // m_n = -q_n / d_n (g_n = 0 exactly, so no lift-off: De Saxce's fixed point without its
  // loop); stick when the force that stops the slip, -q_t / d_t, lies in the disc of radius
  // coef m_n; else slide, the tangential force on that disc's edge opposite to q_t (then
  // g_t = q_t + d_t m_t is parallel to q_t: the force opposes the slip). A larger diagonal
  // (a Gershgorin bound) gives the same fixed point with a shorter step.
  static void local_solve(double *m, const double *g, const double *d, const Coefficients &k)
  {
    const double n = m[0] - g[0] / d[0];
    if (!(n > 0.0)) {
      m[0] = m[1] = m[2] = 0.0;
      return;
    }
    m[0] = n;
    disc(m + 1, g + 1, d[1], k.friction * n);
  }
  // The disc part of local_solve: v = v - g / d, brought back to the disc of radius cap
  // along itself (the exact minimiser over the disc when the block's entries are equal).
  static void disc(double *v, const double *g, double d, double cap)
  {
    const double a = v[0] - g[0] / d, b = v[1] - g[1] / d;
    const double len = norm2(a, b);
    const double f = len > cap ? cap / len : 1.0;
    v[0] = a * f;
    v[1] = b * f;
  }
};

}    // namespace hardcontact
