// A frictional law as one normal force and a list of discs that compose: per contact
// m = (m_n, m_1, ..., m_D), each m_q one or two components bounded by its disc,
//   K = {m_n >= 0, |m_q| <= coef_q m_n for every q},
// with coef_0 the friction coefficient (the tangential disc, coulomb.h) and the others a
// resistance's (rolling.h, ...). The dual cone of K is {g_n >= sum_q coef_q |g_q|}: De
// Saxce's shift is sum_q coef_q |g_q|, which makes a sliding or rolling contact keep g_n = 0
// and dissipate sum_q coef_q m_n |g_q| / h. CoulombLaw is DiscLaw<TangentialDisc>, RollingLaw
// DiscLaw<TangentialDisc, RollingDisc>. The law owns its rows of G through its discs
// (disc_rows.h): DualOperator calls gap_block, apply_block, block_diagonals, block_diagonal
// and add_forces below, and the contact history history_values and from_history, whatever
// the discs.
#pragma once

#include "disc_rows.h"
#include "law.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <type_traits>
#include <utility>

namespace hardcontact {

template <class... Discs>
struct DiscLaw {
  static constexpr int discs = sizeof...(Discs);
  static_assert(discs >= 1, "a frictional law has its tangential disc");
  static_assert(((Discs::size == 1 || Discs::size == 2) && ...), "discs of 1 or 2 components");
  // the tangential disc first: the outputs and the virial read the force from m[0..3)
  static_assert(std::is_same<std::tuple_element_t<0, std::tuple<Discs...>>, TangentialDisc>::value,
                "a frictional law's first disc is the tangential one");
  static constexpr bool frictional = true;
  // the resistances it composes (bit r: ResistanceDisc<r>), for the adapter's choice of law
  static constexpr unsigned resistances = (Discs::resistance_bit | ...);
  static constexpr int block = 1 + (Discs::size + ...);
  // each disc's components and where they start in the block
  static constexpr int size_of[discs] = {Discs::size...};
  static constexpr int offset_of(int q)
  {
    int at = 1;
    for (int k = 0; k < q; ++k) at += size_of[k];
    return at;
  }
  // |x| over a disc's components (2: norm2, 1: the absolute value)
  static double length(const double *x, int size)
  {
    return size == 2 ? norm2(x[0], x[1]) : std::abs(x[0]);
  }
  // values a contact keeps between steps (the contact history): the force (normal and
  // tangential) and each further disc's as box-frame vectors, which survive a new tangent
  // frame and a row seen from the other body (i and j swapped)
  static constexpr int history = 3 * discs;
  // Row c's history values as pushed on j (its opposite on i): per disc sum_k m_k axis_k, the
  // first with m_n n.
  static void history_values(const ContactProblem &p, int c, const double *m, double *on_i,
                             double *on_j)
  {
    int vec = 0;
    each_disc([&](auto disc, int at) {
      using Disc = decltype(disc);
      Vec3 f;
      if constexpr (Disc::size == 2)
        f = m[at] * Disc::axis(p, c, 0) + m[at + 1] * Disc::axis(p, c, 1);
      else
        f = m[at] * Disc::axis(p, c, 0);
      if (vec == 0) f += m[0] * p.normal[c];
      for (int d = 0; d < 3; ++d) {
        on_i[3 * vec + d] = -f[d];
        on_j[3 * vec + d] = f[d];
      }
      ++vec;
    });
  }
  // The multipliers of row c from body i's history values (history_values' on_i), in the
  // row's frame.
  static void from_history(const ContactProblem &p, int c, const double *on_i, double *m)
  {
    int vec = 0;
    each_disc([&](auto disc, int at) {
      using Disc = decltype(disc);
      const double *v = on_i + 3 * vec;
      const Vec3 on_j = -Vec3(v[0], v[1], v[2]);
      if (vec == 0) m[0] = on_j.dot(p.normal[c]);
      for (int k = 0; k < Disc::size; ++k) m[at + k] = on_j.dot(Disc::axis(p, c, k));
      ++vec;
    });
  }

  // disc q's coefficient: friction for the tangential disc, rolling for the rolling one
  static double coefficient(const Coefficients &k, int q)
  {
    const double coef[discs] = {Discs::coefficient(k)...};
    return coef[q];
  }
  // The row's coefficients from the problem (each disc's).
  static Coefficients coefficients(const ContactProblem &p, int c)
  {
    Coefficients k;
    ((Discs::coefficient(k) = Discs::row_coefficient(p, c)), ...);
    return k;
  }
  // f(disc, offset of its first component in the block), for each disc in order
  template <class F>
  static void each_disc(F &&f)
  {
    each_disc(f, std::index_sequence_for<Discs...>{});
  }

  // ---- the rows of G (DualOperator) --------------------------------------------------------
  // The B components of h G_c u + D_c: the gap, then each disc's (h t_k . v_slip, ...).
  static void gap_block(const ContactProblem &p, int c, const std::vector<Vec3> &u, double *g)
  {
    const Vec3 v = p.h * p.slip_velocity(c, u);
    g[0] = p.target[c] + p.normal[c].dot(v);
    each_disc([&](auto disc, int at) { decltype(disc)::gap(p, c, u, v, g + at); });
  }
  // Adds the velocity change of the impulse h (m_n n + the discs' forces) to the owned bodies
  // of row c: the force acts on j at -a_j n and its opposite on i at +a_i n (the arms), so
  // both spin by -a I^-1 n x impulse; then the discs' own torques.
  static void apply_block(const ContactProblem &p, int c, const double *dm, std::vector<Vec3> &u)
  {
    Vec3 f = dm[0] * p.normal[c];
    each_disc([&](auto disc, int at) { decltype(disc)::add_linear(p, c, dm + at, f); });
    const Vec3 impulse = p.h * f;
    const int i = p.body_i[c], j = p.body_j[c], nb = p.n_bodies();
    const Vec3 turn = p.normal[c].cross(impulse);
    if (i < p.n_owned) {
      u[i] -= p.inv_mass[i] * impulse;
      if (p.rotates()) u[nb + i] -= (p.inv_inertia[i] * p.arm_i[c]) * turn;
    }
    if (j >= 0 && j < p.n_owned) {
      u[j] += p.inv_mass[j] * impulse;
      if (p.rotates()) u[nb + j] -= (p.inv_inertia[j] * p.arm_j[c]) * turn;
    }
    if constexpr ((Discs::own_torque || ...)) {
      const bool own_i = i < p.n_owned, own_j = j >= 0 && j < p.n_owned;
      Vec3 *spin_i = own_i ? &u[nb + i] : nullptr, *spin_j = own_j ? &u[nb + j] : nullptr;
      each_disc([&](auto disc, int at) {
        decltype(disc)::push_spins(p, c, dm + at, p.h, i, j, spin_i, spin_j);
      });
    }
  }
  // The diagonal of the block A_cc, d[0..B): the normal entry h^2 (w_i + w_j), then each
  // disc's (equal within a disc; couplings between discs through the spins are not in it).
  static void block_diagonals(const ContactProblem &p, int c, double *d)
  {
    const int i = p.body_i[c], j = p.body_j[c];
    const RowBodies b{i, j, is_wall(j), p.h * p.h};
    d[0] = b.h2 * (p.inv_mass[i] + (b.wall ? 0.0 : p.inv_mass[j]));
    each_disc([&](auto disc, int at) { decltype(disc)::diagonals(p, c, b, d + at); });
  }
  // At least the largest eigenvalue of A_cc: with the tangential disc alone the block is
  // diagonal and this is its largest entry; with discs coupled through the spins, the trace
  // (A_cc >= 0): per body 3 w (the normal and the two tangential rows) + (1 / I) sum of the
  // discs' angular shares.
  static double block_diagonal(const ContactProblem &p, int c)
  {
    if constexpr (discs == 1) {
      return TangentialDisc::largest(p, c);
    } else {
      const int i = p.body_i[c], j = p.body_j[c];
      const auto body = [&](int b, double arm) {
        double angular = 0.0;
        each_disc([&](auto disc, int) { angular += decltype(disc)::angular_trace(p, c, arm); });
        return 3.0 * p.inv_mass[b] + p.inv_inertia[b] * angular;
      };
      double t = body(i, p.arm_i[c]);
      if (!is_wall(j)) t += body(j, p.arm_j[c]);
      return p.h * p.h * t;
    }
  }
  // Raises d (block_diagonals) by the couplings between discs through the spins, so that it
  // dominates the block (nsgs's damped local solves): each coupled disc's entries and the
  // tangential ones by its coupling.
  static void dominate_couplings(const ContactProblem &p, int c, double *d)
  {
    each_disc([&](auto disc, int at) {
      using Disc = decltype(disc);
      if constexpr (Disc::coupled) {
        const double couple = Disc::coupling(p, c);
        for (int k = 1; k < 1 + TangentialDisc::size; ++k) d[k] += couple;
        for (int k = at; k < at + Disc::size; ++k) d[k] += couple;
      }
    });
  }
  // The force of m on j (its opposite on i), and with torque the torques (forces per body).
  static void add_forces(const ContactProblem &p, int c, const double *m, Vec3 &force_i,
                         Vec3 &force_j, Vec3 *torque_i, Vec3 *torque_j)
  {
    Vec3 f = m[0] * p.normal[c];
    each_disc([&](auto disc, int at) { decltype(disc)::add_linear(p, c, m + at, f); });
    force_i -= f;
    force_j += f;
    if (torque_i == nullptr) return;
    // the force on j acts at -a_j n, its opposite on i at +a_i n (apply_block)
    const Vec3 turn = p.normal[c].cross(f);
    *torque_i -= p.arm_i[c] * turn;
    *torque_j -= p.arm_j[c] * turn;
    each_disc([&](auto disc, int at) { decltype(disc)::add_torque(p, c, m + at, *torque_i, *torque_j); });
  }
  // Subtracts from dissipated the work of each disc's force over the step, h m_q . (mean
  // rate), one disc at a time (u, u_free: [lin; ang] velocities at the end and free).
  static void subtract_work(const ContactProblem &p, int c, const double *m,
                            const std::vector<Vec3> &u, const std::vector<Vec3> &u_free,
                            double &dissipated)
  {
    each_disc([&](auto disc, int at) {
      dissipated -= decltype(disc)::work(p, c, m + at, u, u_free);
    });
  }
  // apgd's preconditioned variables x = D^1/2 m (d = block_diagonals): the discs'
  // coefficients scale by sqrt(d_q / d_n), the cone keeps its form.
  static void scale_coefficients(Coefficients &k, const double *d)
  {
    each_disc([&](auto disc, int at) { decltype(disc)::coefficient(k) *= std::sqrt(d[at] / d[0]); });
  }

  // The loops over discs below are unrolled (#pragma GCC unroll): with a disc's size and
  // offset then constants, the law of two discs costs what its hand-written form did (without
  // it, 1.023 x the instructions of a pile with rolling resistance, callgrind).

  // Euclidean projection onto K. One disc: itself inside, 0 in the polar cone
  // (coef |t| <= -n), else onto the cone's surface along the normal of the boundary. Several:
  // for a normal value n' the discs are independent, so the projection minimises
  // f(n') = (n' - n)^2 + sum_q (|m_q| - coef_q n')_+^2 over n' >= 0: f' is piecewise linear
  // and increasing, its root lies in the piece where the terms still outside their disc are
  // active; try the 2^D pieces.
  static void project(double *m, const Coefficients &k)
  {
    if constexpr (discs == 1 && size_of[0] == 2) {
      project_cone(m, coefficient(k, 0));
    } else {
      const double n = m[0];
      double coef[discs], len[discs];
      #pragma GCC unroll 4
      for (int q = 0; q < discs; ++q) {
        coef[q] = coefficient(k, q);
        len[q] = length(m + offset_of(q), size_of[q]);
      }
      int outside = 0;
      while (outside < discs && len[outside] <= coef[outside] * n) ++outside;
      if (outside == discs) return;    // inside (n >= 0)
      // The minimiser is the root of the consistent piece; each piece's root is a candidate
      // and f picks among them (and 0): a point on or within round-off of several discs' edges
      // may find no piece consistent to the bit, and was sent to 0.
      const auto f = [&](double at) {
        double v = (at - n) * (at - n);
        #pragma GCC unroll 4
        for (int q = 0; q < discs; ++q) {
          const double over = len[q] - coef[q] * at;
          if (over > 0.0) v += over * over;
        }
        return v;
      };
      double best = 0.0, best_f = f(0.0);
      for (int set = 1; set < (1 << discs); ++set) {    // bit q: disc q outside at the root
        double num = n, den = 1.0;
        #pragma GCC unroll 4
        for (int q = 0; q < discs; ++q)
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
      #pragma GCC unroll 4
      for (int q = 0; q < discs; ++q) {
        double *v = m + offset_of(q);
        const double cap = coef[q] * best;
        if (len[q] > cap) {
          const double f = len[q] > 0.0 ? cap / len[q] : 0.0;
          for (int c = 0; c < size_of[q]; ++c) v[c] *= f;
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
    return violation(g, m, k, scale, scale, unused, -1.0);
  }
  // The same for a largest violation over rows: a row at most floor may return floor instead
  // (most rows of a solve are far below the largest, and a bound without the norms of p_q and
  // d_q shows it: with |p_q| <= |p_q1| + |p_q2|, d_n <= |g_n| + sum_q coef_q |g_q| |p_q| and
  // |d_q| <= |g_q| (1 + |p_q|); the margin covers the round-off of either side, so the largest
  // is the same to the bit). Also gives shift(g, k) from the same norms: the solver needs both
  // every iteration (IterativeSolver::law_shift_).
  // scale: the gap conditions' (g_n, d_n); slip_scale: the discs' (d_q), residual.h
  // (contact_speed_scale).
  static double violation(const double *g, const double *m, const Coefficients &k, double scale,
                          double slip_scale, double &shift, double floor)
  {
    double coef[discs], gl[discs];
    #pragma GCC unroll 4
    for (int q = 0; q < discs; ++q) {
      coef[q] = coefficient(k, q);
      gl[q] = length(g + offset_of(q), size_of[q]);
    }
    shift = coef[0] * gl[0];
    #pragma GCC unroll 4
    for (int q = 1; q < discs; ++q) shift += coef[q] * gl[q];
    if (m[0] <= 0.0) {
      const double v = shift - g[0];
      return (v > 0.0 ? v : 0.0) / scale;
    }
    double ps[block] = {};    // m_q / cap at the disc's components (0: no bound on the disc)
    double bn = std::abs(g[0]), bt = 0.0;
    #pragma GCC unroll 4
    for (int q = 0; q < discs; ++q) {
      const double cap = coef[q] * m[0];
      if (cap <= 0.0) continue;    // no bound on this disc: no condition (frictionless row)
      const int at = offset_of(q);
      double a = 0.0;
      for (int c = at; c < at + size_of[q]; ++c) {
        ps[c] = m[c] / cap;
        a += std::abs(ps[c]);
      }
      bn += coef[q] * gl[q] * a;
      bt = std::max(bt, gl[q] + gl[q] * a);
    }
    if (std::max(bn / scale, bt / slip_scale) * (1.0 + 1e-12) <= floor) return floor;
    double dn = g[0], worst = 0.0;
    #pragma GCC unroll 4
    for (int q = 0; q < discs; ++q) {
      const double cap = coef[q] * m[0];
      if (cap <= 0.0) continue;
      const int at = offset_of(q);
      double r[2];    // d_q = g_q + |g_q| p_q
      for (int c = 0; c < size_of[q]; ++c) r[c] = g[at + c] + gl[q] * ps[at + c];
      dn -= coef[q] * gl[q] * length(ps + at, size_of[q]);
      const double d = length(r, size_of[q]);
      worst = worst > d ? worst : d;
    }
    dn = std::abs(dn) / scale;
    worst /= slip_scale;
    return dn > worst ? dn : worst;
  }

  static double shift(const double *g, const Coefficients &k)
  {
    double s = coefficient(k, 0) * length(g + offset_of(0), size_of[0]);
    #pragma GCC unroll 4
    for (int q = 1; q < discs; ++q) s += coefficient(k, q) * length(g + offset_of(q), size_of[q]);
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
    #pragma GCC unroll 4
    for (int q = 0; q < discs; ++q) {
      const int at = offset_of(q);
      disc(m + at, g + at, d[at], coefficient(k, q) * n, size_of[q]);
    }
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
    each_disc([&](auto disc, int at) { decltype(disc)::coefficient(scaled) *= root[at] / root[0]; });
    project(y, scaled);
    for (int q = 0; q < block; ++q) m[q] = y[q] / root[q];
  }
  // One disc of local_solve: v = v - g / d, brought back to the disc of radius cap along
  // itself (the exact minimiser over the disc when the block's entries are equal; a disc of
  // one component: the interval [-cap, cap]).
  static void disc(double *v, const double *g, double d, double cap, int size)
  {
    if (size == 1) {
      const double a = v[0] - g[0] / d;
      v[0] = a > cap ? cap : (a < -cap ? -cap : a);
      return;
    }
    const double a = v[0] - g[0] / d, b = v[1] - g[1] / d;
    const double len = norm2(a, b);
    const double f = len > cap ? cap / len : 1.0;
    v[0] = a * f;
    v[1] = b * f;
  }

 private:
  template <class F, size_t... Q>
  static void each_disc(F &f, std::index_sequence<Q...>)
  {
    constexpr int sizes[discs] = {Discs::size...};
    const auto offset = [&](size_t q) {
      int at = 1;
      for (size_t k = 0; k < q; ++k) at += sizes[k];
      return at;
    };
    (f(Discs{}, offset(Q)), ...);
  }
};

}    // namespace hardcontact
