// The paper's contact law (eq. 17-18): one multiplier per contact, the normal force mu >= 0,
// complementary to the predicted gap g >= 0. A law is the set the multipliers may take; the
// solvers are written against this interface (templates, no virtual call per contact):
//   block                   multipliers per contact (and components of g, the gradient of the
//                           dual: the predicted gap first, then tangential displacements)
//   project(m, coef)        the nearest admissible block m[0..block) (the projection of the
//                           dual method, 3.3); coef: the row's coefficient (friction)
//   violation(g, m, coef, s) how far (g, m) is from complementarity, in units of the row
//                           scale s
// Other laws are headers beside this one (coulomb.h).
#pragma once

namespace hardcontact {

struct NormalLaw {
  static constexpr int block = 1;

  static double project(double mu) { return mu > 0.0 ? mu : 0.0; }

  // The predicted overlap max(0, -g), and for a pushing contact (mu > 0) also the gap |g| its
  // force should have closed (eq. 18). 0 exactly at the solution of eq. 15.
  static double violation(double g, double mu, double scale)
  {
    const double v = mu > 0.0 ? (g < 0.0 ? -g : g) : (g < 0.0 ? -g : 0.0);
    return v / scale;
  }

  // The block forms the solvers use (block 1: the scalar forms above).
  static void project(double *m, double) { m[0] = project(m[0]); }
  static double violation(const double *g, const double *m, double, double scale)
  {
    return violation(g[0], m[0], scale);
  }
};

}    // namespace hardcontact
