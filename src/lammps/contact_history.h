// The contact values of the last step (the multipliers today: warm start of the next solve),
// kept per atom so they follow atoms through neighbour rebuilds, processor migration, sorting
// and restart files. Atom i keeps (partner, k values) for each of its active contacts:
// partner = atom ID of the other sphere, or the row's wall code j < 0 (contact_source.h).
// Both atoms of a pair keep the entry, so each of the two processes that hold a pair across
// processors finds the same values. Per contact the law's block (1: the normal force) is kept
// as k = law_history values, written and read by the law (history_values, from_history): with
// friction the force on the storing atom in the box frame (the partner keeps its negation) and
// each further disc's as a box-frame vector, so that the values survive a new tangent frame or
// a row seen from the other atom (i and j swapped) and are read back in the row's frame.
#pragma once

#include "../core/contact_problem.h"
#include "../core/laws/law_list.h"

#include "lmptype.h"

#include <vector>

namespace LAMMPS_NS {
class Memory;
}

namespace hardcontact {

class ContactHistory {
 public:
  // law: the contact law of the rows, whose multipliers per contact (law_block) are kept as
  // law_history values (laws/law_list.h)
  ContactHistory(LAMMPS_NS::Memory *memory, ContactLaw law) :
      memory_(memory), law_(law), block_(law_block(law)), k_(law_history(law))
  {
  }
  ~ContactHistory();
  ContactHistory(const ContactHistory &) = delete;
  ContactHistory &operator=(const ContactHistory &) = delete;

  int values_per_contact() const { return k_; }

  // Start values of the rows: mu[block c + m] = value m stored for row c's pair, 0 if none
  // (with friction: in the frame normal, tangent1, tangent2 of row c, which must be set).
  void load(const ContactProblem &p, const LAMMPS_NS::tagint *tag,
            std::vector<double> &mu) const;
  // Replaces the owned atoms' entries by the rows with a non-zero first value.
  void store(const ContactProblem &p, const LAMMPS_NS::tagint *tag,
             const std::vector<double> &mu);

  // Per-atom storage (the fix's grow/copy/set_arrays).
  void grow(int nmax);
  void copy(int from, int to);
  void clear(int i) { data_[i][0] = 0.0; }

  // Exchange and restart buffers: count, then (partner, k values) per contact.
  int pack(int i, double *buf) const;
  int unpack(int i, const double *buf);
  int packed_size(int i) const { return 1 + stride() * count(i); }
  int max_packed_size() const { return 1 + stride() * capacity_; }
  // bytes of the per-atom table (nmax rows of 1 + stride() x capacity doubles)
  double memory_usage() const
  {
    const double row = sizeof(double *) + sizeof(double) * (1.0 + stride() * capacity_);
    return nmax_ * row;
  }

 private:
  int stride() const { return 1 + k_; }
  int count(int i) const { return static_cast<int>(data_[i][0]); }
  void reserve(int capacity);
  void add(int i, double partner, const double *values);
  const double *find(int i, double partner) const;

  LAMMPS_NS::Memory *memory_;
  ContactLaw law_;
  int block_;
  int k_;
  double **data_ = nullptr;    // nmax rows of 1 + stride() capacity_
  int nmax_ = 0;
  int capacity_ = 0;
};

}    // namespace hardcontact
