// What the fix reports (doc/fix_hardcontact.md, "Restart, fix_modify, output ..."): the global
// vector f_ID[1..NVECTOR], the per-atom array (contacts, contact force) and the local array
// (one row per active contact).
#pragma once

#include "sources/contact_source.h"

#include "step.h"

#include "../core/laws/law_list.h"
#include "../core/plane_wall.h"

#include "pointers.h"

namespace LAMMPS_NS {
class Fix;
}

namespace hardcontact {

class Outputs : protected LAMMPS_NS::Pointers {
 public:
  // global vector, see compute_vector()
  enum { ITERATIONS, MAX_OVERLAP, CANDIDATES, ACTIVE, RESIDUAL, MAXITER_HITS,
         MAX_OVERLAP_RELATIVE, RHO, ROUNDS, CLEARING_WORK, FRICTION_WORK, KEPT_UNDONE, NVECTOR };
  // per atom: number of active contacts, contact force (3); with friction also the contact
  // torque (3)
  static constexpr int kPerAtomColumns = 4;
  // local: atom ID i, atom ID j (0 for a wall), normal force, normal (3), wall number (0 for
  // a pair); with friction also the tangential force on j (3, box frame) and 1 if the
  // contact slides (on Coulomb's cone), 0 if it sticks
  static constexpr int kLocalColumns = 7;
  static constexpr int kFrictionColumns = 4;

  // fix: its array_atom, array_local and size_local_rows are written here.
  Outputs(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::Fix *fix, bool friction) :
      Pointers(lmp), fix_(fix), friction_(friction)
  {
  }
  int per_atom_columns() const { return kPerAtomColumns + (friction_ ? 3 : 0); }
  int local_columns() const { return kLocalColumns + (friction_ ? kFrictionColumns : 0); }
  ~Outputs() override;
  Outputs(const Outputs &) = delete;
  Outputs &operator=(const Outputs &) = delete;

  // Which active contacts the local array lists (fix_modify ID contacts pairs|walls|all): pair
  // rows alone load as bonds in OVITO, which has no atom 0 for a wall row's j.
  enum class LocalRows { ALL, PAIRS, WALLS };
  void set_local_rows(LocalRows rows) { local_rows_ = rows; }

  double vector(int n) const { return diag_[n]; }
  double memory_usage() const;
  void grow_per_atom(int nmax);
  void clear_per_atom(int i);

  // Setup: the overlaps the run starts from (a warning beyond tol), every other figure 0.
  void start_of_run(const ContactProblem &p, const WallGaps &walls, double tol);
  // After the solve of a step, before the atoms move: all outputs of the step.
  // mu: block values per row (1, or 3 with friction).
  // Its global figures (rows, active rows, friction's and clearing's work, largest overlaps)
  // take one reduction of ops (sums and maxima at once).
  void record_step(const StepResult &r, const ContactProblem &p, const std::vector<double> &mu,
                   ContactLaw law, const std::vector<Vec3> &u, const WallGaps &walls,
                   const SolverSettings &settings, DistributedOps &ops);
  void end_of_run(const SolverSettings &settings);

 private:
  void record_solve(const StepResult &r, const SolverSettings &settings);
  // this process's largest overlap at q + h u (h = 0: at q), absolute and relative (worst[2])
  void local_overlaps(const ContactProblem &p, const std::vector<Vec3> *u, double h,
                      const WallGaps &walls, double *worst) const;
  // the per-atom and local arrays, and this process's rows, active rows and friction's work
  // (counts[3])
  void per_atom_and_local(const ContactProblem &p, const std::vector<double> &mu, ContactLaw law,
                          const std::vector<Vec3> &u, double *counts);

  LAMMPS_NS::Fix *fix_;
  bool friction_;
  double diag_[NVECTOR] = {};
  LAMMPS_NS::bigint maxiter_hits_ = 0;
  LAMMPS_NS::bigint maxiter_hits_run_ = 0;
  LAMMPS_NS::bigint kept_undone_ = 0;    // solves whose kept overlaps were cleared again
  std::vector<Vec3> force_;     // contact force per owned atom
  std::vector<Vec3> torque_;    // contact torque per owned atom (friction)
  int nlocal_rows_max_ = 0;
  LocalRows local_rows_ = LocalRows::ALL;
  bool listed(int j) const
  {
    return local_rows_ == LocalRows::ALL || (local_rows_ == LocalRows::WALLS) == is_wall(j);
  }
};

}    // namespace hardcontact
