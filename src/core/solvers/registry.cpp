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
template <class S>
std::unique_ptr<Solver> create()
{
  return std::unique_ptr<Solver>(new S());
}
// A solver family's constructor of each law, in ContactLaw's order (laws/law_list.h).
#define HARDCONTACT_DETAIL_CREATE(Law, Enumerator, Suffix, Template) &create<Template<Law>>,
#define HARDCONTACT_FAMILY(name, Template) \
  Entry { name, { HARDCONTACT_LAWS_WITH(HARDCONTACT_DETAIL_CREATE, Template) } }

struct Entry {
  const char *name;
  // per ContactLaw (laws/law_list.h); null: the solver does not solve that law
  std::unique_ptr<Solver> (*create[kContactLaws])();
};
const Entry registry[] = {
    HARDCONTACT_FAMILY("uzawa", UzawaSolver),
    HARDCONTACT_FAMILY("apgd", ApgdSolver),
    HARDCONTACT_FAMILY("pgs", PgsSolver),
    HARDCONTACT_FAMILY("nsgs", NsgsSolver),
    HARDCONTACT_FAMILY("hybrid", HybridSolver),
    // the paper's law only
    {"cg", {&create<ProjectedCg>}},
    {"exact", {&create<Exact>}},
};
#undef HARDCONTACT_FAMILY
#undef HARDCONTACT_DETAIL_CREATE
}    // namespace

std::unique_ptr<Solver> make_solver(const std::string &name, ContactLaw law)
{
  for (const Entry &e : registry) {
    if (name != e.name) continue;
    auto make = e.create[static_cast<int>(law)];
    return make ? make() : nullptr;
  }
  return nullptr;
}

bool solver_has_friction(const std::string &name)
{
  for (const Entry &e : registry)
    if (name == e.name) return e.create[static_cast<int>(ContactLaw::Coulomb)] != nullptr;
  return false;
}

std::vector<std::string> solver_names()
{
  std::vector<std::string> names;
  for (const Entry &e : registry) names.emplace_back(e.name);
  return names;
}

}    // namespace hardcontact
