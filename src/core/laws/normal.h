// The paper's contact law (eq. 17-18): one multiplier per contact, the normal force mu >= 0,
// complementary to the predicted gap g >= 0. A law is the set the multipliers may take; the
// solvers are written against this interface (templates, no virtual call per contact):
//   block              multipliers per contact
//   project(mu)        the nearest admissible value (the projection of the dual method, 3.3)
//   violation(g,mu,s)  how far (g, mu) is from complementarity, in units of the row scale s
// Later laws (Coulomb cone, cohesion mu >= -c, rolling resistance) are headers beside this one.
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
};

}    // namespace hardcontact
