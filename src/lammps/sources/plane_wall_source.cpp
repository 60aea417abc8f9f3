#include "plane_wall_source.h"

#include "row_sink.h"

#include "../lammps_compat.h"

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "input.h"
#include "lammps.h"
#include "modify.h"
#include "update.h"
#include "variable.h"

#include <cmath>

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
    for (int w = 0; w < nw; ++w) {
      const double d = walls_[w].gap(x[i], radius[i]);
      // most spheres are far from most walls: turned down before the row is assembled
      const double speed = any_moving_ ? velocity_[w].norm() : 0.0;
      if (sink.wall_too_far(i, d, speed)) continue;
      const int j = wall_body(first_wall_ + w);
      if (any_moving_)    // every row of a moving plane carries its velocity (zero: at rest)
        sink.offer(i, j, walls_[w].normal(), d, radius[i], velocity_[w]);
      else
        sink.offer(i, j, walls_[w].normal(), d, radius[i]);
    }
  }
}

double PlaneWallSource::evaluate(int w) const
{
  lmp_->modify->clearstep_compute();
  const double x = lmp_->input->variable->compute_equal(var_index_[w]);
  compat::addstep_compute(lmp_->modify, lmp_->update->ntimestep + 1);
  return x;
}

void PlaneWallSource::init_positions()
{
  static const char *names[3] = {"xplane", "yplane", "zplane"};
  const int nw = static_cast<int>(walls_.size());
  var_index_.assign(nw, -1);
  velocity_.assign(nw, Vec3::Zero());
  any_moving_ = false;
  for (int w = 0; w < nw; ++w) {
    if (variables_[w].empty()) continue;
    const int ivar = compat::find_variable(lmp_->input->variable, variables_[w]);
    if (ivar < 0)
      compat::error_all(lmp_->error, FLERR,
                        "Fix hardcontact wall {}: variable {} does not exist: define it "
                        "with 'variable {} equal ...' before the run",
                        names[walls_[w].dim], variables_[w], variables_[w]);
    if (!lmp_->input->variable->equalstyle(ivar))
      compat::error_all(lmp_->error, FLERR,
                        "Fix hardcontact wall {}: variable {} is not equal-style: a wall "
                        "position is one number ('variable {} equal ...')",
                        names[walls_[w].dim], variables_[w], variables_[w]);
    var_index_[w] = ivar;
    any_moving_ = true;
    walls_[w].coord = evaluate(w);
    walls_[w].velocity = 0.0;
    if (!std::isfinite(walls_[w].coord))
      compat::error_all(lmp_->error, FLERR,
                        "Fix hardcontact wall {}: variable {} is not a finite number",
                        names[walls_[w].dim], variables_[w]);
  }
}

void PlaneWallSource::advance(double h)
{
  if (!any_moving_) return;
  const int nw = static_cast<int>(walls_.size());
  for (int w = 0; w < nw; ++w) {
    if (var_index_[w] < 0) continue;
    const double next = evaluate(w);
    if (!std::isfinite(next))
      compat::error_all(lmp_->error, FLERR,
                        "Fix hardcontact: the position of moving wall {} is not a finite "
                        "number at step {}: check variable {}",
                        w + 1, lmp_->update->ntimestep, variables_[w]);
    walls_[w].velocity = (next - walls_[w].coord) / h;
    velocity_[w] = walls_[w].velocity_vector();
  }
}

void PlaneWallSource::commit(double h)
{
  for (PlaneWall &w : walls_) w.coord += h * w.velocity;
}

void PlaneWallSource::check_in_box() const
{
  static const char *names[3] = {"xplane", "yplane", "zplane"};
  const Domain *domain = lmp_->domain;
  Error *error = lmp_->error;
  for (const auto &w : walls_) {
    if (domain->periodicity[w.dim])
      compat::error_all(error, FLERR,
                        "Fix hardcontact wall {} needs a non-periodic boundary in that "
                        "direction: change the boundary command",
                        names[w.dim]);
    // A shrink-wrapped box follows the atoms: only fixed boundaries bound the wall.
    const bool fixed_lo = domain->boundary[w.dim][0] == 1;
    const bool fixed_hi = domain->boundary[w.dim][1] == 1;
    if ((fixed_lo && w.coord < domain->boxlo[w.dim]) ||
        (fixed_hi && w.coord > domain->boxhi[w.dim]))
      compat::error_all(error, FLERR,
                        "Fix hardcontact wall {} at {} lies outside the box ({} to {}): move "
                        "it inside",
                        names[w.dim], w.coord, domain->boxlo[w.dim], domain->boxhi[w.dim]);
  }
}

}    // namespace hardcontact
