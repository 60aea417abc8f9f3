// The wall sources of the fix as one WallGaps: plane walls hold wall indices 0..P-1 (in the
// order of the fix command), region walls the next kFacesPerRegion per region
// (region_wall_source.h), mesh walls the next (mesh_wall_source.h).
#pragma once

#include "mesh_wall_source.h"
#include "plane_wall_source.h"
#include "region_wall_source.h"

namespace hardcontact {

class Obstacles : public WallGaps {
 public:
  Obstacles(const PlaneWallSource &planes, const RegionWallSource &regions,
            const MeshWallSource &meshes) :
      planes_(planes), regions_(regions), meshes_(meshes)
  {
  }
  double wall_gap(int w, const Vec3 &x, double radius) const override
  {
    if (meshes_.owns(w)) return meshes_.gap(w, x, radius);
    if (regions_.owns(w)) return regions_.gap(w, x, radius);
    return planes_.walls()[w].gap(x.data(), radius);
  }

 private:
  const PlaneWallSource &planes_;
  const RegionWallSource &regions_;
  const MeshWallSource &meshes_;
};

}    // namespace hardcontact
