// One step of scheme (S) inside LAMMPS's Verlet loop, as one visible sequence:
//   bodies (eq. 14) -> sources (candidate rows, Remark 7) -> targets -> solve rounds
// (each followed by the missed-row check) -> u^{n+1}; the fix then writes outputs and moves
// the atoms (integrate.h). What one stage finds is handed to the next as a value (Bodies,
// Targets, StepResult), never left in a member for a later call to find.
// The vectors here are workspace, kept across steps so that a step allocates nothing.
#pragma once

#include "contact_history.h"
#include "neighbor_reach.h"
#include "effects/effect.h"
#include "sources/contact_source.h"

#include "../core/kept_overlaps.h"
#include "../core/plane_wall.h"
#include "../core/solver.h"

#include "pointers.h"

#include <unordered_map>
#include <vector>

namespace hardcontact {

struct StepResult {
  SolveReport report;           // of the last solve round
  int iterations = 0;           // over all rounds
  int rounds = 0;
  double clearing_work = 0.0;   // this process's part (residual.h; the outputs sum it)
  int kept_undone = 0;          // solves whose kept overlaps were cleared again (0 or 1)
};

// The law of the rows and its coefficients, set once (the fix's keywords); the opt-in effects
// are parts of their own (effects/effect.h), added to the step as they are asked for.
struct StepLaw {
  // Coulomb coefficient per type pair ((ntypes + 1)^2), null for none: the bodies rotate and
  // the solver must be one made for friction (core/laws/coulomb.h). I = inertia m r^2.
  const std::vector<double> *friction = nullptr;
  // a wall's own coefficient by wall index (FixOptions::kByType: the type's), empty when no
  // wall has one (filled at each init: Obstacles::init)
  const std::vector<double> *wall_friction = nullptr;
  double inertia = 0.4;
  // each resistance's coefficient per type pair (rolling, twisting, ... by index:
  // core/laws/law_list.h), null for none (needs friction)
  const std::vector<double> *resistance[kResistances] = {};
  // the law of the rows (FixOptions::contact_law)
  ContactLaw law = ContactLaw::Normal;
};

class ContactStep : protected LAMMPS_NS::Pointers {
 public:
  ContactStep(LAMMPS_NS::LAMMPS *lmp, int groupbit, DistributedOps &ops,
              const NeighborReach &reach, std::vector<const ContactSource *> sources);

  // The law and its coefficients (before the run).
  void set_law(const StepLaw &law) { law_ = law; }
  // One more effect (before the run): its hooks are called every step, in the order added.
  void add_effect(Effect *effect) { effects_.push_back(effect); }
  // u^{n+1} from the state at q^n; history (nullptr: no warm start) gives the start values
  // and keeps the result. moving_obstacles: some wall moves this step (a plane, a region, a
  // mesh...), so rows carry their wall's velocity.
  StepResult solve(Solver &solver, const SolverSettings &settings, ContactHistory *history,
                   bool moving_obstacles);
  // Setup: stops with one collective error naming the first atom with a non-finite or
  // non-positive value, or with its centre behind a wall.
  void check_bodies(const std::vector<PlaneWall> &walls) const;
  // One more source of rows (before the run): its rows are offered in every pass.
  void add_source(const ContactSource *source) { sources_.push_back(source); }
  // Step 0 (setup): only the rows overlapping at q^n, for the diagnostics the run starts from.
  void find_overlaps(const Solver &solver);
  void clear();
  double memory_usage() const;

  const ContactProblem &problem() const { return problem_; }
  // The contact forces of the last step (mu, or mu' - F with cohesion: core/cohesion.h),
  // block() values per row (the law's: 3 with friction, normal, tangent1, tangent2; then each
  // resistance's components).
  const std::vector<double> &mu() const { return reported_ ? *reported_ : mu_; }
  int block() const { return block_; }
  const std::vector<Vec3> &u() const { return u_; }
  // the kept overlaps' back-off and budget (core/kept_overlaps.h), for restart files
  KeptOverlaps &kept_overlaps() { return kept_; }

 private:
  Bodies build_bodies(bool needs_owner_map, bool rotates);
  void offer_rows(const Bodies &bodies, class RowSink &sink) const;
  // by_wall[wall] of the wall rows first.. into out, where it is the wall's own value
  // (FixOptions::own_friction: not kByType)
  void wall_values_of_rows(const std::vector<double> &by_wall, int first,
                           std::vector<double> &out);

  int groupbit_;
  DistributedOps &ops_;
  const NeighborReach &reach_;
  std::vector<const ContactSource *> sources_;
  StepLaw law_;
  std::vector<Effect *> effects_;

  ContactProblem problem_;
  std::vector<double> mu_;
  std::vector<Vec3> u_;
  std::vector<Vec3> x_owner_;
  std::vector<double> free_speed_;    // RowSink's |u_free| per body
  std::vector<double> speed_;         // RowSink's |u| per body after a solve
  // the forces an effect reports instead of the multipliers (cohesion: mu' - F), or null
  const std::vector<double> *reported_ = nullptr;
  int block_ = 1;
  KeptOverlaps kept_;                 // frictionless overlaps kept, and the back-off
  std::unordered_map<LAMMPS_NS::tagint, int> owner_index_;
};

}    // namespace hardcontact
