// The contact laws, declared once. Every per-law name the code needs is generated from the list
// below: the ContactLaw enumerators, each solver family's aliases (Apgd, ApgdFriction,
// ApgdRolling), the explicit instantiations of the templates written against a law, the
// solver registry's constructors, the multipliers per contact (law_block), the values the
// contact history keeps (law_history) and the law a scene's coefficients ask for
// (law_composing). A new law is its file in laws/ (law.h: the interface) and a line here; a
// new resistance (a disc beyond Coulomb's, disc_rows.h) is its disc and laws in one file, a
// line in HARDCONTACT_RESISTANCES (which gives it its keyword in the adapter) and its laws'
// lines.
//
// HARDCONTACT_LAWS_WITH(X, ...) expands X(Law, Enumerator, Suffix, ...) once per law, in the
// order of ContactLaw; Suffix names the law in a solver family's alias (empty: the paper's).
// HARDCONTACT_RESISTANCES(X) expands X(Disc) once per resistance, in the order of its index.
#pragma once

#include "coulomb.h"
#include "normal.h"
#include "rolling.h"
#include "twisting.h"

#define HARDCONTACT_LAWS_WITH(X, ...)           \
  X(NormalLaw, Normal, , __VA_ARGS__)           \
  X(CoulombLaw, Coulomb, Friction, __VA_ARGS__) \
  X(RollingLaw, Rolling, Rolling, __VA_ARGS__)       \
  X(TwistingLaw, Twisting, Twisting, __VA_ARGS__)    \
  X(RollingTwistingLaw, RollingTwisting, RollingTwisting, __VA_ARGS__)

#define HARDCONTACT_RESISTANCES(X) X(RollingDisc) X(TwistingDisc)

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
#define HARDCONTACT_DETAIL_COVERS(Law, Enumerator, Suffix, unused)                  \
  if (Law::frictional == frictional && (Law::resistances & resistances) == resistances && \
      (!found || detail::bits(Law::resistances) < detail::bits(best))) {            \
    law = ContactLaw::Enumerator;                                                   \
    best = Law::resistances;                                                        \
    found = true;                                                                   \
  }
#define HARDCONTACT_DETAIL_RESISTANCE_KEYWORD(Disc) Disc::keyword,
#define HARDCONTACT_DETAIL_RESISTANCE_INDEX(Disc) Disc::index,

// using <Family><Suffix> = <Template><Law>; for every law (in a solver's header).
#define HARDCONTACT_SOLVER_ALIASES(Family, Template) \
  HARDCONTACT_LAWS_WITH(HARDCONTACT_DETAIL_ALIAS, Family, Template)
// template class <Template><Law>; for every law (in the .cpp that defines Template's members).
#define HARDCONTACT_INSTANTIATE_FOR_LAWS(Template) \
  HARDCONTACT_LAWS_WITH(HARDCONTACT_DETAIL_INSTANTIATE, Template)

namespace hardcontact {

// The law of every row: the paper's (laws/normal.h, 1 multiplier per row), Coulomb friction
// (laws/coulomb.h, mu[3 c..] = normal, tangent1, tangent2) or with resistances too, each
// disc's components after (laws/rolling.h: then rolling1, rolling2).
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

// The resistances' keywords (the adapter's `keyword mu [I J]`), at their index.
constexpr const char *kResistanceKeywords[] = {
    HARDCONTACT_RESISTANCES(HARDCONTACT_DETAIL_RESISTANCE_KEYWORD)};
constexpr int kResistancesListed = sizeof(kResistanceKeywords) / sizeof(kResistanceKeywords[0]);
static_assert(kResistancesListed <= kResistances, "raise kResistances (contact_problem.h)");
namespace detail {
constexpr int kListedIndex[] = {HARDCONTACT_RESISTANCES(HARDCONTACT_DETAIL_RESISTANCE_INDEX)};
constexpr bool listed_in_index_order()
{
  for (int r = 0; r < kResistancesListed; ++r)
    if (kListedIndex[r] != r) return false;
  return true;
}
}    // namespace detail
static_assert(detail::listed_in_index_order(),
              "HARDCONTACT_RESISTANCES lists the resistances by index, 0, 1, ...");

namespace detail {
constexpr int bits(unsigned v) { return v == 0 ? 0 : int(v & 1u) + bits(v >> 1); }
}    // namespace detail

// The law of a scene: frictional or not, with the resistances of the mask (bit r: the
// resistance of index r has a positive coefficient somewhere). The law listed that holds
// them with the fewest discs: a disc the scene does not ask for then has coefficient 0 (its
// force vanishes), so a combination without a law of its own is solved, at a disc's cost.
// False when no frictional law holds them all.
inline bool law_composing(bool frictional, unsigned resistances, ContactLaw &law)
{
  bool found = false;
  unsigned best = 0;
  HARDCONTACT_LAWS_WITH(HARDCONTACT_DETAIL_COVERS, ~)
  return found;
}

}    // namespace hardcontact
