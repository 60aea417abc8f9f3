// A flat obstacle x_dim = coord (Remark 4: an obstacle adds constraints of the same form as a
// pair). The wall keeps the spheres on one side: above it for a `lo` wall, below for `hi`.
#pragma once

#include "contact_problem.h"

namespace hardcontact {

struct PlaneWall {
  int dim = 2;          // 0, 1, 2 for xplane, yplane, zplane
  bool lo = true;       // true: spheres live at x_dim > coord
  double coord = 0.0;
  // d coord / dt over the current step (a moving wall: its position at the end of the step
  // is coord + h velocity). The rows see it as the velocity of the obstacle (Targets).
  double velocity = 0.0;

  // Signed gap D = distance(centre, plane) - r, negative when the sphere crosses the plane.
  double gap(const double *x, double radius) const
  {
    return (lo ? x[dim] - coord : coord - x[dim]) - radius;
  }
  // The wall's velocity as a vector.
  Vec3 velocity_vector() const
  {
    Vec3 v = Vec3::Zero();
    v[dim] = velocity;
    return v;
  }
  // Unit normal from the sphere towards the wall (the row's n).
  Vec3 normal() const
  {
    Vec3 n = Vec3::Zero();
    n[dim] = lo ? -1.0 : 1.0;
    return n;
  }
};

}    // namespace hardcontact
