// The paper's contact law (eq. 17-18): one multiplier per contact, the normal force mu >= 0,
// complementary to the predicted gap g >= 0 (law.h: the interface every law follows).
#pragma once

#include "law.h"

namespace hardcontact {

struct NormalLaw {
  static constexpr int block = 1;
  // values a contact keeps between steps (the contact history): the normal force
  static constexpr int history = 1;

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

  // The exact solve of one row with the others held (nonsmooth Gauss-Seidel, solvers/nsgs.h):
  // g the row's gap at m, d its diagonal entry of A (or a larger one, for a damped step).
  static void local_solve(double *m, const double *g, const double *d, const Coefficients &)
  {
    m[0] = project(m[0] - g[0] / d[0]);
  }
};

}    // namespace hardcontact
