// The multipliers of the last step, kept per atom so they follow atoms through neighbour
// rebuilds, processor migration, sorting and restart files (warm start of the next solve).
// Atom i keeps (partner, mu) for each of its active contacts: partner = atom ID of the other
// sphere, or -(w+1) for wall w. Both atoms of a pair keep the entry, so each of the two
// processes that hold a pair across processors finds the same start value.
#pragma once

#include "lmptype.h"

namespace LAMMPS_NS {
class Memory;
}

namespace hardcontact {

class WarmStartStore {
 public:
  explicit WarmStartStore(LAMMPS_NS::Memory *memory) : memory_(memory) {}
  ~WarmStartStore();
  WarmStartStore(const WarmStartStore &) = delete;
  WarmStartStore &operator=(const WarmStartStore &) = delete;

  void grow(int nmax);
  void copy(int from, int to);
  void clear(int i) { data_[i][0] = 0.0; }
  void add(int i, double partner, double mu);
  // mu stored for (i, partner), or 0.
  double find(int i, double partner) const;

  // Exchange and restart buffers: count, then (partner, mu) pairs.
  int pack(int i, double *buf) const;
  int unpack(int i, const double *buf);
  int packed_size(int i) const { return 1 + 2 * count(i); }
  int max_packed_size() const { return 1 + 2 * capacity_; }

 private:
  int count(int i) const { return static_cast<int>(data_[i][0]); }
  void reserve(int capacity);

  LAMMPS_NS::Memory *memory_;
  double **data_ = nullptr;    // nmax rows of 1 + 2 capacity_
  int nmax_ = 0;
  int capacity_ = 0;
};

}    // namespace hardcontact
