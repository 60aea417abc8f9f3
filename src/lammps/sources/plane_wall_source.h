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

class PlaneWallSource : public WallSource {
 public:
  // variables: per wall, the name of the equal-style variable giving its position (a moving
  // wall), or "" for a fixed one; friction: per wall its own Coulomb coefficient, negative for
  // the atom type's.
  PlaneWallSource(LAMMPS_NS::LAMMPS *lmp, int groupbit, std::vector<PlaneWall> walls,
                  std::vector<std::string> variables, std::vector<double> friction) :
      lmp_(lmp), groupbit_(groupbit), walls_(std::move(walls)), variables_(std::move(variables)),
      friction_(std::move(friction))
  {
  }
  void visit(const Bodies &bodies, RowSink &sink) const override;

  // The moving walls' variables (errors if missing or not equal-style), every moving wall
  // where its variable says now, and the walls inside the box.
  void init(const WallSourceInit &) override
  {
    init_positions();
    check_in_box();
  }
  int n_walls() const override { return static_cast<int>(walls_.size()); }
  void at_current_step() override { init_positions(); }
  // Each moving wall's velocity (x(t^{n+1}) - x(t^n)) / h.
  void advance(double h) override;
  // The moving walls at x(t^{n+1}).
  void commit(double h) override;
  bool moving() const override { return any_moving_; }
  double friction(int w) const override { return friction_[w - first_wall_]; }
  double wall_gap(int w, const Vec3 &x, double radius) const override
  {
    return walls_[w - first_wall_].gap(x.data(), radius);
  }

  // Find the variables and place every moving wall where its variable says now.
  void init_positions();
  // Stops with an error if a wall lies on a periodic direction or outside a fixed boundary.
  void check_in_box() const;
  const std::vector<PlaneWall> &walls() const { return walls_; }

 private:
  LAMMPS_NS::LAMMPS *lmp_;
  int groupbit_;
  std::vector<PlaneWall> walls_;
  std::vector<std::string> variables_;
  std::vector<double> friction_;
  std::vector<int> var_index_;       // per wall, -1 for a fixed wall
  std::vector<Vec3> velocity_;       // per wall, offered with its rows while some wall moves
  bool any_moving_ = false;
  double evaluate(int w) const;
};

}    // namespace hardcontact
