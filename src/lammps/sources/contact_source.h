// A contact source offers the potential rows of one step (Remark 4: pairs and obstacles give
// constraints of the same form) to a RowSink, which alone decides which become rows. Adding a
// kind of obstacle (region walls, moving walls) is adding one source.
#pragma once

#include "../../core/contact_problem.h"

#include <vector>

namespace hardcontact {

class RowSink;

// What the bodies stage of a step found (step.h), read by the sources and the targets.
struct Bodies {
  const std::vector<Vec3> &u_free;     // eq. 14, owned bodies and ghosts
  const std::vector<Vec3> &x_owner;    // owners' coordinates, unshifted on ghosts
  double recovery_speed;               // largest |h f / m| of the step (overlap policy)
};

// The gap of a sphere (centre x, radius) to wall w (wall_index of a row), for the overlap
// diagnostics: each obstacle source answers for its own walls.
class WallGaps {
 public:
  virtual ~WallGaps() = default;
  virtual double wall_gap(int w, const Vec3 &x, double radius) const = 0;
};

class ContactSource {
 public:
  virtual ~ContactSource() = default;
  // Offers every potential row at q^n: sink.offer(i, j, n, D, size), n the unit normal from i
  // towards j. Called once per pass (candidates, then once per missed-row check); one virtual
  // call per pass, none per row.
  virtual void visit(const Bodies &bodies, RowSink &sink) const = 0;
};

}    // namespace hardcontact
