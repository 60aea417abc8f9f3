// Flat walls x_dim = coord (keyword wall): a row for each owned atom of the group and each wall.
#pragma once

#include "contact_source.h"

#include "../../core/plane_wall.h"

#include <utility>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace hardcontact {

class PlaneWallSource : public ContactSource {
 public:
  PlaneWallSource(LAMMPS_NS::LAMMPS *lmp, int groupbit, std::vector<PlaneWall> walls) :
      lmp_(lmp), groupbit_(groupbit), walls_(std::move(walls))
  {
  }
  void visit(const Bodies &bodies, RowSink &sink) const override;

  // Stops with an error if a wall lies on a periodic direction or outside a fixed boundary.
  void check_in_box() const;
  // The wall of row body j < 0 (contact_source.h).
  const PlaneWall &wall_of_row(int j) const { return walls_[wall_index(j)]; }
  const std::vector<PlaneWall> &walls() const { return walls_; }

 private:
  LAMMPS_NS::LAMMPS *lmp_;
  int groupbit_;
  std::vector<PlaneWall> walls_;
};

}    // namespace hardcontact
