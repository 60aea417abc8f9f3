// Eq. 19 and the spins, plus the guarantee that no contact was missed (the skin look-ahead).
#pragma once

#include "../core/contact_problem.h"

#include "pointers.h"

#include <mpi.h>
#include <vector>

namespace hardcontact {

class Integrate : protected LAMMPS_NS::Pointers {
 public:
  Integrate(LAMMPS_NS::LAMMPS *lmp, int groupbit) : Pointers(lmp), groupbit_(groupbit) {}
  ~Integrate() override;
  Integrate(const Integrate &) = delete;
  Integrate &operator=(const Integrate &) = delete;

  // I = inertia m r^2: 0.4 for spheres (as fix nve/sphere), 0.5 for discs
  void set_inertia(double inertia) { inertia_ = inertia; }
  // After each neighbour list build: the positions the skin is counted from.
  void store_build_positions();
  // v = u, x += h u for the group; stops with an error if a contact may have been missed, and
  // returns true if the list must be rebuilt before the next step. spins >= 0: omega = u[spins
  // + i], the solver's angular velocities (friction); spins < 0: contacts exert no torque,
  // omega changes by the other forces' torques alone.
  bool move(const std::vector<Vec3> &u, int spins = -1);

 private:
  int groupbit_;
  double inertia_ = 0.4;
  std::vector<Vec3> xhold_;    // owned positions at the last list build
  MPI_Datatype moves_type_ = MPI_DATATYPE_NULL;
  MPI_Op moves_op_ = MPI_OP_NULL;
};

}    // namespace hardcontact
