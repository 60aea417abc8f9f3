// The `solver` keyword's table: adding an algorithm is adding a line here and a file.
#include "../solver.h"
#include "apgd.h"
#include "exact.h"
#include "hybrid.h"
#include "nsgs.h"
#include "projected_cg.h"
#include "pgs.h"
#include "uzawa.h"

namespace hardcontact {

namespace {
struct Entry {
  const char *name;
  std::unique_ptr<Solver> (*create)();             // the paper's law (laws/normal.h)
  std::unique_ptr<Solver> (*create_friction)();    // Coulomb's (laws/coulomb.h); null: none
  std::unique_ptr<Solver> (*create_rolling)();     // with rolling (laws/rolling.h); null: none
};
const Entry registry[] = {
    {"uzawa", [] { return std::unique_ptr<Solver>(new Uzawa()); },
     [] { return std::unique_ptr<Solver>(new UzawaFriction()); },
     [] { return std::unique_ptr<Solver>(new UzawaRolling()); }},
    {"apgd", [] { return std::unique_ptr<Solver>(new Apgd()); },
     [] { return std::unique_ptr<Solver>(new ApgdFriction()); },
     [] { return std::unique_ptr<Solver>(new ApgdRolling()); }},
    {"pgs", [] { return std::unique_ptr<Solver>(new Pgs()); },
     [] { return std::unique_ptr<Solver>(new PgsFriction()); },
     [] { return std::unique_ptr<Solver>(new PgsRolling()); }},
    {"nsgs", [] { return std::unique_ptr<Solver>(new Nsgs()); },
     [] { return std::unique_ptr<Solver>(new NsgsFriction()); },
     [] { return std::unique_ptr<Solver>(new NsgsRolling()); }},
    {"hybrid", [] { return std::unique_ptr<Solver>(new Hybrid()); }, [] { return std::unique_ptr<Solver>(new HybridFriction()); },
     [] { return std::unique_ptr<Solver>(new HybridRolling()); }},
    {"cg", [] { return std::unique_ptr<Solver>(new ProjectedCg()); }, nullptr, nullptr},
    {"exact", [] { return std::unique_ptr<Solver>(new Exact()); }, nullptr, nullptr},
};
}    // namespace

std::unique_ptr<Solver> make_solver(const std::string &name, ContactLaw law)
{
  for (const Entry &e : registry) {
    if (name != e.name) continue;
    auto create = law == ContactLaw::Normal    ? e.create
                  : law == ContactLaw::Coulomb ? e.create_friction
                                               : e.create_rolling;
    return create ? create() : nullptr;
  }
  return nullptr;
}

bool solver_has_friction(const std::string &name)
{
  for (const Entry &e : registry)
    if (name == e.name) return e.create_friction != nullptr;
  return false;
}

std::vector<std::string> solver_names()
{
  std::vector<std::string> names;
  for (const Entry &e : registry) names.emplace_back(e.name);
  return names;
}

}    // namespace hardcontact
