#include "pair_source.h"

#include "row_sink.h"

#include "atom.h"
#include "domain.h"
#include "lammps.h"
#include "neigh_list.h"

#include <cmath>

using namespace LAMMPS_NS;

namespace hardcontact {

// The list holds each pair with an owned atom first; a pair across processes is held by both,
// each side pushing only its own atom (core/dual_operator.h).
void PairSource::visit(const Bodies &bodies, RowSink &sink) const
{
  Atom *atom = lmp_->atom;
  double *radius = atom->radius;
  int *mask = atom->mask;
  tagint *tag = atom->tag;
  const int inum = list_->inum;
  const int *ilist = list_->ilist;
  for (int ii = 0; ii < inum; ++ii) {
    const int i = ilist[ii];
    const int *jlist = list_->firstneigh[i];
    const int jnum = list_->numneigh[i];
    for (int jj = 0; jj < jnum; ++jj) {
      const int j = jlist[jj] & NEIGHMASK;
      if (!(mask[i] & groupbit_) && !(mask[j] & groupbit_)) continue;
      if (tag[i] == tag[j]) continue;    // a sphere and its own periodic image
      const Vec3 dx = pair_vector(i, j, bodies.x_owner);
      // most listed pairs are farther apart than any row of the step: turned down here without
      // a square root (the margin keeps the decision offer_row's, whatever the rounding)
      const double bound = radius[i] + radius[j] + sink.pair_reach(i, j);
      if (dx.squaredNorm() > bound * bound * (1.0 + 1e-12)) continue;
      const double r = dx.norm();
      const Vec3 n = r > 0.0 ? Vec3(dx / r) : coincident_normal(i, j, bodies.u_free);
      sink.offer(i, j, n, r - radius[i] - radius[j], radius[i] + radius[j]);
    }
  }
}

// x_j - x_i for a listed pair. A pair across processes (newton off) is a row on both, and
// Prop. 4 (exact momentum) needs the two rows to evolve identically: same D, opposite normals,
// bit for bit. A ghost copied without a periodic shift has exactly its owner's coordinates, so
// the plain difference is antisymmetric. Across a periodic boundary the ghost holds
// x_owner + k L rounded, and the two processes would round differently: there the difference
// of the owners' coordinates is taken, then k L added, which rounds antisymmetrically.
Vec3 PairSource::pair_vector(int i, int j, const std::vector<Vec3> &x_owner) const
{
  double **x = lmp_->atom->x;
  const Domain *domain = lmp_->domain;
  const Vec3 plain = Vec3(x[j]) - Vec3(x[i]);
  if (j < lmp_->atom->nlocal) return plain;
  const Vec3 shift = Vec3(x[j]) - x_owner[j];
  if (shift.isZero(0.0)) return plain;
  Vec3 dx = x_owner[j] - Vec3(x[i]);
  for (int d = 0; d < 3; ++d) {
    if (shift[d] == 0.0) continue;
    const double k = std::nearbyint(shift[d] / domain->prd[d]);
    dx[d] += k * domain->prd[d];
  }
  return dx;
}

// Coincident centres: D is not differentiable and any unit vector is a valid G (subgradient).
// Every free motion moves such a pair apart, so take the direction of the free relative
// velocity: the constraint then lets the pair go on as it moves, instead of stopping it on an
// arbitrary axis. At rest, orient by atom ID. Both processes holding the pair see the same
// u_free (forwarded to ghosts) and atom IDs, so they pick opposite vectors of one normal.
Vec3 PairSource::coincident_normal(int i, int j, const std::vector<Vec3> &u_free) const
{
  const Vec3 du = u_free[j] - u_free[i];
  const double speed = du.norm();
  if (speed > 0.0) return du / speed;
  const tagint *tag = lmp_->atom->tag;
  return Vec3::UnitX() * (tag[i] < tag[j] ? 1.0 : -1.0);
}

}    // namespace hardcontact
