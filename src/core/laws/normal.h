// The paper's contact law (eq. 17-18): one multiplier per contact, the normal force mu >= 0,
// complementary to the predicted gap g >= 0 (law.h: the interface every law follows).
#pragma once

#include "../contact_problem.h"
#include "law.h"

namespace hardcontact {

struct NormalLaw {
  static constexpr int block = 1;
  // values a contact keeps between steps (the contact history): the normal force
  static constexpr int history = 1;
  static constexpr bool frictional = false;
  static constexpr unsigned resistances = 0;
  // the normal force, kept alike by both bodies
  static void history_values(const ContactProblem &, int, const double *m, double *on_i,
                             double *on_j)
  {
    on_i[0] = on_j[0] = m[0];
  }
  static void from_history(const ContactProblem &, int, const double *on_i, double *m)
  {
    m[0] = on_i[0];
  }

  static double project(double mu) { return mu > 0.0 ? mu : 0.0; }

  // The predicted overlap max(0, -g), and for a pushing contact (mu > 0) also the gap |g| its
  // force should have closed (eq. 18). 0 exactly at the solution of eq. 15.
  static double violation(double g, double mu, double scale)
  {
    const double v = mu > 0.0 ? (g < 0.0 ? -g : g) : (g < 0.0 ? -g : 0.0);
    return v / scale;
  }

  // The block forms the solvers use (block 1: the scalar forms above).
  static void project(double *m, const Coefficients &) { m[0] = project(m[0]); }
  static double violation(const double *g, const double *m, const Coefficients &, double scale)
  {
    return violation(g[0], m[0], scale);
  }
  static double shift(const double *, const Coefficients &) { return 0.0; }

  // Its row of G (DualOperator): G_c = grad D_c, -n_c on body i, +n_c on body j (eq. 1).
  static Coefficients coefficients(const ContactProblem &, int) { return {}; }
  // g_c(u) = D_c + h G_c u, eq. 15
  static void gap_block(const ContactProblem &p, int c, const std::vector<Vec3> &u, double *g)
  {
    g[0] = p.predicted_gap(c, u);
  }
  // u_i -= w_i h dm n_c, u_j += w_j h dm n_c on the owned bodies
  static void apply_block(const ContactProblem &p, int c, const double *dm, std::vector<Vec3> &u)
  {
    RowKernel(p).apply(c, dm[0], doubles(u));
  }
  // A_cc = h^2 (w_i + w_j): the exact step along one row (Gauss-Seidel)
  static double block_diagonal(const ContactProblem &p, int c)
  {
    const int j = p.body_j[c];
    return p.h * p.h * (p.inv_mass[p.body_i[c]] + (is_wall(j) ? 0.0 : p.inv_mass[j]));
  }
  static void block_diagonals(const ContactProblem &p, int c, double *d) { d[0] = block_diagonal(p, c); }
  // the force m n_c on j, its opposite on i (no torque: the normal passes through the centres)
  static void add_forces(const ContactProblem &p, int c, const double *m, Vec3 &force_i,
                         Vec3 &force_j, Vec3 *, Vec3 *)
  {
    const Vec3 f = m[0] * p.normal[c];
    force_i -= f;
    force_j += f;
  }

  // The exact solve of one row with the others held (nonsmooth Gauss-Seidel, solvers/nsgs.h):
  // g the row's gap at m, d its diagonal entry of A (or a larger one, for a damped step).
  static void local_solve(double *m, const double *g, const double *d, const Coefficients &)
  {
    m[0] = project(m[0] - g[0] / d[0]);
  }
};

}    // namespace hardcontact
