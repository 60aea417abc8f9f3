// How the members in liggghts_members.h are reached. LIGGGHTS has no plugin mechanism and
// no setter for them; of the ways in, this is the least invasive: C++ does not check access for
// the names used in an explicit template instantiation ([temp.spec.general]/6), so
// instantiating ExposeMember with &Modify::fix_map lets it hand the member pointer to a friend
// function. Each member's type is spelled out: if a LIGGGHTS renames or retypes one, this file
// stops compiling instead of writing to the wrong memory, and no LIGGGHTS header or object
// changes. Rejected: redefining 'private' before including the headers (undefined behaviour,
// and it changes every class they pull in), declaring our own LAMMPS_NS::Info (Modify's friend,
// but the library defines one: two definitions of a class), reading at byte offsets (silent
// corruption on another build), patching or copying LIGGGHTS sources (excluded by design).
// The explicit instantiations must appear once in the program: here, behind plain functions.
#include "liggghts_members.h"

#include "expose_member.h"

#include "atom.h"
#include "modify.h"
#include "neighbor.h"

using namespace LAMMPS_NS;

namespace hardcontact {
namespace liggghts {
namespace {

HARDCONTACT_MEMBER_TAG(FixMap, FixStyles *Modify::*)
HARDCONTACT_MEMBER_TAG(CutNeighMaxSq, double Neighbor::*)
HARDCONTACT_MEMBER_TAG(BinSizeFlag, int Neighbor::*)
HARDCONTACT_MEMBER_TAG(BinSizeUser, double Neighbor::*)
HARDCONTACT_MEMBER_TAG(UserBinSize, double Atom::*)

HARDCONTACT_MEMBER_TAG(ListTimeflag, int *Modify::*)

}    // namespace

template struct ExposeMember<FixMap, &Modify::fix_map>;
template struct ExposeMember<CutNeighMaxSq, &Neighbor::cutneighmaxsq>;
template struct ExposeMember<BinSizeFlag, &Neighbor::binsizeflag>;
template struct ExposeMember<BinSizeUser, &Neighbor::binsize_user>;
template struct ExposeMember<UserBinSize, &Atom::userbinsize>;
template struct ExposeMember<ListTimeflag, &Modify::list_timeflag>;

FixStyles &fix_styles(Modify *modify) { return *(modify->*member(FixMap{})); }
double &stencil_reach_sq(Neighbor *neighbor) { return neighbor->*member(CutNeighMaxSq{}); }
int &bin_size_set(Neighbor *neighbor) { return neighbor->*member(BinSizeFlag{}); }
double &bin_size(Neighbor *neighbor) { return neighbor->*member(BinSizeUser{}); }
double &sort_bin_size(Atom *atom) { return atom->*member(UserBinSize{}); }
int *compute_time_list(Modify *modify) { return modify->*member(ListTimeflag{}); }

}    // namespace liggghts
}    // namespace hardcontact
