// An opt-in effect of the step (restitution, cohesion, ...) as one part, in the manner of
// LAMMPS GRANULAR's sub-models: the object holds the values of its keywords, its checks, its
// per-row values, and its term on u_free (before the solve), on the rows' targets (each solve
// round) or on the forces the fix reports. The fix makes an effect only when its keywords ask
// for it (present()), so an absent effect is no object and costs nothing.
//
// A new effect is its class (a file pair here) and a line in the table of effect_kinds.cpp:
// its keyword rows then join the fix's keyword table (keywords.cpp), and the step calls its
// hooks (step.cpp). doc/architecture.md has the recipe.
#pragma once

#include "../../core/contact_problem.h"
#include "../../core/distributed_ops.h"

#include <memory>
#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace hardcontact {

// table[type_i, type_j] ((ntypes + 1)^2, row-major) of rows first.. of p into out (a wall row:
// the atom's type with itself).
void pair_values_of_rows(const ContactProblem &p, const int *type, int ntypes,
                         const std::vector<double> &table, int first, std::vector<double> &out);

// What an effect sees of the step it acts in.
struct EffectStep {
  LAMMPS_NS::LAMMPS *lmp;
  ContactProblem &problem;    // the candidate rows (each round adds some) and u_free
  DistributedOps &ops;
  double tol;                 // the solver tolerance
  // table[type_i, type_j] of rows first.. into out (pair_values_of_rows)
  void pair_values(const std::vector<double> &table, int first, std::vector<double> &out) const;
};

class Effect {
 public:
  virtual ~Effect() = default;
  // Whether the keywords asked for anything: the fix keeps only effects that are present.
  virtual bool present() const = 0;
  // The fix's init: an error for what the deck cannot have with it.
  virtual void init(LAMMPS_NS::LAMMPS *) {}
  // The step's candidate rows are offered, none has its target yet: terms on u_free (eq. 14).
  // Returns whether it may have changed u_free (the solvers then find V themselves).
  virtual bool begin_step(EffectStep &) { return false; }
  // Rows first.. have the common target terms (core/targets.h): the effect's own. Called
  // for each round's new rows, and for every row again (first 0) when the targets are
  // written again (KeptOverlaps::undo).
  virtual void target_rows(EffectStep &, int) {}
  // After the last round, from the solver's multipliers (block per row): the contact forces
  // the fix reports (outputs, virial), or null where they are the multipliers.
  virtual const std::vector<double> *reported_forces(const ContactProblem &,
                                                     const std::vector<double> &, int)
  {
    return nullptr;
  }
};

// One keyword of an effect: its name, values (and optional ones, all or none), the doc line,
// and the parser that stores them in the effect (values[0..n-1]).
struct EffectKeyword {
  const char *name;
  int nvalues;
  int optional;
  const char *doc;
  void (*parse)(LAMMPS_NS::LAMMPS *lmp, char **values, int n, Effect &effect);
};

struct EffectKind {
  const char *name;
  std::unique_ptr<Effect> (*create)(LAMMPS_NS::LAMMPS *lmp);
  std::vector<EffectKeyword> keywords;
};

// The create of a kind whose class needs nothing to be made (its keywords fill it).
template <class E>
std::unique_ptr<Effect> make_effect(LAMMPS_NS::LAMMPS *)
{
  return std::make_unique<E>();
}

// Every kind, in the table's order (effect_kinds.cpp): the order of their keywords in the
// fix's table, and of their hooks in a step.
const std::vector<EffectKind> &effect_kinds();

}    // namespace hardcontact
