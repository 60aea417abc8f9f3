// The virial of the contact forces (doc/fix_hardcontact.md, "Pressure and stress"): what the
// step's contact forces add to LAMMPS's pressure (compute pressure, thermo press) and to the
// per-atom stress (compute stress/atom), as a constraint fix's virial does (fix shake, fix
// rigid). Computed only on the steps a pressure or stress is asked for.
//
// Row c (force f_c = mu_0 n + mu_1 t1 + mu_2 t2 on j, -f_c on i, eq. 16 divided by h) adds
//   pair:  (x_j - x_i) (x) f_c,       half to each of i and j (a pair across processes: each
//          process holds the row and gives half to its own atom, LAMMPS's newton-off tally);
//   wall:  (p_c - x_i) (x) f_c = (r_i + D_c) n (x) f_c, all to i, p_c the contact point on the
//          wall: a wall is outside the system, so its lever ends on its surface, as LAMMPS's
//          fix wall tallies it. At rest the sum is then sum_walls p (x) F_wall plus the body
//          forces' moment: in a box, the pressure on a face is the face's force over its area.
// Components in LAMMPS's order xx, yy, zz, xy, xz, yz (v[3] = dx f_y, as the pair styles).
// Rolling torques are couples: no virial.
#pragma once

#include "sources/contact_source.h"

#include "../core/contact_problem.h"

#include "pointers.h"

#include <vector>

namespace hardcontact {

class ContactVirial : protected LAMMPS_NS::Pointers {
 public:
  static constexpr int kComponents = 6;

  explicit ContactVirial(LAMMPS_NS::LAMMPS *lmp) : Pointers(lmp) {}
  ~ContactVirial() override;
  ContactVirial(const ContactVirial &) = delete;
  ContactVirial &operator=(const ContactVirial &) = delete;

  // The step's rows, with levers at q^{n+1} = q + h u (the positions the step's output
  // reports; atom->x still holds q^n) and the walls at t^{n+1}: this process's share of the
  // global virial into global[6] (null: not asked), and the per-atom virial of the owned atoms
  // into the per-atom store (per_atom false: not asked). block: mu's values per row (1, 3, 5).
  void tally(const ContactProblem &p, const std::vector<double> &mu, int block,
             const std::vector<Vec3> &u, double h, const WallGaps &walls, double *global,
             bool per_atom);
  // The last tally's global share (zero before the first), for the setup of the next run.
  const double *last_global() const { return last_global_; }
  // Copies the stored per-atom virial of the owned atoms into vatom (zero where none yet).
  void copy_per_atom(double **vatom) const;

  // Per-atom store: it follows atoms through sorting and migration between the step (where it
  // is computed) and the output (where LAMMPS reads the fix's vatom). Allocated on the first
  // step a per-atom virial is asked for; no memory and no exchanged values before.
  bool per_atom_kept() const { return store_ != nullptr; }
  void grow(int nmax);
  void copy(int from, int to);
  void clear(int i);
  int exchange_values() const { return per_atom_kept() ? kComponents : 0; }
  int pack(int i, double *buf) const;
  int unpack(int i, const double *buf);
  double memory_usage() const;

 private:
  double **store_ = nullptr;
  int nmax_ = 0;
  double last_global_[kComponents] = {};
};

}    // namespace hardcontact
