// Walls made of the surface of LAMMPS regions (keyword `wall region ID`): the side of the
// surface the region's `side in/out` says is free, the other is the obstacle (Remark 4: one
// row per sphere and touched face, the same form as a plane wall's). Static regions only.
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
  // Finds the regions (errors: unknown ID, moving region); first_wall: the wall index of the
  // first region's faces (after the plane walls).
  void init(int first_wall);
  void visit(const Bodies &bodies, RowSink &sink) const override;
  // Stops with an error if an atom's centre is on the obstacle side of a region's surface.
  void check_sides() const;
  bool owns(int w) const { return !regions_.empty() && w >= first_wall_; }
  // Gap of a sphere of this radius centred at x to the face of wall w (diagnostics).
  double gap(int w, const Vec3 &x, double radius) const;
  bool empty() const { return ids_.empty(); }

 private:
  LAMMPS_NS::LAMMPS *lmp_;
  int groupbit_;
  std::vector<std::string> ids_;
  std::vector<LAMMPS_NS::Region *> regions_;
  int first_wall_ = 0;
};

}    // namespace hardcontact
