#include "keywords.h"

#include "lammps_compat.h"
#include "effects/effect.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "lammps.h"
#include "utils.h"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>

using namespace LAMMPS_NS;

namespace hardcontact {
namespace {

// subspace N: each kept correction is a double per row and a product per solve
constexpr int kMaxSubspace = 100;

// A parser reads the values of its keyword (values[0..n-1]) into the options; n is nvalues,
// or nvalues + optional when the words after them are values rather than the next keyword.
using Parser = void (*)(LAMMPS *lmp, char **values, int n, FixOptions &options);

struct Keyword {
  const char *name;
  int nvalues;
  int optional;    // values that may follow (e.g. type ranges I J), all or none
  Parser parse;    // null for an effect's keyword, which fills its effect's object instead:
  const char *doc;
  const EffectKeyword *effect_row = nullptr;    // its row (effects/effect.h)
  int effect = -1;                              // its kind's index in effect_kinds()
};

bool is_keyword(const char *word);

}    // namespace

double keyword_number(LAMMPS *lmp, const char *keyword, const char *word)
{
  if (!utils::is_double(word))
    compat::error_all(lmp->error, FLERR, "Fix hardcontact {}: expected a number, got '{}'", keyword,
                      word);
  // Checked before utils::numeric: modern LAMMPS stops there on 1e999 with a message that
  // does not name the keyword.
  if (!std::isfinite(std::strtod(word, nullptr)))
    compat::error_all(lmp->error, FLERR, "Fix hardcontact {}: value '{}' is not a finite number",
                      keyword, word);
  return utils::numeric(FLERR, word, false, lmp);
}

namespace {

// A value per type pair (I, J LAMMPS type ranges, default every pair; later lines win) into a
// (ntypes + 1)^2 table.
void set_pair_values(LAMMPS *lmp, char **values, int n, double value, std::vector<double> &table)
{
  const int ntypes = lmp->atom->ntypes;
  int ilo = 1, ihi = ntypes, jlo = 1, jhi = ntypes;
  if (n == 3) {
    utils::bounds(FLERR, values[1], 1, ntypes, ilo, ihi, lmp->error);
    utils::bounds(FLERR, values[2], 1, ntypes, jlo, jhi, lmp->error);
  }
  table.resize((ntypes + 1) * (ntypes + 1), 0.0);
  for (int i = ilo; i <= ihi; ++i)
    for (int j = jlo; j <= jhi; ++j) {
      table[i * (ntypes + 1) + j] = value;
      table[j * (ntypes + 1) + i] = value;
    }
}

}    // namespace

// One coefficient per type pair, in [lo, hi]; else "Fix hardcontact NAME must be WHAT, got V".
void parse_pair_coefficient(LAMMPS *lmp, const char *name, const char *what, double lo,
                            double hi, char **values, int n, std::vector<double> &table)
{
  const double v = keyword_number(lmp, name, values[0]);
  if (v < lo || v > hi)
    compat::error_all(lmp->error, FLERR, "Fix hardcontact {} must be {}, got {}", name, what,
                      values[0]);
  set_pair_values(lmp, values, n, v, table);
}

namespace {

std::string joined(const std::vector<std::string> &names)
{
  std::string s;
  for (const auto &n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

void parse_solver(LAMMPS *lmp, char **values, int, FixOptions &o)
{
  o.solver_name = values[0];
  if (!make_solver(o.solver_name))
    compat::error_all(lmp->error, FLERR, "Fix hardcontact solver '{}' is unknown: use one of {}",
                      o.solver_name, joined(solver_names()));
}

void parse_tol(LAMMPS *lmp, char **values, int, FixOptions &o)
{
  o.settings.tol = keyword_number(lmp, "tol", values[0]);
  o.tol_given = true;
  if (o.settings.tol <= 0.0 || o.settings.tol >= 1.0)
    compat::error_all(lmp->error, FLERR,
                      "Fix hardcontact tol must be in (0, 1) (an overlap relative to the "
                      "contact size), got {}",
                      values[0]);
}

void parse_maxiter(LAMMPS *lmp, char **values, int, FixOptions &o)
{
  if (!utils::is_integer(values[0]))
    compat::error_all(lmp->error, FLERR, "Fix hardcontact maxiter: expected an integer, got '{}'",
                      values[0]);
  const bigint maxiter = utils::bnumeric(FLERR, values[0], false, lmp);
  if (maxiter < 1 || maxiter > MAXSMALLINT)
    compat::error_all(lmp->error, FLERR,
                      "Fix hardcontact maxiter must be at least 1 and at most {}, got {}",
                      MAXSMALLINT, values[0]);
  o.settings.maxiter = static_cast<int>(maxiter);
}

void parse_subspace(LAMMPS *lmp, char **values, int, FixOptions &o)
{
  if (!utils::is_integer(values[0]))
    compat::error_all(lmp->error, FLERR,
                      "Fix hardcontact subspace: expected an integer (past corrections kept, 0 "
                      "for none), got '{}'",
                      values[0]);
  const bigint n = utils::bnumeric(FLERR, values[0], false, lmp);
  if (n < 0 || n > kMaxSubspace)
    compat::error_all(lmp->error, FLERR,
                      "Fix hardcontact subspace must be from 0 to {} (past corrections kept), "
                      "got {}",
                      kMaxSubspace, values[0]);
  o.settings.subspace = static_cast<int>(n);
  o.subspace_given = true;
}

void parse_rho(LAMMPS *lmp, char **values, int, FixOptions &o)
{
  o.settings.rho = keyword_number(lmp, "rho", values[0]);
  if (o.settings.rho <= 0.0)
    compat::error_all(lmp->error, FLERR,
                      "Fix hardcontact rho must be positive (omit it for the automatic "
                      "step), got {}",
                      values[0]);
}

void parse_warmstart(LAMMPS *lmp, char **values, int, FixOptions &o)
{
  const std::string value = values[0];
  if (value != "yes" && value != "no")
    compat::error_all(lmp->error, FLERR, "Fix hardcontact warmstart must be yes or no, got '{}'",
                      value);
  o.warmstart = value == "yes";
}

void parse_cone(LAMMPS *lmp, char **values, int, FixOptions &o)
{
  const std::string value = values[0];
  using Cone = SolverSettings::Cone;
  if (value == "lagged") o.settings.cone = Cone::Lagged;
  else if (value == "exact") o.settings.cone = Cone::Exact;
  else if (value == "convex") o.settings.cone = Cone::Convex;
  else
    compat::error_all(lmp->error, FLERR,
                      "Fix hardcontact cone must be lagged (the default), exact or convex, got "
                      "'{}'",
                      value);
  o.cone_given = true;
}

void parse_speed(LAMMPS *lmp, char **values, int, FixOptions &o)
{
  const std::string value = values[0];
  if (value != "approach" && value != "contact")
    compat::error_all(lmp->error, FLERR,
                      "Fix hardcontact speed must be approach or contact (the default with "
                      "friction), got '{}'",
                      value);
  o.settings.contact_speed = value == "contact";
  o.speed_given = true;
}

void parse_wall(LAMMPS *lmp, char **values, int n, FixOptions &o)
{
  const std::string plane = values[0];
  if (plane == "stl") {    // its 'scale s' is read after it, as a wall's 'friction mu'
    if (n != 2)
      lmp->error->all(FLERR, "Fix hardcontact wall stl takes one value, the STL file's name");
    FixOptions::MeshWall mesh;
    mesh.file = values[1];
    o.wall_meshes.push_back(mesh);
    o.mesh_friction.push_back(FixOptions::kByType);
    return;
  }
  if (plane == "mesh") {    // LIGGGHTS's fix mesh/surface ID
    if (n != 2)
      lmp->error->all(FLERR, "Fix hardcontact wall mesh takes one value, the ID of a fix "
                             "mesh/surface");
    FixOptions::MeshWall mesh;
    mesh.fix_id = values[1];
    o.wall_meshes.push_back(mesh);
    o.mesh_friction.push_back(FixOptions::kByType);
    return;
  }
  if (const WallKind *kind = find_wall_kind(plane)) {    // sources/wall_kinds.cpp
    WallSpec spec;
    spec.values.assign(values + 1, values + n);
    spec.friction = FixOptions::kByType;
    o.kind_walls.push_back({kind, spec});
    return;
  }
  if (n != 3)
    compat::error_all(lmp->error, FLERR,
                      "Fix hardcontact wall needs 3 value(s) after it (wall {} lo hi)", plane);
  int dim = -1;
  if (plane == "xplane") dim = 0;
  else if (plane == "yplane") dim = 1;
  else if (plane == "zplane") dim = 2;
  else
    compat::error_all(lmp->error, FLERR,
                      "Fix hardcontact wall '{}' is unknown: use xplane, yplane, zplane, {}"
                      "stl or mesh",
                      plane, [] {
                        std::string names;
                        for (const WallKind &k : wall_kinds()) names += std::string(k.name) + ", ";
                        return names;
                      }());
  if (dim == 2 && lmp->domain->dimension == 2)
    lmp->error->all(FLERR, "Fix hardcontact wall zplane is not allowed in a 2d simulation");
  const bool has_lo = strcmp(values[1], "NULL") != 0;
  const bool has_hi = strcmp(values[2], "NULL") != 0;
  if (!has_lo && !has_hi)
    compat::error_all(lmp->error, FLERR, "Fix hardcontact wall {}: lo and hi cannot both be NULL",
                      plane);
  // a position is a number, or v_name: an equal-style variable, a moving wall
  auto variable = [](const char *word) { return strncmp(word, "v_", 2) == 0 ? word + 2 : ""; };
  const std::string var_lo = has_lo ? variable(values[1]) : "";
  const std::string var_hi = has_hi ? variable(values[2]) : "";
  double lo = 0.0, hi = 0.0;
  if (has_lo && var_lo.empty()) lo = keyword_number(lmp, "wall lo", values[1]);
  if (has_hi && var_hi.empty()) hi = keyword_number(lmp, "wall hi", values[2]);
  if (has_lo && has_hi && var_lo.empty() && var_hi.empty() && lo >= hi)
    compat::error_all(lmp->error, FLERR, "Fix hardcontact wall {}: lo ({}) must be below hi ({})",
                      plane, lo, hi);
  if (has_lo) {
    o.walls.push_back({dim, true, lo});
    o.wall_variables.push_back(var_lo);
    o.plane_friction.push_back(FixOptions::kByType);
  }
  if (has_hi) {
    o.walls.push_back({dim, false, hi});
    o.wall_variables.push_back(var_hi);
    o.plane_friction.push_back(FixOptions::kByType);
  }
}

// `friction mu` right after a wall's values: that wall's own coefficient (every plane of an
// `xplane lo hi`, every face of a region). Returns the words it read.
int parse_wall_friction(LAMMPS *lmp, char **arg, int narg, int iarg, size_t planes_before,
                        size_t kinds_before, size_t meshes_before, FixOptions &o)
{
  if (iarg + 1 >= narg)
    lmp->error->all(FLERR, "Fix hardcontact wall ... friction needs a value (the wall's own "
                           "Coulomb coefficient)");
  const double mu = keyword_number(lmp, "wall friction", arg[iarg + 1]);
  if (mu < 0.0)
    compat::error_all(lmp->error, FLERR,
                      "Fix hardcontact wall friction must be a Coulomb coefficient >= 0, got {}",
                      arg[iarg + 1]);
  if (iarg + 2 < narg && !is_keyword(arg[iarg + 2]) && strcmp(arg[iarg + 2], "scale") != 0 &&
      strcmp(arg[iarg + 2], "move") != 0 && strcmp(arg[iarg + 2], "rotate") != 0)
    compat::error_all(lmp->error, FLERR,
                      "Fix hardcontact wall ... friction takes one value, the wall's own "
                      "coefficient, got '{}' after it: for type pairs write 'friction mu I J' "
                      "before the wall keyword",
                      arg[iarg + 2]);
  for (size_t k = planes_before; k < o.plane_friction.size(); ++k) o.plane_friction[k] = mu;
  for (size_t k = kinds_before; k < o.kind_walls.size(); ++k) o.kind_walls[k].spec.friction = mu;
  for (size_t k = meshes_before; k < o.mesh_friction.size(); ++k) o.mesh_friction[k] = mu;
  return 2;
}

// `move v_x v_y v_z` after `wall stl FILE`: the mesh's displacement from where the file puts
// it, each an equal-style variable (v_name) or NULL. Returns the words it read.
int parse_wall_move(LAMMPS *lmp, char **arg, int narg, int iarg, FixOptions &o)
{
  if (iarg + 3 >= narg)
    lmp->error->all(FLERR, "Fix hardcontact wall stl ... move needs 3 values (v_x v_y v_z: "
                           "equal-style variables of the displacement, or NULL)");
  bool any = false;
  for (int d = 0; d < 3; ++d) {
    const char *w = arg[iarg + 1 + d];
    if (strcmp(w, "NULL") == 0) continue;
    if (strncmp(w, "v_", 2) != 0 || w[2] == '\0')
      compat::error_all(lmp->error, FLERR,
                        "Fix hardcontact wall stl ... move takes v_name or NULL per direction "
                        "(as region ... move), got '{}'",
                        w);
    o.wall_meshes.back().move[d] = w + 2;
    any = true;
  }
  if (!any)
    lmp->error->all(FLERR, "Fix hardcontact wall stl ... move NULL NULL NULL moves nothing: "
                           "remove it or name a variable");
  return 4;
}

// `rotate v_theta Px Py Pz Ax Ay Az` after `wall stl FILE`: the mesh turned by the angle
// theta (radians, an equal-style variable) about the axis A through P, as region ... rotate.
int parse_wall_rotate(LAMMPS *lmp, char **arg, int narg, int iarg, FixOptions &o)
{
  if (iarg + 7 >= narg)
    lmp->error->all(FLERR, "Fix hardcontact wall stl ... rotate needs 7 values (v_theta Px Py "
                           "Pz Ax Ay Az: the angle in radians, a point on the axis, its "
                           "direction)");
  const char *w = arg[iarg + 1];
  if (strncmp(w, "v_", 2) != 0 || w[2] == '\0')
    compat::error_all(lmp->error, FLERR,
                      "Fix hardcontact wall stl ... rotate takes the angle as v_name (an "
                      "equal-style variable, radians), got '{}'",
                      w);
  FixOptions::MeshWall &m = o.wall_meshes.back();
  m.theta = w + 2;
  for (int d = 0; d < 3; ++d)
    m.point[d] = keyword_number(lmp, "wall stl rotate P", arg[iarg + 2 + d]);
  for (int d = 0; d < 3; ++d)
    m.axis[d] = keyword_number(lmp, "wall stl rotate A", arg[iarg + 5 + d]);
  if (m.axis[0] == 0.0 && m.axis[1] == 0.0 && m.axis[2] == 0.0)
    lmp->error->all(FLERR, "Fix hardcontact wall stl ... rotate: the axis direction is zero");
  return 8;
}

// `scale s` right after `wall stl FILE`: the factor on the file's lengths (CAD in mm, a deck
// in m: scale 0.001). Returns the words it read.
int parse_wall_scale(LAMMPS *lmp, char **arg, int narg, int iarg, FixOptions &o)
{
  if (iarg + 1 >= narg)
    lmp->error->all(FLERR, "Fix hardcontact wall stl ... scale needs a value (the factor on the "
                           "file's lengths)");
  const double s = keyword_number(lmp, "wall stl scale", arg[iarg + 1]);
  if (!(s > 0.0))
    compat::error_all(lmp->error, FLERR,
                      "Fix hardcontact wall stl scale must be a positive factor, got {}",
                      arg[iarg + 1]);
  o.wall_meshes.back().scale = s;
  return 2;
}

const double kUnbounded = std::numeric_limits<double>::infinity();

void parse_friction(LAMMPS *lmp, char **values, int n, FixOptions &o)
{
  parse_pair_coefficient(lmp, "friction", "a Coulomb coefficient >= 0 (0: frictionless)", 0.0,
                         kUnbounded, values, n, o.friction);
}

// A resistance's keyword (core/laws/law_list.h, HARDCONTACT_RESISTANCES): its coefficient per
// type pair.
template <class Disc>
void parse_resistance(LAMMPS *lmp, char **values, int n, FixOptions &o)
{
  parse_pair_coefficient(lmp, Disc::keyword, Disc::bound, 0.0, kUnbounded, values, n,
                         o.resistance[Disc::index]);
}
#define HARDCONTACT_RESISTANCE_ROW(Disc) {Disc::keyword, 1, 2, parse_resistance<Disc>, Disc::usage},

void parse_disc(LAMMPS *lmp, char **, int, FixOptions &o)
{
  if (lmp->domain->dimension != 2)
    lmp->error->all(FLERR, "Fix hardcontact disc requires 'dimension 2' (discs spin as "
                           "cylinders): remove disc in 3d");
  o.disc = true;
}

const Keyword before_effects[] = {
    {"solver", 1, 0, parse_solver, "solver name: cg (default without friction), hybrid (default with friction), apgd, nsgs, pgs, uzawa or exact"},
    {"tol", 1, 0, parse_tol, "tol value: row tolerance relative to the row scale, in (0, 1)"},
    {"maxiter", 1, 0, parse_maxiter, "maxiter N: at most N solver iterations per solve"},
    {"rho", 1, 0, parse_rho, "rho value: fixed solver step (omit: automatic)"},
    {"subspace", 1, 0, parse_subspace,
     "subspace N: cg or apgd (frictionless) start from the best point in the span of the last N "
     "corrections (default 10 for cg without friction, else 0: off)"},
    {"warmstart", 1, 0, parse_warmstart, "warmstart yes/no: start from the last step's forces"},
    {"wall", 2, 1, parse_wall,
     "wall xplane|yplane|zplane lo hi: flat walls, NULL for none, v_name for a moving one; "
     "wall region ID: the surface of a region; wall stl FILE [scale s] [move v_x v_y v_z] "
     "[rotate v_theta Px Py Pz Ax Ay Az]: a triangle mesh from an STL file (ASCII or binary), "
     "its lengths times s, moved as region ... move/rotate; wall mesh ID: LIGGGHTS's fix "
     "mesh/surface ID (moved by its fix move/mesh); each followed by 'friction mu': the "
     "wall's own Coulomb coefficient"},
};
// then each effect's keywords (restitution, bounce, cohesion, ...: effects/effect_kinds.cpp)
const Keyword after_effects[] = {
    {"friction", 1, 2, parse_friction,
     "friction mu [I J]: Coulomb friction coefficient >= 0 for type pairs I J (all: default); "
     "walls use the value of the atom's type with itself"},
    {"cone", 1, 0, parse_cone,
     "cone lagged|exact|convex: friction's cone, De Saxce's shift kept at its warm-start value "
     "within 3 tol of Coulomb's (lagged, the default), brought to its fixed point in every solve "
     "(exact), or none (convex: Anitescu and Tasora's relaxation, sliding contacts lift off at "
     "mu |slip|)"},
    {"speed", 1, 0, parse_speed,
     "speed approach|contact: the stopping test's scales h V, V the contact points' fastest "
     "approach, or with friction (its default) the slip conditions' from their fastest motion, "
     "slides included"},
    // rolling, twisting, ...: a row per resistance
    HARDCONTACT_RESISTANCES(HARDCONTACT_RESISTANCE_ROW)
    {"disc", 0, 0, parse_disc, "disc: 2d discs, moment of inertia 1/2 m r^2"},
};

// The fix's keywords, in the order of the doc: the rows above with the effects' between them.
const std::vector<Keyword> &keywords()
{
  static const std::vector<Keyword> table = [] {
    std::vector<Keyword> t(std::begin(before_effects), std::end(before_effects));
    const std::vector<EffectKind> &kinds = effect_kinds();
    for (size_t e = 0; e < kinds.size(); ++e)
      for (const EffectKeyword &k : kinds[e].keywords)
        t.push_back({k.name, k.nvalues, k.optional, nullptr, k.doc, &k, static_cast<int>(e)});
    t.insert(t.end(), std::begin(after_effects), std::end(after_effects));
    return t;
  }();
  return table;
}

bool is_keyword(const char *word)
{
  for (const Keyword &k : keywords())
    if (strcmp(word, k.name) == 0) return true;
  return false;
}

// "solver, tol, ... or wall", from the table.
std::string keyword_list()
{
  std::string s;
  const int n = static_cast<int>(keywords().size());
  for (int k = 0; k < n; ++k)
    s += (k == 0 ? "" : k + 1 < n ? ", " : " or ") + std::string(keywords()[k].name);
  return s;
}

}    // namespace

FixOptions parse_keywords(LAMMPS *lmp, int narg, char **arg, int first)
{
  FixOptions options;
  bool pair_friction = false;    // a 'friction' keyword of its own (not a wall's)
  std::vector<std::unique_ptr<Effect>> made(effect_kinds().size());    // by kind
  std::vector<std::string> given(effect_kinds().size());    // by kind: its keywords written
  int iarg = first;
  while (iarg < narg) {
    const Keyword *found = nullptr;
    for (const Keyword &k : keywords())
      if (strcmp(arg[iarg], k.name) == 0) found = &k;
    if (!found)
      compat::error_all(lmp->error, FLERR, "Fix hardcontact keyword '{}' is unknown: use {}",
                        arg[iarg], keyword_list());
    if (iarg + found->nvalues >= narg)
      compat::error_all(lmp->error, FLERR, "Fix hardcontact {} needs {} value(s) after it ({})",
                        found->name, found->nvalues, found->doc);
    int n = found->nvalues;
    const bool stl = found->parse == parse_wall && strcmp(arg[iarg + 1], "stl") == 0;
    // `wall KIND` of the kinds' table: the kind says how many values follow its name
    const WallKind *kind = found->parse == parse_wall ? find_wall_kind(arg[iarg + 1]) : nullptr;
    if (kind) {
      n = 1 + kind->nvalues;
      const int extra = iarg + n + 1;    // the word after its values: a keyword or 'friction'
      if (iarg + n >= narg || (extra < narg && !is_keyword(arg[extra]) &&
                               strcmp(arg[extra], "friction") != 0))
        compat::error_all(lmp->error, FLERR, "Fix hardcontact wall {} takes {} value(s) ({})",
                          kind->name, kind->nvalues, kind->usage);
    }
    // optional values: present when the next word is not a keyword name
    if (!stl && !kind && found->optional > 0 && iarg + n + 1 < narg &&
        !is_keyword(arg[iarg + n + 1])) {
      if (iarg + n + found->optional >= narg)
        compat::error_all(lmp->error, FLERR, "Fix hardcontact {} takes {} or {} value(s) after it",
                          found->name, found->nvalues, found->nvalues + found->optional);
      n += found->optional;
    }
    const size_t planes_before = options.plane_friction.size();
    const size_t kinds_before = options.kind_walls.size();
    const size_t meshes_before = options.mesh_friction.size();
    if (found->effect_row) {    // the effect's object, made at its first keyword
      std::unique_ptr<Effect> &effect = made[found->effect];
      if (!effect) effect = effect_kinds()[found->effect].create(lmp);
      // the keywords that only shape the effect (bounce), not the one that turns it on
      std::string &names = given[found->effect];
      if (strcmp(found->name, effect_kinds()[found->effect].keywords[0].name) != 0)
        names += (names.empty() ? "" : ", ") + std::string(found->name);
      found->effect_row->parse(lmp, arg + iarg + 1, n, *effect);
    } else {
      found->parse(lmp, arg + iarg + 1, n, options);
    }
    iarg += 1 + n;
    if (found->parse == parse_wall) {
      bool scaled = false, rubbed = false, moved = false, turned = false;    // each at most once
      for (;;) {
        if (stl && !scaled && iarg < narg && strcmp(arg[iarg], "scale") == 0) {
          iarg += parse_wall_scale(lmp, arg, narg, iarg, options);
          scaled = true;
        } else if (stl && !moved && iarg < narg && strcmp(arg[iarg], "move") == 0) {
          iarg += parse_wall_move(lmp, arg, narg, iarg, options);
          moved = true;
        } else if (stl && !turned && iarg < narg && strcmp(arg[iarg], "rotate") == 0) {
          iarg += parse_wall_rotate(lmp, arg, narg, iarg, options);
          turned = true;
        } else if (!rubbed && iarg < narg && strcmp(arg[iarg], "friction") == 0) {
          iarg += parse_wall_friction(lmp, arg, narg, iarg, planes_before, kinds_before,
                                      meshes_before, options);
          rubbed = true;
        } else {
          break;
        }
      }
    } else if (found->parse == parse_friction) {
      pair_friction = true;
    }
  }
  // the effects asked for, in the table's order; an effect whose keywords ask for nothing
  // (bounce without restitution, or with restitution 0) is dropped, and a deck that shaped it
  // (bounce) told: that keyword was written for something which does not happen. 'restitution
  // 0' alone says what the default says: nothing to tell.
  for (size_t e = 0; e < made.size(); ++e) {
    if (!made[e]) continue;
    if (made[e]->present()) {
      options.effects.push_back({&effect_kinds()[e], std::move(made[e])});
    } else if (!given[e].empty() && lmp->comm->me == 0) {
      const EffectKind &kind = effect_kinds()[e];
      compat::warning(lmp->error, FLERR,
                      "Fix hardcontact: no {} is above 0, so '{}' does nothing: give {} a "
                      "value above 0 or remove '{}'",
                      kind.name, given[e], kind.name, given[e]);
    }
  }
  // A deck written before walls had their own coefficient ('wall zplane 0 NULL friction 0.5')
  // meant friction everywhere: say what it means now.
  if (options.has_wall_friction() && !pair_friction && lmp->comm->me == 0)
    compat::warning(lmp->error, FLERR,
                    "Fix hardcontact: 'friction' after a wall keyword is that wall's own "
                    "coefficient; the spheres have no friction with each other: write "
                    "'friction mu' before the wall keyword for the pairs");
  // the pair table exists whenever a friction law is solved (walls only: pairs at 0)
  if (options.has_wall_friction() && options.friction.empty())
    options.friction.assign((lmp->atom->ntypes + 1) * (lmp->atom->ntypes + 1), 0.0);
  return options;
}

}    // namespace hardcontact
