#include "integrate.h"

#include "lammps_compat.h"

#include "atom.h"
#include "error.h"
#include "force.h"
#include "neighbor.h"
#include "update.h"

using namespace LAMMPS_NS;

namespace hardcontact {
namespace {

// What the skin test needs of all processes' atoms, reduced in one message.
struct Moves {
  double now[2];      // two largest displacements since the build (of distinct atoms)
  double ahead[2];    // same after two more steps like this one
  double step;        // largest move of this step
};
const int MOVES_DOUBLES = static_cast<int>(sizeof(Moves) / sizeof(double));

void two_largest(double v, double top[2])
{
  if (v > top[0]) {
    top[1] = top[0];
    top[0] = v;
  } else if (v > top[1]) {
    top[1] = v;
  }
}

// MPI_User_function: merges the Moves of two processes (commutative and associative: the two
// largest values of a union do not depend on the order).
void merge_moves(void *in, void *inout, int *len, MPI_Datatype *)
{
  const Moves *a = static_cast<const Moves *>(in);
  Moves *b = static_cast<Moves *>(inout);
  for (int m = 0; m < *len; ++m) {
    for (int k = 0; k < 2; ++k) {
      two_largest(a[m].now[k], b[m].now);
      two_largest(a[m].ahead[k], b[m].ahead);
    }
    b[m].step = MAX(b[m].step, a[m].step);
  }
}

}    // namespace

Integrate::~Integrate()
{
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (finalized) return;
  if (moves_op_ != MPI_OP_NULL) MPI_Op_free(&moves_op_);
  if (moves_type_ != MPI_DATATYPE_NULL) MPI_Type_free(&moves_type_);
}

void Integrate::store_build_positions()
{
  const int nlocal = atom->nlocal;
  xhold_.resize(nlocal);
  for (int i = 0; i < nlocal; ++i) xhold_[i] = Vec3(atom->x[i]);
}

// Eq. 19, plus the guarantee that no contact was missed: a pair absent from the list was at
// least r_i + r_j + skin apart at the last build, so it cannot overlap while the two atoms
// together have moved less than the skin since (d_i + d_j < skin). A rebuild is forced as soon
// as the next step could break that even if speeds doubled (gravity, collisions).
bool Integrate::move(const std::vector<Vec3> &u, int spins)
{
  const int nlocal = atom->nlocal;
  double **x = atom->x, **v = atom->v, **omega = atom->omega, **torque = atom->torque;
  double *rmass = atom->rmass, *radius = atom->radius;
  int *mask = atom->mask;
  const double dt = update->dt;
  const double dtfrot = dt * force->ftm2v / inertia_;

  Moves mine = {{0.0, 0.0}, {0.0, 0.0}, 0.0};
  for (int i = 0; i < nlocal; ++i) {
    if (!(mask[i] & groupbit_)) continue;
    for (int k = 0; k < 3; ++k) {
      v[i][k] = u[i][k];
      x[i][k] += dt * u[i][k];
    }
    // Frictionless contacts exert no torque: spins change only by external torques.
    if (spins >= 0) {
      for (int k = 0; k < 3; ++k) omega[i][k] = u[spins + i][k];
    } else if (omega && torque) {
      const double s = dtfrot / (rmass[i] * radius[i] * radius[i]);
      for (int k = 0; k < 3; ++k) omega[i][k] += s * torque[i][k];
    }
    const double step = dt * u[i].norm();
    const double disp = (Vec3(x[i]) - xhold_[i]).norm();
    two_largest(disp, mine.now);
    two_largest(disp + 2.0 * step, mine.ahead);
    mine.step = MAX(mine.step, step);
  }
  if (moves_op_ == MPI_OP_NULL) {
    MPI_Type_contiguous(MOVES_DOUBLES, MPI_DOUBLE, &moves_type_);
    MPI_Type_commit(&moves_type_);
    MPI_Op_create(merge_moves, 1, &moves_op_);
  }
  Moves all;
  MPI_Allreduce(&mine, &all, 1, moves_type_, moves_op_, world);

  const double skin = neighbor->skin;
  if (all.now[0] + all.now[1] >= skin)
    compat::error_all(error, FLERR,
                      "Fix hardcontact: at step {} two atoms moved {:.6g} and {:.6g} since the "
                      "last neighbor list build, together more than the skin ({:.6g}), so a "
                      "contact may have been missed. The largest move in one step was {:.6g}: "
                      "use 'neighbor {:.3g} bin' or a smaller timestep",
                      update->ntimestep, all.now[0], all.now[1], skin, all.step,
                      MAX(2.0 * skin, 8.0 * all.step));
  return all.ahead[0] + all.ahead[1] >= skin;
}

}    // namespace hardcontact
