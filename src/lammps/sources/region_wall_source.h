// Walls made of the surface of LAMMPS regions (keyword `wall region ID`): the side of the
// surface the region's `side in/out` says is free, the other is the obstacle (Remark 4: one
// row per sphere and touched face, the same form as a plane wall's). A region that moves,
// rotates or changes shape (`region ... move/rotate`, variable radii) is a moving wall: each
// row carries the velocity of the surface at its contact point (LAMMPS's
// Region::velocity_contact, the same as fix wall/gran/region uses).
#pragma once

#include "contact_source.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
class Region;
}

namespace hardcontact {

class RegionWallSource : public ContactSource {
 public:
  // Wall indices of region k's faces: first_wall + kFacesPerRegion k + iwall (LAMMPS's face
  // id), stable across steps (warm start, outputs).
  static constexpr int kFacesPerRegion = 64;

  RegionWallSource(LAMMPS_NS::LAMMPS *lmp, int groupbit, std::vector<std::string> ids) :
      lmp_(lmp), groupbit_(groupbit), ids_(std::move(ids))
  {
  }
  // Finds the regions (error: unknown ID); first_wall: the wall index of the first region's
  // faces (after the plane walls).
  void init(int first_wall);
  // Moving regions where their variables put them now (setup: q^n and the region at t^n).
  void at_current_step();
  // Before a step at t^{n+1} (LAMMPS's step counter already advanced): moving regions where
  // they will be at its end, and their velocities over the step. Rows then measure the gap
  // to the surface at t^{n+1} and offer D = that gap - h n . u_wall, the gap of eq. 15 whose
  // target Targets moves back by + h n . u_wall (a plane wall's convention).
  void advance();
  bool moving() const { return moving_; }
  void visit(const Bodies &bodies, RowSink &sink) const override;
  // Stops with an error if an atom's centre is on the obstacle side of a region's surface.
  void check_sides() const;
  bool owns(int w) const
  {
    return w >= first_wall_ && w < first_wall_ + kFacesPerRegion * static_cast<int>(regions_.size());
  }
  // the wall indices the regions hold (after init): kFacesPerRegion each
  int n_walls() const { return kFacesPerRegion * static_cast<int>(ids_.size()); }
  // Gap of a sphere of this radius centred at x to the face of wall w (diagnostics).
  double gap(int w, const Vec3 &x, double radius) const;
  bool empty() const { return ids_.empty(); }
  const std::vector<LAMMPS_NS::Region *> &regions() const { return regions_; }    // after init

 private:
  LAMMPS_NS::LAMMPS *lmp_;
  int groupbit_;
  std::vector<std::string> ids_;
  std::vector<LAMMPS_NS::Region *> regions_;
  int first_wall_ = 0;
  bool moving_ = false;          // some region moves or changes shape
  bool ahead_ = false;           // moving regions stand at t^{n+1} (advance), not t^n
  double h_ = 0.0;               // the step advance() moved them by
};

}    // namespace hardcontact
