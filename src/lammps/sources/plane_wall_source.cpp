#include "plane_wall_source.h"

#include "row_sink.h"

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "lammps.h"

using namespace LAMMPS_NS;

namespace hardcontact {

void PlaneWallSource::visit(const Bodies &, RowSink &sink) const
{
  const int nw = static_cast<int>(walls_.size());
  if (nw == 0) return;
  const Atom *atom = lmp_->atom;
  double **x = atom->x;
  double *radius = atom->radius;
  int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; ++i) {
    if (!(mask[i] & groupbit_)) continue;
    for (int w = 0; w < nw; ++w)
      sink.offer(i, wall_body(w), walls_[w].normal(), walls_[w].gap(x[i], radius[i]), radius[i]);
  }
}

void PlaneWallSource::check_in_box() const
{
  static const char *names[3] = {"xplane", "yplane", "zplane"};
  const Domain *domain = lmp_->domain;
  Error *error = lmp_->error;
  for (const auto &w : walls_) {
    if (domain->periodicity[w.dim])
      error->all(FLERR, "Fix hardcontact wall {} needs a non-periodic boundary in that "
                        "direction: change the boundary command", names[w.dim]);
    // A shrink-wrapped box follows the atoms: only fixed boundaries bound the wall.
    const bool fixed_lo = domain->boundary[w.dim][0] == 1;
    const bool fixed_hi = domain->boundary[w.dim][1] == 1;
    if ((fixed_lo && w.coord < domain->boxlo[w.dim]) ||
        (fixed_hi && w.coord > domain->boxhi[w.dim]))
      error->all(FLERR, "Fix hardcontact wall {} at {} lies outside the box ({} to {}): move "
                        "it inside", names[w.dim], w.coord, domain->boxlo[w.dim],
                 domain->boxhi[w.dim]);
  }
}

}    // namespace hardcontact
