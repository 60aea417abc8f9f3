// A frictional law as one normal force and a list of discs that compose: per contact
// m = (m_n, m_1, ..., m_D), each m_q a pair of components bounded by its disc,
//   K = {m_n >= 0, |m_q| <= coef_q m_n for every q},
// with coef_0 the friction coefficient (the tangential disc, coulomb.h) and coef_1 the rolling
// one (rolling.h). The dual cone of K is {g_n >= sum_q coef_q |g_q|}: De Saxce's shift is
// sum_q coef_q |g_q|, which makes a sliding or rolling contact keep g_n = 0 and dissipate
// sum_q coef_q m_n |g_q| / h. CoulombLaw is DiscLaw<1>, RollingLaw DiscLaw<2>.
#pragma once

#include "law.h"

#include <algorithm>
#include <cmath>

namespace hardcontact {

template <int Discs>
struct DiscLaw {
  static_assert(Discs >= 1 && Discs <= 2, "Coefficients holds a friction and a rolling coefficient");
  static constexpr int block = 1 + 2 * Discs;
  // values a contact keeps between steps (the contact history): the force (normal and
  // tangential) and each further disc's force as box-frame vectors, which survive a new
  // tangent frame
  static constexpr int history = 3 * Discs;

  // disc q's coefficient: friction for the tangential disc, rolling for the rolling one
  static double coefficient(const Coefficients &k, int q) { return q == 0 ? k.friction : k.rolling; }

  // Euclidean projection onto K. One disc: itself inside, 0 in the polar cone
  // (coef |t| <= -n), else onto the cone's surface along the normal of the boundary. Several:
  // for a normal value n' the discs are independent, so the projection minimises
  // f(n') = (n' - n)^2 + sum_q (|m_q| - coef_q n')_+^2 over n' >= 0: f' is piecewise linear
  // and increasing, its root lies in the piece where the terms still outside their disc are
  // active; try the 2^D pieces.
  static void project(double *m, const Coefficients &k)
  {
    if constexpr (Discs == 1) {
      project_cone(m, k.friction);
    } else {
      const double n = m[0];
      double coef[Discs], len[Discs];
      for (int q = 0; q < Discs; ++q) {
        coef[q] = coefficient(k, q);
        len[q] = norm2(m[1 + 2 * q], m[2 + 2 * q]);
      }
      int outside = 0;
      while (outside < Discs && len[outside] <= coef[outside] * n) ++outside;
      if (outside == Discs) return;    // inside (n >= 0)
      // The minimiser is the root of the consistent piece; each piece's root is a candidate
      // and f picks among them (and 0): a point on or within round-off of several discs' edges
      // may find no piece consistent to the bit, and was sent to 0.
      const auto f = [&](double at) {
        double v = (at - n) * (at - n);
        for (int q = 0; q < Discs; ++q) {
          const double over = len[q] - coef[q] * at;
          if (over > 0.0) v += over * over;
        }
        return v;
      };
      double best = 0.0, best_f = f(0.0);
      for (int set = 1; set < (1 << Discs); ++set) {    // bit q: disc q outside at the root
        double num = n, den = 1.0;
        for (int q = 0; q < Discs; ++q)
          if (set & (1 << q)) {
            num += coef[q] * len[q];
            den += coef[q] * coef[q];
          }
        const double root = num / den;
        if (!(root > 0.0)) continue;
        const double at = f(root);
        if (at < best_f) {
          best = root;
          best_f = at;
        }
      }
      m[0] = best;
      for (int q = 0; q < Discs; ++q) {
        double *v = m + 1 + 2 * q;
        const double cap = coef[q] * best;
        if (len[q] > cap) {
          const double f = len[q] > 0.0 ? cap / len[q] : 0.0;
          v[0] *= f;
          v[1] *= f;
        }
      }
    }
  }
  // Euclidean projection of (m[0], m[1], m[2]) onto {|m_t| <= coef m_n}: the closed form of
  // one disc.
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

  // g = (g_n + s, g_1, ..., g_D): the shifted gap and each disc's displacement in the step.
  // No force: g must lie in the dual cone (g_n >= sum_q coef_q |g_q|; with s at its fixed
  // point, the real gap >= 0). A pushing contact: a disc that sticks (|m_q| < coef_q m_n)
  // asks g_q = 0; one that slides asks g_q against m_q; and g_n = sum_q coef_q |g_q|. With
  // p_q = m_q / (coef_q m_n) these read
  //   d_q = g_q + |g_q| p_q = 0,   d_n = g_n - sum_q coef_q |g_q| |p_q| = 0.
  static double violation(const double *g, const double *m, const Coefficients &k, double scale)
  {
    double unused;
    return violation(g, m, k, scale, unused, -1.0);
  }
  // The same for a largest violation over rows: a row at most floor may return floor instead
  // (most rows of a solve are far below the largest, and a bound without the norms of p_q and
  // d_q shows it: with |p_q| <= |p_q1| + |p_q2|, d_n <= |g_n| + sum_q coef_q |g_q| |p_q| and
  // |d_q| <= |g_q| (1 + |p_q|); the margin covers the round-off of either side, so the largest
  // is the same to the bit). Also gives shift(g, k) from the same norms: the solver needs both
  // every iteration (IterativeSolver::law_shift_).
  static double violation(const double *g, const double *m, const Coefficients &k, double scale,
                          double &shift, double floor)
  {
    double coef[Discs], gl[Discs];
    for (int q = 0; q < Discs; ++q) {
      coef[q] = coefficient(k, q);
      gl[q] = norm2(g[1 + 2 * q], g[2 + 2 * q]);
    }
    shift = coef[0] * gl[0];
    for (int q = 1; q < Discs; ++q) shift += coef[q] * gl[q];
    if (m[0] <= 0.0) {
      const double v = shift - g[0];
      return (v > 0.0 ? v : 0.0) / scale;
    }
    double ps[2 * Discs] = {};    // m_q / cap (0: no bound on the disc)
    double bn = std::abs(g[0]), bt = 0.0;
    for (int q = 0; q < Discs; ++q) {
      const double cap = coef[q] * m[0];
      if (cap <= 0.0) continue;    // no bound on this disc: no condition (frictionless row)
      ps[2 * q] = m[1 + 2 * q] / cap;
      ps[2 * q + 1] = m[2 + 2 * q] / cap;
      const double a = std::abs(ps[2 * q]) + std::abs(ps[2 * q + 1]);
      bn += coef[q] * gl[q] * a;
      bt = std::max(bt, gl[q] + gl[q] * a);
    }
    if (std::max(bn, bt) / scale * (1.0 + 1e-12) <= floor) return floor;
    double dn = g[0], worst = 0.0;
    for (int q = 0; q < Discs; ++q) {
      const double cap = coef[q] * m[0];
      if (cap <= 0.0) continue;
      const double p1 = ps[2 * q], p2 = ps[2 * q + 1];
      dn -= coef[q] * gl[q] * norm2(p1, p2);
      const double d = norm2(g[1 + 2 * q] + gl[q] * p1, g[2 + 2 * q] + gl[q] * p2);
      worst = worst > d ? worst : d;
    }
    dn = std::abs(dn);
    return (dn > worst ? dn : worst) / scale;
  }

  static double shift(const double *g, const Coefficients &k)
  {
    double s = coefficient(k, 0) * norm2(g[1], g[2]);
    for (int q = 1; q < Discs; ++q) s += coefficient(k, q) * norm2(g[1 + 2 * q], g[2 + 2 * q]);
    return s;
  }

  // The exact solve of one contact's law with the other contacts held (nonsmooth
  // Gauss-Seidel, solvers/nsgs.h), no shift needed. g: the unshifted gradient at m; d: the
  // diagonal of the contact's block of A (DualOperator::block_diagonals), equal within each
  // disc. With q = g - D m the gradient of the other contacts, Coulomb's three cases are:
  // take-off (m = 0) when the free gap q_n >= 0; else the normal force closes the gap,
  // m_n = -q_n / d_n (g_n = 0 exactly, so no lift-off: De Saxce's fixed point without its
  // loop); a disc sticks when the force that stops its motion, -q_q / d_q, lies in the disc of
  // radius coef_q m_n, else slides, its force on that disc's edge opposite to q_q. Each disc
  // takes its force from g and its own diagonal entry. For one disc the block is diagonal and
  // this is the exact solve; with several, the spins couple the discs' entries, so d must
  // dominate them (raised by the coupling: NsgsSolver), which makes this a convergent damped
  // step with the exact law's fixed point. A larger diagonal (a Gershgorin bound) gives the
  // same fixed point with a shorter step.
  static void local_solve(double *m, const double *g, const double *d, const Coefficients &k)
  {
    const double n = m[0] - g[0] / d[0];
    if (!(n > 0.0)) {
      for (int q = 0; q < block; ++q) m[q] = 0.0;
      return;
    }
    m[0] = n;
    for (int q = 0; q < Discs; ++q)
      disc(m + 1 + 2 * q, g + 1 + 2 * q, d[1 + 2 * q], coefficient(k, q) * n);
  }
  // The same local problem on the unshifted cone (SolverSettings::Cone::Convex): the point of
  // K nearest to m - D^-1 g in the metric of D. With y = D^(1/2) m, K stays a cone whose disc
  // q has the coefficient coef_q sqrt(d_q / d_n), so this is a Euclidean projection (project)
  // there; with several discs d as in local_solve (a damped step with the same fixed point).
  static void local_solve_convex(double *m, const double *g, const double *d,
                                 const Coefficients &k)
  {
    double root[block], y[block];
    for (int q = 0; q < block; ++q) {
      root[q] = std::sqrt(d[q]);
      y[q] = root[q] * (m[q] - g[q] / d[q]);
    }
    Coefficients scaled = k;
    scaled.friction *= root[1] / root[0];
    if constexpr (Discs > 1) scaled.rolling *= root[3] / root[0];
    project(y, scaled);
    for (int q = 0; q < block; ++q) m[q] = y[q] / root[q];
  }
  // One disc of local_solve: v = v - g / d, brought back to the disc of radius cap along
  // itself (the exact minimiser over the disc when the block's entries are equal).
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
