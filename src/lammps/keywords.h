// The keywords of `fix ID group hardcontact keyword values ...`, read in one place from one
// table (keywords.cpp): each row is a name, its number of values, its parser and its doc line.
// A new keyword is a row there, a field here, and a paragraph in doc/fix_hardcontact.md; an
// effect's keywords are rows of its own (effects/effect.h) and fill its object instead.
#pragma once

#include "effects/effect.h"
#include "sources/wall_kinds.h"

#include "../core/plane_wall.h"
#include "../core/solver.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace hardcontact {

struct FixOptions {
  // empty: the default, chosen once the law is known (cg without friction, apgd with it)
  std::string solver_name;
  SolverSettings settings;
  // whether `subspace` was given; if not, the fix picks kDefaultSubspace where it applies
  bool subspace_given = false;
  static constexpr int kDefaultSubspace = 10;
  // whether `tol` was given; if not, friction takes kFrictionTol (the measured front of
  // bench/friction 11: a frictional scene's observables at 1e-2 are those at 1e-4, within
  // their scatter over seeds, for 7-15 x less time), the other laws SolverSettings' 1e-4
  bool tol_given = false;
  static constexpr double kFrictionTol = 1.0e-2;
  // whether `cone` was given (settings.cone): it applies with friction only
  bool cone_given = false;
  // whether `speed` was given; if not, friction takes `speed contact` (settings.contact_speed:
  // the slip conditions against the contact points' slides, bench/friction/README.md "Two
  // scales": the same rest, 1.1-1.5 x faster flows, 2.4-2.9 x fewer iterations for beds
  // sliding or dragged as a whole), the other laws the approach
  bool speed_given = false;
  std::vector<PlaneWall> walls;
  std::vector<std::string> wall_variables;    // per wall: equal-style variable name, or ""
  // walls of a kind in the table of sources/wall_kinds.cpp (`wall region ID`, ...), in the
  // order of the fix line, each with its own friction (WallSpec::friction)
  struct KindWall {
    const WallKind *kind;
    WallSpec spec;
  };
  std::vector<KindWall> kind_walls;
  // triangle-mesh walls (`wall stl FILE [scale s]`): the file and the factor on its lengths
  struct MeshWall {
    std::string fix_id;    // `wall mesh ID` (LIGGGHTS's fix mesh/surface), else the file:
    std::string file;
    double scale = 1.0;
    // `move v_x v_y v_z` (each a variable name or "" for NULL) and `rotate v_theta Px Py Pz
    // Ax Ay Az` (theta "" for none): the mesh's displacement and rotation, as region ... move
    // / rotate take them
    std::string move[3];
    std::string theta;
    double point[3] = {0.0, 0.0, 0.0};
    double axis[3] = {0.0, 0.0, 1.0};
  };
  std::vector<MeshWall> wall_meshes;
  // A wall's own Coulomb coefficient (`wall ... friction mu`), per plane wall (as walls) and
  // per mesh; kByType: the pair value of the atom's type with itself.
  static constexpr double kByType = -1.0;
  std::vector<double> plane_friction;
  std::vector<double> mesh_friction;    // per mesh wall (as wall_meshes)
  bool warmstart = true;
  // the effects the keywords ask for (restitution, cohesion, ...: effects/effect.h), in the
  // order of the effects' table, each present; none asked for: empty (the paper's scheme)
  struct EffectPart {
    const EffectKind *kind;
    std::unique_ptr<Effect> effect;
  };
  std::vector<EffectPart> effects;
  bool has_effect(const char *name) const
  {
    for (const EffectPart &e : effects)
      if (std::string(e.kind->name) == name) return true;
    return false;
  }
  // Coulomb coefficient per type pair, (ntypes + 1)^2 row-major; empty or all 0: frictionless
  // (the normal law alone, as if the keyword were absent)
  std::vector<double> friction;
  bool disc = false;    // 2d discs: I = 1/2 m r^2 (as fix nve/sphere disc), else 2/5 m r^2
  // each resistance's coefficient per type pair (rolling, twisting, ...: by its index,
  // core/laws/law_list.h), (ntypes + 1)^2 row-major; empty: none. Needs friction.
  std::vector<double> resistance[kResistances];

  bool has_friction() const
  {
    return any_positive(friction) || any_positive(plane_friction) ||
           any_kind_friction(0.0) || any_positive(mesh_friction) || resistances() != 0;
  }
  // whether a wall's friction value is its own (not kByType)
  static bool own_friction(double v) { return v != kByType; }
  bool has_wall_friction() const
  {
    for (const double v : plane_friction)
      if (own_friction(v)) return true;
    if (any_kind_friction(kByType)) return true;
    for (const double v : mesh_friction)
      if (own_friction(v)) return true;
    return false;
  }
  // whether a kind wall's own coefficient is above `above` (0: positive; kByType: its own)
  bool any_kind_friction(double above) const
  {
    for (const KindWall &w : kind_walls)
      if (w.spec.friction > above) return true;
    return false;
  }
  bool has_resistance(int r) const { return any_positive(resistance[r]); }
  // bit r: resistance r has a positive coefficient
  unsigned resistances() const
  {
    unsigned mask = 0;
    for (int r = 0; r < kResistances; ++r)
      if (has_resistance(r)) mask |= 1u << r;
    return mask;
  }
  // The law the coefficients ask for (core/laws/law_list.h: law_composing; the fix checks
  // that one exists)
  ContactLaw contact_law() const
  {
    ContactLaw law = ContactLaw::Normal;
    law_composing(has_friction(), resistances(), law);
    return law;
  }
  static bool any_positive(const std::vector<double> &table)
  {
    for (const double v : table)
      if (v > 0.0) return true;
    return false;
  }
};

// Parses arg[first..narg-1]; stops with an error that names the keyword and what to write.
FixOptions parse_keywords(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg, int first);

// For the keywords' parsers (and the effects'): the number `word` given to `keyword`, or an
// error naming both; and one coefficient per type pair (values: v [I J], LAMMPS type ranges,
// all pairs by default, later keywords win), in [lo, hi], into a (ntypes + 1)^2 table, else
// "Fix hardcontact NAME must be WHAT, got V".
double keyword_number(LAMMPS_NS::LAMMPS *lmp, const char *keyword, const char *word);
void parse_pair_coefficient(LAMMPS_NS::LAMMPS *lmp, const char *name, const char *what,
                            double lo, double hi, char **values, int n,
                            std::vector<double> &table);

}    // namespace hardcontact
