// Sphere pairs from the fix's neighbour list: a half list of owned/ghost pairs closer than
// r_i + r_j + skin, cross-processor pairs on both processors (newton off).
#pragma once

#include "contact_source.h"

#include "lmptype.h"

namespace LAMMPS_NS {
class LAMMPS;
class NeighList;
}

namespace hardcontact {

class PairSource : public ContactSource {
 public:
  PairSource(LAMMPS_NS::LAMMPS *lmp, int groupbit) : lmp_(lmp), groupbit_(groupbit) {}
  void set_list(LAMMPS_NS::NeighList *list) { list_ = list; }
  void visit(const Bodies &bodies, RowSink &sink) const override;

 private:
  Vec3 pair_vector(int i, int j, const std::vector<Vec3> &x_owner) const;
  Vec3 coincident_normal(int i, int j, const std::vector<Vec3> &u_free) const;

  LAMMPS_NS::LAMMPS *lmp_;
  int groupbit_;
  LAMMPS_NS::NeighList *list_ = nullptr;
};

}    // namespace hardcontact
