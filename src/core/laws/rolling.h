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

#include "coulomb.h"
#include "law.h"

#include <algorithm>
#include <cmath>

namespace hardcontact {

struct RollingLaw {
  static constexpr int block = 5;
  // values a contact keeps between steps (the contact history): the force and the rolling
  // force as box-frame vectors
  static constexpr int history = 6;

  // Euclidean projection onto K. For a normal value n' the two discs are independent, so the
  // projection minimises f(n') = (n' - n)^2 + (|t| - mu n')_+^2 + (|r| - mur n')_+^2 over
  // n' >= 0: f' is piecewise linear and increasing, its root lies in the piece where the
  // terms still outside their disc are active; try the (at most four) pieces.
  static void project(double *m, const Coefficients &k)
  {
    const double n = m[0];
    const double coef[2] = {k.friction, k.rolling};
    const double len[2] = {norm2(m[1], m[2]), norm2(m[3], m[4])};
    if (len[0] <= coef[0] * n && len[1] <= coef[1] * n) return;    // inside (n >= 0)
    double best = 0.0;
    for (int set = 0; set < 4; ++set) {    // bit q: term q outside its disc at the root
      double num = n, den = 1.0;
      for (int q = 0; q < 2; ++q)
        if (set & (1 << q)) {
          num += coef[q] * len[q];
          den += coef[q] * coef[q];
        }
      const double root = num / den;
      if (root < 0.0) continue;
      bool consistent = true;
      for (int q = 0; q < 2; ++q) {
        const bool outside = len[q] > coef[q] * root;
        consistent = consistent && outside == ((set & (1 << q)) != 0);
      }
      if (consistent) {
        best = root;
        break;
      }
    }
    m[0] = best;
    for (int q = 0; q < 2; ++q) {
      double *v = m + 1 + 2 * q;
      const double cap = coef[q] * best;
      if (len[q] > cap) {
        const double f = len[q] > 0.0 ? cap / len[q] : 0.0;
        v[0] *= f;
        v[1] *= f;
      }
    }
  }

  // As coulomb.h, with the rolling pair beside the tangential one: g = (g_n + s, g_t, g_r).
  static double violation(const double *g, const double *m, const Coefficients &k, double scale)
  {
    double unused;
    return violation(g, m, k, scale, unused, -1.0);
  }
  // The same for a largest violation over rows, giving floor for a row shown to be at most
  // floor by the bound of coulomb.h pair by pair; also shift(g, k) from the same norms.
  static double violation(const double *g, const double *m, const Coefficients &k, double scale,
                          double &shift, double floor)
  {
    const double coef[2] = {k.friction, k.rolling};
    const double gl[2] = {norm2(g[1], g[2]), norm2(g[3], g[4])};
    shift = coef[0] * gl[0] + coef[1] * gl[1];
    if (m[0] <= 0.0) {
      const double v = shift - g[0];
      return (v > 0.0 ? v : 0.0) / scale;
    }
    double qs[4] = {0.0, 0.0, 0.0, 0.0};    // m_t / cap, m_r / cap (0: no bound on the pair)
    double bn = std::abs(g[0]), bt = 0.0;
    for (int q = 0; q < 2; ++q) {
      const double cap = coef[q] * m[0];
      if (cap <= 0.0) continue;    // no bound on this pair: no condition
      qs[2 * q] = m[1 + 2 * q] / cap;
      qs[2 * q + 1] = m[2 + 2 * q] / cap;
      const double a = std::abs(qs[2 * q]) + std::abs(qs[2 * q + 1]);
      bn += coef[q] * gl[q] * a;
      bt = std::max(bt, gl[q] + gl[q] * a);
    }
    if (std::max(bn, bt) / scale * (1.0 + 1e-12) <= floor) return floor;
    double dn = g[0], worst = 0.0;
    for (int q = 0; q < 2; ++q) {
      const double cap = coef[q] * m[0];
      if (cap <= 0.0) continue;    // no bound on this pair: no condition
      const double q1 = qs[2 * q], q2 = qs[2 * q + 1];
      dn -= coef[q] * gl[q] * norm2(q1, q2);
      const double d = norm2(g[1 + 2 * q] + gl[q] * q1, g[2 + 2 * q] + gl[q] * q2);
      worst = worst > d ? worst : d;
    }
    dn = std::abs(dn);
    return (dn > worst ? dn : worst) / scale;
  }

  static double shift(const double *g, const Coefficients &k)
  {
    return k.friction * norm2(g[1], g[2]) + k.rolling * norm2(g[3], g[4]);
  }

  // The solve of one contact with the others held (solvers/nsgs.h), as CoulombLaw's, with the
  // rolling disc beside the tangential one: the normal force closes the gap (the normal entry
  // of the block couples with nothing), then each disc takes its force from g and its own
  // diagonal entry. The spins couple the tangential and rolling entries of the block, so d
  // must dominate them (d_t, d_r raised by the coupling: NsgsSolver), which makes this a
  // convergent damped step with the exact law's fixed point.
  static void local_solve(double *m, const double *g, const double *d, const Coefficients &k)
  {
    const double n = m[0] - g[0] / d[0];
    if (!(n > 0.0)) {
      for (int q = 0; q < block; ++q) m[q] = 0.0;
      return;
    }
    m[0] = n;
    CoulombLaw::disc(m + 1, g + 1, d[1], k.friction * n);
    CoulombLaw::disc(m + 3, g + 3, d[3], k.rolling * n);
  }
};

}    // namespace hardcontact
