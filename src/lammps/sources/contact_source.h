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

// What a wall source's init needs from the fix (Obstacles::init).
struct WallSourceInit {
  double reach;          // how far a sphere's rows reach: its radius + the skin, at most
  int fix_index;         // the fix's index in Modify (a mover of the walls must come before it)
  const char *fix_id;    // for messages ("Fix hardcontact ID: ...")
};

// A source of walls (planes, region surfaces, meshes, or one a host adds). Its walls take
// the wall codes first_wall() .. first_wall() + n_walls() - 1 (wall_index of its rows),
// handed out by Obstacles in the order of its list at each run's init, so warm starts and
// outputs follow a wall from step to step. It carries its own Coulomb coefficient per wall,
// offers each row with its gap at t^n and, if it moves, the wall's velocity at the contact
// (RowSink::offer), and follows its walls through the steps with the hooks below.
class WallSource : public ContactSource, public WallGaps {
 public:
  // Finds what it needs in the deck (errors name the keyword); n_walls() is known after it.
  virtual void init(const WallSourceInit &) {}
  virtual int n_walls() const = 0;
  // Setup: moving walls where they stand now (t^n of the run's first step).
  virtual void at_current_step() {}
  // Setup: stops with an error if an atom's centre is behind one of its walls.
  virtual void check_sides() const {}
  // Before a step at t^{n+1} (LAMMPS's step counter already advanced): moving walls to where
  // they will be, with their velocities over the step of length h.
  virtual void advance(double) {}
  // After the step's solve (the outputs then measure q^{n+1} against the walls at t^{n+1}).
  virtual void commit(double) {}
  // Whether some wall moves this step (after advance): rows then carry their wall's velocity.
  virtual bool moving() const { return false; }
  // Wall w's own Coulomb coefficient, or a negative value: the atom type's (the pair table).
  virtual double friction(int w) const = 0;
  // The gap of a sphere (centre x, radius) to its wall w (diagnostics): wall_gap.

  // after init (n_walls known)
  void assign_walls(int first)
  {
    first_wall_ = first;
    end_wall_ = first + n_walls();
  }
  int first_wall() const { return first_wall_; }
  bool owns(int w) const { return w >= first_wall_ && w < end_wall_; }

 protected:
  int first_wall_ = 0, end_wall_ = 0;
};

}    // namespace hardcontact
