// The contact laws, declared once. Every per-law name the code needs is generated from the list
// below: the ContactLaw enumerators, each solver family's aliases (Apgd, ApgdFriction,
// ApgdRolling), the explicit instantiations of the templates written against a law, the
// solver registry's constructors, the multipliers per contact (law_block) and the values the
// contact history keeps (law_history). A new law is its file in laws/ (law.h: the interface)
// and a line here.
//
// HARDCONTACT_LAWS_WITH(X, ...) expands X(Law, Enumerator, Suffix, ...) once per law, in the
// order of ContactLaw; Suffix names the law in a solver family's alias (empty: the paper's).
#pragma once

#include "coulomb.h"
#include "normal.h"
#include "rolling.h"

#define HARDCONTACT_LAWS_WITH(X, ...)           \
  X(NormalLaw, Normal, , __VA_ARGS__)           \
  X(CoulombLaw, Coulomb, Friction, __VA_ARGS__) \
  X(RollingLaw, Rolling, Rolling, __VA_ARGS__)

#define HARDCONTACT_DETAIL_ENUMERATOR(Law, Enumerator, Suffix, unused) Enumerator,
#define HARDCONTACT_DETAIL_COUNT(Law, Enumerator, Suffix, unused) +1
#define HARDCONTACT_DETAIL_BLOCK(Law, Enumerator, Suffix, unused) \
  case ContactLaw::Enumerator: return Law::block;
#define HARDCONTACT_DETAIL_HISTORY(Law, Enumerator, Suffix, unused) \
  case ContactLaw::Enumerator: return Law::history;
#define HARDCONTACT_DETAIL_ALIAS(Law, Enumerator, Suffix, Family, Template) \
  using Family##Suffix = Template<Law>;
#define HARDCONTACT_DETAIL_INSTANTIATE(Law, Enumerator, Suffix, Template) template class Template<Law>;

#define HARDCONTACT_DETAIL_WITH_LAW(Law, Enumerator, Suffix, unused) \
  case ContactLaw::Enumerator: return f(Law{});

// using <Family><Suffix> = <Template><Law>; for every law (in a solver's header).
#define HARDCONTACT_SOLVER_ALIASES(Family, Template) \
  HARDCONTACT_LAWS_WITH(HARDCONTACT_DETAIL_ALIAS, Family, Template)
// template class <Template><Law>; for every law (in the .cpp that defines Template's members).
#define HARDCONTACT_INSTANTIATE_FOR_LAWS(Template) \
  HARDCONTACT_LAWS_WITH(HARDCONTACT_DETAIL_INSTANTIATE, Template)

namespace hardcontact {

// The law of every row: the paper's (laws/normal.h, 1 multiplier per row), Coulomb friction
// (laws/coulomb.h, mu[3 c..] = normal, tangent1, tangent2) or with rolling resistance too
// (laws/rolling.h, 5 per row: then rolling1, rolling2).
enum class ContactLaw { HARDCONTACT_LAWS_WITH(HARDCONTACT_DETAIL_ENUMERATOR, ~) };

constexpr int kContactLaws = 0 HARDCONTACT_LAWS_WITH(HARDCONTACT_DETAIL_COUNT, ~);

// Multipliers per contact of a law (its block): the solvers' unknowns per row.
constexpr int law_block(ContactLaw law)
{
  switch (law) {
    HARDCONTACT_LAWS_WITH(HARDCONTACT_DETAIL_BLOCK, ~)
  }
  return NormalLaw::block;
}

// f(Law{}) for the law named at run time (a generic lambda sees the law's type).
template <class F>
decltype(auto) with_law(ContactLaw law, F &&f)
{
  switch (law) {
    HARDCONTACT_LAWS_WITH(HARDCONTACT_DETAIL_WITH_LAW, ~)
  }
  return f(NormalLaw{});
}

// Values a contact keeps between steps under a law (the contact history, per contact).
constexpr int law_history(ContactLaw law)
{
  switch (law) {
    HARDCONTACT_LAWS_WITH(HARDCONTACT_DETAIL_HISTORY, ~)
  }
  return NormalLaw::history;
}

}    // namespace hardcontact
