// fix hardcontact: B. Maury's time-stepping scheme for inelastic collisions (Numer. Math. 2006)
// as the time integrator of a group of finite-size spheres. See doc/fix_hardcontact.md and,
// for where each part lives, doc/architecture.md. This class holds the LAMMPS callbacks only.
#pragma once

#include "fix.h"

#include "contact_history.h"
#include "contact_virial.h"
#include "deck_checks.h"
#include "integrate.h"
#include "keywords.h"
#include "lammps_compat.h"
#include "lammps_ops.h"
#include "neighbor_reach.h"
#include "outputs.h"
#include "sources/mesh_wall_source.h"
#include "sources/pair_source.h"
#include "sources/obstacles.h"
#include "sources/plane_wall_source.h"
#include "sources/wall_kinds.h"
#include "step.h"

#include <memory>

namespace LAMMPS_NS {

class FixHardContact : public Fix {
 public:
  FixHardContact(class LAMMPS *, int, char **);
  ~FixHardContact() override;
  int setmask() override;
  void init() override;
  void init_list(int, class NeighList *) override;
  void setup(int) override;
  void setup_post_neighbor() HARDCONTACT_LAMMPS_OVERRIDE;
  void post_neighbor() HARDCONTACT_LAMMPS_OVERRIDE;
  void initial_integrate(int) override;
  void post_force(int) override;
  void post_run() override;

  int modify_param(int, char **) override;
  double compute_vector(int) override;
  double memory_usage() override;

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;
  int pack_forward_comm(int, int *, double *, int, int *) HARDCONTACT_LAMMPS_OVERRIDE;
  void unpack_forward_comm(int, int, double *) HARDCONTACT_LAMMPS_OVERRIDE;

 protected:
  // how far the neighbour list and ghosts reach (2 r_max + skin): the LIGGGHTS fix sizes the
  // stencil with it (src/liggghts/fix_hardcontact_liggghts.h)
  double reach_cutoff() const { return reach_.cutoff(); }
  // values per atom of the forward communication in progress (LIGGGHTS's pack_comm returns it)
  int forward_values_per_atom() const { return ops_.values_per_atom(); }
  // Appends a source of walls (a host's own obstacles) to the list after the planes, regions
  // and meshes of the keywords: its walls take the next wall codes at each init, its rows
  // are offered every pass, its hooks are called every step (sources/contact_source.h).
  // Call it from the constructor; the source must outlive the fix.
  void add_wall_source(hardcontact::WallSource *source);

 private:
  hardcontact::FixOptions options_;    // the keywords (keywords.h)
  hardcontact::ContactLaw law_;        // the law they ask for, found once
  std::unique_ptr<hardcontact::Solver> solver_;
  hardcontact::LammpsOps ops_;
  hardcontact::NeighborReach reach_;
  hardcontact::PairSource pairs_;
  hardcontact::PlaneWallSource walls_;
  // walls of the kinds' table (sources/wall_kinds.cpp: region surfaces, ...), one source per
  // kind on the fix line
  std::vector<std::unique_ptr<hardcontact::WallSource>> kind_sources_;
  hardcontact::MeshWallSource meshes_;
  // the wall sources, in the order their wall codes follow: walls_, kind_sources_, meshes_,
  // then any added (add_wall_source)
  hardcontact::Obstacles obstacles_;
  hardcontact::ContactHistory history_;
  hardcontact::ContactStep step_;
  hardcontact::Integrate integrate_;
  hardcontact::Outputs outputs_;
  hardcontact::ContactVirial virial_;
  hardcontact::DeckChecks deck_checks_;    // the rest of the deck (deck_checks.h)
  // by wall index: a wall's own friction (wall ... friction mu), negative for the type's;
  // empty when no wall has its own (Obstacles::init)
  std::vector<double> wall_friction_;
  // HARDCONTACT_DUMP_PROBLEMS: developers' file prefix for every step's problem
  // (core/problem_dump.h), empty when unset
  std::string dump_prefix_;
  // HARDCONTACT_COMM_TIMES: developers' report of the solver's communication at the end of
  // each run (post_run)
  bool report_comm_ = false;
  void report_comm_times();

  void history_resized();
  // LAMMPS's v_init on every host: the virial is computed on this step (vflag_global,
  // vflag_atom) only if a compute asked for it and fix_modify virial is on
  void start_virial(int vflag);
  hardcontact::StepResult solve_and_dump(bool moving_obstacles);
};

}    // namespace LAMMPS_NS
