// The `solver` keyword's table: adding an algorithm is adding a line here and a file.
#include "../solver.h"
#include "apgd.h"
#include "exact.h"
#include "pgs.h"
#include "uzawa.h"

namespace hardcontact {

namespace {
struct Entry {
  const char *name;
  std::unique_ptr<Solver> (*create)();
};
const Entry registry[] = {
    {"uzawa", [] { return std::unique_ptr<Solver>(new Uzawa()); }},
    {"apgd", [] { return std::unique_ptr<Solver>(new Apgd()); }},
    {"pgs", [] { return std::unique_ptr<Solver>(new Pgs()); }},
    {"exact", [] { return std::unique_ptr<Solver>(new Exact()); }},
};
}    // namespace

std::unique_ptr<Solver> make_solver(const std::string &name)
{
  for (const Entry &e : registry)
    if (name == e.name) return e.create();
  return nullptr;
}

std::vector<std::string> solver_names()
{
  std::vector<std::string> names;
  for (const Entry &e : registry) names.emplace_back(e.name);
  return names;
}

}    // namespace hardcontact
