// The table of wall kinds (wall_kinds.h): adding a kind of wall is adding a line here and its
// source's files.
#include "wall_kinds.h"

#include "region_wall_source.h"

namespace hardcontact {

const std::vector<WallKind> &wall_kinds()
{
  static const std::vector<WallKind> kinds = {
      {"region", 1, "wall region ID: the surface of a region", &RegionWallSource::create},
  };
  return kinds;
}

const WallKind *find_wall_kind(const std::string &name)
{
  for (const WallKind &k : wall_kinds())
    if (name == k.name) return &k;
  return nullptr;
}

}    // namespace hardcontact
