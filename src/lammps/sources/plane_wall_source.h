// Flat walls x_dim = coord (keyword wall): a row for each owned atom of the group and each wall.
#pragma once

#include "contact_source.h"

#include "../../core/plane_wall.h"

#include <string>
#include <utility>
#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace hardcontact {

class PlaneWallSource : public ContactSource {
 public:
  // variables: per wall, the name of the equal-style variable giving its position (a moving
  // wall), or "" for a fixed one.
  PlaneWallSource(LAMMPS_NS::LAMMPS *lmp, int groupbit, std::vector<PlaneWall> walls,
                  std::vector<std::string> variables) :
      lmp_(lmp), groupbit_(groupbit), walls_(std::move(walls)), variables_(std::move(variables))
  {
  }
  void visit(const Bodies &bodies, RowSink &sink) const override;

  // Moving walls: find their variables (error if missing or not equal-style) and place every
  // moving wall where its variable says now.
  void init_positions();
  // Before a step at time t^{n+1} (LAMMPS's step counter already advanced): each moving wall's
  // velocity (x(t^{n+1}) - x(t^n)) / h. Returns the velocities by wall index, or null when no
  // wall moves (Targets and RowSink then do nothing for walls).
  const std::vector<Vec3> *advance(double h);
  // After the step's solve: the moving walls are at x(t^{n+1}).
  void commit(double h);

  // Stops with an error if a wall lies on a periodic direction or outside a fixed boundary.
  void check_in_box() const;
  // The wall of row body j < 0 (contact_source.h).
  const PlaneWall &wall_of_row(int j) const { return walls_[wall_index(j)]; }
  const std::vector<PlaneWall> &walls() const { return walls_; }

 private:
  LAMMPS_NS::LAMMPS *lmp_;
  int groupbit_;
  std::vector<PlaneWall> walls_;
  std::vector<std::string> variables_;
  std::vector<int> var_index_;       // per wall, -1 for a fixed wall
  std::vector<Vec3> velocity_;       // per wall, for Targets and RowSink
  bool any_moving_ = false;
  double evaluate(int w) const;
};

}    // namespace hardcontact
