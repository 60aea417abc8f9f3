#include "region_wall_source.h"

#include "row_sink.h"
#include "wall_kinds.h"

#include "../lammps_compat.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "lammps.h"
#include "neighbor.h"
#include "region.h"
#include "update.h"

#include <limits>

using namespace LAMMPS_NS;

namespace hardcontact {

std::unique_ptr<WallSource> RegionWallSource::create(LAMMPS *lmp, int groupbit,
                                                     const std::vector<WallSpec> &walls)
{
  std::vector<std::string> ids;
  std::vector<double> friction;
  for (const WallSpec &w : walls) {
    ids.push_back(w.values[0]);
    friction.push_back(w.friction);
  }
  return std::make_unique<RegionWallSource>(lmp, groupbit, std::move(ids), std::move(friction));
}

void RegionWallSource::init(const WallSourceInit &at)
{
  regions_.clear();
  if (!ids_.empty() && !compat::kRegionFacesNumbered)
    compat::error_all(lmp_->error, FLERR,
                      "Fix hardcontact wall region {}: region walls are not available on this "
                      "host (LIGGGHTS 3.8 regions do not number the face a contact lies on, "
                      "which the fix needs to follow each face from step to step): use plane "
                      "walls (wall xplane/yplane/zplane)",
                      ids_.front());
  for (const std::string &id : ids_) {
    Region *region = compat::find_region(lmp_->domain, id);
    if (region == nullptr)
      compat::error_all(lmp_->error, FLERR,
                        "Fix hardcontact wall region {}: no region with that ID: define it "
                        "with the region command before the fix",
                        id);
    // A union/intersect is never moved itself; its sub-regions may be, but the velocity of
    // its surface is not known to LAMMPS (velocity_contact reads the union's own motion).
    const std::string style = region->style;
    if (region->dynamic_check() && (style == "union" || style == "intersect"))
      compat::error_all(lmp_->error, FLERR,
                        "Fix hardcontact wall region {}: a {} of moving regions has no known "
                        "surface velocity: give each moving region its own 'wall region' "
                        "keyword",
                        id, style);
    if (region->dynamic_check()) moving_ = true;
    regions_.push_back(region);
#if !HARDCONTACT_LIGGGHTS    // (LIGGGHTS has no region walls: the error above stops first)
    // A sphere passing through an open face has no contact there, and the wrong-side check
    // (check_sides) cannot tell an exit from a crossing: say so once per fix.
    if (!warned_open_ && region->openflag && lmp_->comm->me == 0)
      compat::warning(lmp_->error, FLERR,
                      "Fix hardcontact {}: wall region {} has open faces: a sphere reaching "
                      "an open face has no contact there and leaves unseen (the check that "
                      "stops a run when a sphere is on the wrong side of a wall cannot tell "
                      "an exit from a crossing); close the region, or bound it with plane "
                      "walls or another region",
                      at.fix_id, region->id);
#else
    (void) at;
#endif
  }
  warned_open_ = true;
  ahead_ = false;
}

void RegionWallSource::at_current_step()
{
  for (Region *region : regions_)
    if (region->dynamic_check()) compat::region_move_to_step(region);    // seeds velocities
  ahead_ = false;
}

void RegionWallSource::advance(double h)
{
  if (!moving_) return;
  for (Region *region : regions_)
    if (region->dynamic_check()) compat::region_move_to_step(region);
  ahead_ = true;
  h_ = h;
}

// Every face of every region within the skin of an owned sphere: a sphere cannot move more
// than the skin in a step (the fix's skin check), so no face it could reach is left out.
void RegionWallSource::visit(const Bodies &, RowSink &sink) const
{
  const Atom *atom = lmp_->atom;
  double **x = atom->x;
  const double *radius = atom->radius;
  const int *mask = atom->mask;
  const double skin = lmp_->neighbor->skin;
  const int nr = static_cast<int>(regions_.size());
  for (int k = 0; k < nr; ++k) {
    Region *region = regions_[k];
    const bool moving = region->dynamic_check();    // once per region, not per contact
    for (int i = 0; i < atom->nlocal; ++i) {
      if (!(mask[i] & groupbit_)) continue;
      const int n = region->surface(x[i][0], x[i][1], x[i][2], radius[i] + skin);
      for (int m = 0; m < n; ++m) {
        const auto &ct = region->contact[m];
        if (compat::region_face(ct) >= kFacesPerRegion)
          compat::error_one(lmp_->error, FLERR,
                            "Fix hardcontact wall region {}: face {} beyond the {} faces a "
                            "region may have here: split the region into several wall "
                            "region keywords",
                            ids_[k], compat::region_face(ct), kFacesPerRegion);
        if (!(ct.r > 0.0)) continue;    // centre on the surface: no direction (check_sides)
        // delx.. points from the surface to the centre: the row's normal is the opposite
        const Vec3 normal = -Vec3(ct.delx, ct.dely, ct.delz) / ct.r;
        const int w = first_wall_ + kFacesPerRegion * k + compat::region_face(ct);
        if (!moving) {    // at rest even when plane walls move (the sink's plane velocities
                          // are indexed by plane)
          sink.offer(i, wall_body(w), normal, ct.r - radius[i], radius[i], Vec3::Zero());
          continue;
        }
        Vec3 u_wall = Vec3::Zero();
        compat::region_contact_velocity(region, u_wall.data(), x[i], m);
        const double d = ct.r - radius[i] - (ahead_ ? h_ * normal.dot(u_wall) : 0.0);
        sink.offer(i, wall_body(w), normal, d, radius[i], u_wall);
      }
    }
  }
}

void RegionWallSource::check_sides() const
{
  const Atom *atom = lmp_->atom;
  tagint bad = 0;
  int which = -1;
  for (int k = 0; k < static_cast<int>(regions_.size()); ++k)
    for (int i = 0; i < atom->nlocal && !bad; ++i)
      if ((atom->mask[i] & groupbit_) &&
          !regions_[k]->match(atom->x[i][0], atom->x[i][1], atom->x[i][2])) {
        bad = atom->tag[i];
        which = k;
      }
  tagint all;
  MPI_Allreduce(&bad, &all, 1, MPI_LMP_TAGINT, MPI_MAX, lmp_->world);
  int which_all;
  MPI_Allreduce(&which, &which_all, 1, MPI_INT, MPI_MAX, lmp_->world);
  if (all)
    compat::error_all(lmp_->error, FLERR,
                      "Fix hardcontact: the centre of atom {} is on the wrong side of wall "
                      "region {} (outside a 'side in' region, inside a 'side out' one): "
                      "move the atom or change the region",
                      all, ids_[which_all]);
}

double RegionWallSource::wall_gap(int w, const Vec3 &x, double radius) const
{
  const int k = (w - first_wall_) / kFacesPerRegion;
  const int iwall = (w - first_wall_) % kFacesPerRegion;
  Region *region = regions_[k];
  // the centre crossed the surface: an overlap of at least the radius
  if (!region->match(x[0], x[1], x[2])) return -radius;
  const int n = region->surface(x[0], x[1], x[2], radius + lmp_->neighbor->skin);
  for (int m = 0; m < n; ++m)
    if (compat::region_face(region->contact[m]) == iwall) return region->contact[m].r - radius;
  return std::numeric_limits<double>::infinity();    // that face is farther than the skin
}

}    // namespace hardcontact
