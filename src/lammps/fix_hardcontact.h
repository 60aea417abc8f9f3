// fix hardcontact: B. Maury's time-stepping scheme for inelastic collisions (Numer. Math. 2006)
// as the time integrator of a group of finite-size spheres. See doc/fix_hardcontact.md.
#pragma once

#include "fix.h"

#include "../core/contact_problem.h"
#include "../core/plane_wall.h"
#include "../core/solver.h"
#include "lammps_ops.h"
#include "warm_start_store.h"

#include <memory>
#include <vector>

namespace LAMMPS_NS {

class FixHardContact : public Fix {
 public:
  FixHardContact(class LAMMPS *, int, char **);
  ~FixHardContact() override;
  int setmask() override;
  void init() override;
  void init_list(int, class NeighList *) override;
  void setup(int) override;
  void setup_post_neighbor() override;
  void post_neighbor() override;
  void initial_integrate(int) override;
  void post_run() override;

  double compute_vector(int) override;
  double memory_usage() override;

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;

 private:
  // keywords (parsed in one place: parse_keywords)
  std::string solver_name_;
  hardcontact::SolverSettings settings_;
  std::vector<hardcontact::PlaneWall> walls_;
  bool warmstart_ = true;
  hardcontact::WarmStartStore warm_;

  std::unique_ptr<hardcontact::Solver> solver_;
  hardcontact::LammpsOps ops_;
  class NeighList *list_ = nullptr;

  hardcontact::ContactProblem problem_;
  std::vector<double> mu_;
  std::vector<hardcontact::Vec3> u_;

  std::vector<hardcontact::Vec3> xhold_;    // owned positions at the last list build
  double cutoff_ = 0.0;                     // 2 r_max + skin, reach of list and ghosts
  double rmax_ = 0.0;
  double user_cutghost_ = -1.0;
  bool binsize_set_here_ = false;
  bool sortbin_set_here_ = false;

  // global vector output, see compute_vector()
  enum { ITERATIONS, MAX_OVERLAP, CANDIDATES, ACTIVE, RESIDUAL, MAXITER_HITS,
         MAX_OVERLAP_RELATIVE, RHO, ROUNDS, CLEARING_WORK, NVECTOR };
  double diag_[NVECTOR] = {};
  bigint maxiter_hits_ = 0;
  bigint maxiter_hits_run_ = 0;
  double recovery_speed_ = 0.0;      // overlap policy, see apply_overlap_policy()
  double speed_scale_ = 0.0;         // V of the candidate rows (core/residual.h)
  double last_speed_scale_ = 0.0;    // V the last solve used
  std::vector<hardcontact::Vec3> xowner_;    // owners' coordinates, unshifted on ghosts
  std::vector<hardcontact::Vec3> force_;    // contact force per owned atom
  int nmax_ = 0;
  int nlocal_rows_max_ = 0;

  void parse_keywords(int narg, char **arg);
  void check_walls_in_box();
  void check_atoms();
  void radius_grew(double rmax_now);    // stops with an error
  void store_xhold();
  void build_bodies();
  void build_candidates(double scale);
  bool add_missed_rows();
  void add_row(int i, int j, const hardcontact::Vec3 &n, double d, double size);
  template <class F> void visit_pairs(F &&f);
  hardcontact::Vec3 coincident_normal(int i, int j) const;
  hardcontact::Vec3 pair_vector(int i, int j, double **x) const;
  void apply_overlap_policy(int first_row);
  template <class F> void visit_walls(F &&f);
  void solve();
  void move_and_check();
  void overlap_diagnostics(double h);
  void fill_outputs();
  void remember_multipliers();
  bool counted_here(int c) const;
  double partner_key(int c) const;
};

}    // namespace LAMMPS_NS
