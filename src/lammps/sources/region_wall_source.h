// Walls made of the surface of LAMMPS regions (keyword `wall region ID`): the side of the
// surface the region's `side in/out` says is free, the other is the obstacle (Remark 4: one
// row per sphere and touched face, the same form as a plane wall's). A region that moves,
// rotates or changes shape (`region ... move/rotate`, variable radii) is a moving wall: each
// row carries the velocity of the surface at its contact point (LAMMPS's
// Region::velocity_contact, the same as fix wall/gran/region uses).
#pragma once

#include "contact_source.h"

#include <memory>
#include <string>
#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
class Region;
}

namespace hardcontact {

struct WallSpec;

class RegionWallSource : public WallSource {
 public:
  // Wall indices of region k's faces: first_wall + kFacesPerRegion k + iwall (LAMMPS's face
  // id), stable across steps (warm start, outputs).
  static constexpr int kFacesPerRegion = 64;

  // friction: per region its own Coulomb coefficient (every face's), negative for the atom
  // type's
  RegionWallSource(LAMMPS_NS::LAMMPS *lmp, int groupbit, std::vector<std::string> ids,
                   std::vector<double> friction) :
      lmp_(lmp), groupbit_(groupbit), ids_(std::move(ids)), friction_(std::move(friction))
  {
  }
  // `wall region ID` (wall_kinds.cpp): one source for every region wall of the fix line.
  static std::unique_ptr<WallSource> create(LAMMPS_NS::LAMMPS *lmp, int groupbit,
                                            const std::vector<WallSpec> &walls);
  // Finds the regions (error: unknown ID); warns once about a region with open faces.
  void init(const WallSourceInit &at) override;
  // Moving regions where their variables put them now (setup: q^n and the region at t^n).
  void at_current_step() override;
  // Before a step at t^{n+1} (LAMMPS's step counter already advanced): moving regions where
  // they will be at its end (h: the step), and their velocities over the step. Rows then
  // measure the gap to the surface at t^{n+1} and offer D = that gap - h n . u_wall, the gap
  // of eq. 15 whose target Targets moves back by + h n . u_wall (a plane wall's convention).
  void advance(double h) override;
  bool moving() const override { return moving_; }
  void visit(const Bodies &bodies, RowSink &sink) const override;
  // Stops with an error if an atom's centre is on the obstacle side of a region's surface.
  void check_sides() const override;
  // the wall indices the regions hold: kFacesPerRegion each
  int n_walls() const override { return kFacesPerRegion * static_cast<int>(ids_.size()); }
  double friction(int w) const override { return friction_[(w - first_wall_) / kFacesPerRegion]; }
  // Gap of a sphere of this radius centred at x to the face of wall w (diagnostics).
  double wall_gap(int w, const Vec3 &x, double radius) const override;
  bool empty() const { return ids_.empty(); }
  const std::vector<LAMMPS_NS::Region *> &regions() const { return regions_; }    // after init

 private:
  LAMMPS_NS::LAMMPS *lmp_;
  int groupbit_;
  std::vector<std::string> ids_;
  std::vector<double> friction_;
  std::vector<LAMMPS_NS::Region *> regions_;
  bool moving_ = false;          // some region moves or changes shape
  bool warned_open_ = false;     // the open-face warning, once per fix
  bool ahead_ = false;           // moving regions stand at t^{n+1} (advance), not t^n
  double h_ = 0.0;               // the step advance() moved them by
};

}    // namespace hardcontact
