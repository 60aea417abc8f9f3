// The fix's wall sources as one list (planes, region surfaces, meshes, and any source a host
// adds, in that order): each run's init hands out the wall codes in the list's order (plane
// walls 0..P-1 in the order of the fix command, then each source's range), collects each
// wall's own friction, and every per-step hook of a wall source goes through here. The list
// is also the WallGaps of the diagnostics: a wall's gap comes from the source that owns it.
#pragma once

#include "contact_source.h"

#include <limits>
#include <vector>

namespace hardcontact {

class Obstacles : public WallGaps {
 public:
  // Appends a source (before the run's init).
  void add(WallSource *source) { sources_.push_back(source); }

  // Each source's init, then the codes in the list's order. wall_friction: by wall index each
  // wall's own Coulomb coefficient, negative for the atom type's; left empty when no wall has
  // its own. False if the walls are too many to number (the caller stops the run).
  bool init(const WallSourceInit &at, std::vector<double> &wall_friction)
  {
    long long next = 0;
    for (WallSource *s : sources_) {
      s->init(at);
      s->assign_walls(static_cast<int>(next));
      next += s->n_walls();
      if (next > std::numeric_limits<int>::max() / 2) return false;
    }
    wall_friction.clear();
    for (const WallSource *s : sources_)
      for (int w = s->first_wall(); w < s->first_wall() + s->n_walls(); ++w)
        wall_friction.push_back(s->friction(w));
    for (const double mu : wall_friction)
      if (mu >= 0.0) return true;    // some wall has its own
    wall_friction.clear();
    return true;
  }
  void at_current_step()
  {
    for (WallSource *s : sources_) s->at_current_step();
  }
  void check_sides() const
  {
    for (const WallSource *s : sources_) s->check_sides();
  }
  void advance(double h)
  {
    for (WallSource *s : sources_) s->advance(h);
  }
  void commit(double h)
  {
    for (WallSource *s : sources_) s->commit(h);
  }
  bool moving() const
  {
    for (const WallSource *s : sources_)
      if (s->moving()) return true;
    return false;
  }
  double wall_gap(int w, const Vec3 &x, double radius) const override
  {
    for (const WallSource *s : sources_)
      if (s->owns(w)) return s->wall_gap(w, x, radius);
    return std::numeric_limits<double>::infinity();
  }

 private:
  std::vector<WallSource *> sources_;
};

}    // namespace hardcontact
