#include "contact_virial.h"

#include "atom.h"
#include "memory.h"

#include <algorithm>

using namespace LAMMPS_NS;

namespace hardcontact {

namespace {

// lever (x) force in LAMMPS's virial order xx, yy, zz, xy, xz, yz, times w
void add_outer(double *v, const Vec3 &lever, const Vec3 &f, double w)
{
  v[0] += w * lever[0] * f[0];
  v[1] += w * lever[1] * f[1];
  v[2] += w * lever[2] * f[2];
  v[3] += w * lever[0] * f[1];
  v[4] += w * lever[0] * f[2];
  v[5] += w * lever[1] * f[2];
}

}    // namespace

ContactVirial::~ContactVirial()
{
  memory->destroy(store_);
}

void ContactVirial::tally(const ContactProblem &p, const std::vector<double> &mu, int block,
                          const std::vector<Vec3> &u, double h, const WallGaps &walls,
                          double *global, bool per_atom)
{
  const int nlocal = atom->nlocal;
  double **x = atom->x;
  const double *radius = atom->radius;
  if (per_atom) {
    if (!store_) {    // the first step asked: from now on the values travel with the atoms
      nmax_ = atom->nmax;
      memory->create(store_, nmax_, kComponents, "hardcontact:virial_atom");
    }
    for (int i = 0; i < nlocal; ++i) clear(i);
  }
  double v[kComponents] = {};
  const int nc = p.n_contacts();
  for (int c = 0; c < nc; ++c) {
    const double *m = &mu[static_cast<size_t>(block) * c];
    if (m[0] == 0.0 && (block == 1 || (m[1] == 0.0 && m[2] == 0.0))) continue;
    Vec3 f = m[0] * p.normal[c];
    if (block > 1) f += m[1] * p.tangent1[c] + m[2] * p.tangent2[c];
    const int i = p.body_i[c], j = p.body_j[c];
    const Vec3 xi = Vec3(x[i]) + h * u[i];
    Vec3 lever;
    if (is_wall(j))    // the centre's distance to the wall: r_i + D (p.gap holds a target)
      lever = (radius[i] + walls.wall_gap(wall_index(j), xi, radius[i])) * p.normal[c];
    else    // a ghost's coordinates are its image's
      lever = Vec3(x[j]) + h * u[j] - xi;
    if (p.counted[c]) add_outer(v, lever, f, 1.0);
    if (!per_atom) continue;
    const double share = is_wall(j) ? 1.0 : 0.5;
    if (i < nlocal) add_outer(store_[i], lever, f, share);
    if (!is_wall(j) && j < nlocal) add_outer(store_[j], lever, f, share);
  }
  std::copy(v, v + kComponents, last_global_);
  if (global) std::copy(v, v + kComponents, global);
}

void ContactVirial::copy_per_atom(double **vatom) const
{
  const int nlocal = atom->nlocal;
  for (int i = 0; i < nlocal; ++i)
    for (int k = 0; k < kComponents; ++k) vatom[i][k] = store_ ? store_[i][k] : 0.0;
}

void ContactVirial::grow(int nmax)
{
  if (!store_) return;
  memory->grow(store_, nmax, kComponents, "hardcontact:virial_atom");
  nmax_ = nmax;
}

void ContactVirial::copy(int from, int to)
{
  if (store_) std::copy(store_[from], store_[from] + kComponents, store_[to]);
}

void ContactVirial::clear(int i)
{
  if (store_) std::fill(store_[i], store_[i] + kComponents, 0.0);
}

int ContactVirial::pack(int i, double *buf) const
{
  if (!store_) return 0;
  std::copy(store_[i], store_[i] + kComponents, buf);
  return kComponents;
}

int ContactVirial::unpack(int i, const double *buf)
{
  if (!store_) return 0;
  std::copy(buf, buf + kComponents, store_[i]);
  return kComponents;
}

double ContactVirial::memory_usage() const
{
  return store_ ? static_cast<double>(nmax_) * kComponents * sizeof(double) : 0.0;
}

}    // namespace hardcontact
