// One interface for every algorithm that projects u_free onto K_h (eq. 14-15). The scheme does
// not depend on the solver (section 3.3): any exact solver gives the same u^{n+1}.
#pragma once

#include "contact_problem.h"
#include "distributed_ops.h"
#include "container_bytes.h"
#include "laws/law_list.h"    // ContactLaw

#include <memory>
#include <string>
#include <vector>

namespace hardcontact {

struct SolverSettings {
  double tol = 1.0e-4;    // stop when residual() <= tol (relative to each row's scale, residual.h)
  int maxiter = 10000;    // cap on multiplier updates per solve
  double rho = 0.0;       // Uzawa step; 0 = 1 / the Gershgorin bound each solve (dual_operator.h)
  // cg: how many past corrections (answer - warm start) span the subspace its start is
  // improved in (projected_cg.h); 0 = the warm start as it is.
  int subspace = 0;
  // Friction: how a solve treats De Saxce's shift of the normal target (laws/disc_law.h), the
  // one thing that makes Coulomb's law nonconvex (iterative_solver.h, where each is measured):
  //   Lagged (the default): a contact that pushed at the warm start may keep its shift there
  //     where Coulomb's is higher by at most 3 tol of its row scale (iterative_solver.h,
  //     kLagAllowance): Coulomb's law wherever a contact slides no faster than the warm start
  //     predicted (a steady slide, a slide slowing down, every sticking contact), and elsewhere
  //     a lift-off of at most 3 tol of the row scale. Never an overlap.
  //   Exact: the shifts are brought to their fixed point in every solve: Coulomb's law itself.
  //   Convex: no shift, Anitescu and Tasora's convex relaxation (the cone complementarity
  //     problem): a sliding contact lifts off at mu |slip| in every step.
  enum class Cone { Lagged, Exact, Convex };
  Cone cone = Cone::Lagged;
  // Friction: the slip conditions of the stopping test are measured against h max(V, V_t), V_t
  // the fastest motion of the contact points, slides included; the gap conditions keep h V, V
  // the fastest approach (residual.h, contact_speed_scale). Unset: h V for both (the fix sets it
  // by default with friction: src/lammps/keywords.h). The host passes it on in
  // ContactProblem::contact_speed_scale.
  bool contact_speed = false;
  // Developers: when set, an iterative solver of the frictionless law writes the problem it
  // receives to this file before it starts (problem_dump.h); empty = nothing written.
  std::string dump_problem;
};

struct SolveReport {
  int iterations = 0;    // multiplier updates done
  double residual = 0.0;
  bool converged = false;
  double rho = 0.0;    // step actually used (0 if the solver has none)
  double speed_scale = 0.0;    // V of the row scales (residual.h)
  bool dump_failed = false;    // SolverSettings::dump_problem could not be written
};

// What a solver needs from the host, asked of the object instead of compared by name.
struct SolverTraits {
  bool distributed = true;        // runs with bodies spread over processes (DistributedOps)
  bool needs_owner_map = false;   // needs ContactProblem::owner (assembles the operator)
  // stops at the tolerance: a solve it does not finish goes on from its multipliers (the
  // host's kept overlaps, kept_overlaps.h, rely on that); false for the reference solver
  bool iterative = true;
};

class Solver {
 public:
  virtual ~Solver() = default;
  virtual SolverTraits traits() const { return {}; }
  // Bytes the solver keeps between solves (its per-row and per-body scratch), for the fix's
  // memory_usage() (LAMMPS's per-rank memory line).
  virtual double memory_usage() const { return 0.0; }
  // mu: multipliers (contact forces, eq. 16), in: start values (resized to the rows, missing
  // ones 0), out: result. u: out, velocities of all bodies, ghosts included.
  virtual SolveReport solve(const ContactProblem &p, const SolverSettings &s,
                            DistributedOps &ops, std::vector<double> &mu,
                            std::vector<Vec3> &u) = 0;
  // What a solver carries from one solve to the next besides the multipliers (the host's
  // warm start), for restart files, so that a split run solves as the unsplit one:
  // kStateSize doubles (unused ones 0; a solver with nothing to carry ignores them).
  static constexpr int kStateSize = 2;
  virtual void save_state(double *state) const
  {
    for (int k = 0; k < kStateSize; ++k) state[k] = 0.0;
  }
  virtual void load_state(const double *) {}
};

// nullptr for an unknown name, or for a solver without the law.
std::unique_ptr<Solver> make_solver(const std::string &name,
                                    ContactLaw law = ContactLaw::Normal);
bool solver_has_friction(const std::string &name);
// The names make_solver knows, for error messages and docs.
std::vector<std::string> solver_names();

}    // namespace hardcontact
