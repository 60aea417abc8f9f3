// The kinds of wall the `wall KIND values...` keyword can name besides planes and meshes, in
// one table (wall_kinds.cpp): a kind is its name, its number of values, its usage line and the
// function that makes the source of every wall of that kind on the fix line. A new kind of
// wall is its source (a WallSource, contact_source.h) and a line in that table: the keyword's
// parsing, its `friction mu`, the wall codes, the per-step hooks and the diagnostics follow.
#pragma once

#include "contact_source.h"

#include <memory>
#include <string>
#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace hardcontact {

// One `wall KIND values... [friction mu]` of the fix line.
struct WallSpec {
  std::vector<std::string> values;
  double friction = -1.0;    // its own Coulomb coefficient, negative for the atom type's
};

struct WallKind {
  const char *name;     // the word after `wall`
  int nvalues;          // values after the name
  const char *usage;    // for the keyword's error messages and doc line
  // the source of every wall of this kind, in the order of the fix line (their values are
  // checked there: errors name the wall and what to write)
  std::unique_ptr<WallSource> (*create)(LAMMPS_NS::LAMMPS *lmp, int groupbit,
                                        const std::vector<WallSpec> &walls);
};

// The kind named `name`, or null.
const WallKind *find_wall_kind(const std::string &name);
// Every kind, in the table's order (the order their wall codes follow).
const std::vector<WallKind> &wall_kinds();

}    // namespace hardcontact
