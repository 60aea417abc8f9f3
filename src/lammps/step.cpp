// At initial_integrate of step n+1, LAMMPS holds q^n (x, ghosts current), u^n (v) and f(q^n)
// (computed in step n or in setup), and the neighbour list of the last build. This is exactly
// the data of eq. 14-19, so the whole step happens there: u_free, projection onto K_h(q^n),
// then q^{n+1} = q^n + h u^{n+1}.
#include "step.h"

#include "keywords.h"
#include "sources/row_sink.h"
#include "lammps_ops.h"
#include "lammps_compat.h"
#include "../core/targets.h"

#include "../core/residual.h"

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "neighbor.h"
#include "update.h"

#include <cfloat>
#include <cmath>

using namespace LAMMPS_NS;

namespace hardcontact {
namespace {
const int MAX_ROUNDS = 1000;    // a safety net: each round adds rows, and there are finitely many
}    // namespace

ContactStep::ContactStep(LAMMPS *lmp, int groupbit, DistributedOps &ops,
                         const NeighborReach &reach, std::vector<const ContactSource *> sources) :
    Pointers(lmp), groupbit_(groupbit), ops_(ops), reach_(reach), sources_(std::move(sources))
{
}

StepResult ContactStep::solve(Solver &solver, const SolverSettings &settings,
                              ContactHistory *history, bool moving_obstacles)
{
  block_ = law_block(law_.law);
  const Bodies bodies = build_bodies(solver.traits().needs_owner_map, law_.friction != nullptr);
  RowSink sink(problem_, atom->tag, atom->nlocal, free_speed_);
  sink.set_moving(moving_obstacles);
  sink.begin_candidates(1.0);
  offer_rows(bodies, sink);
  problem_.contact_speed_scale = settings.contact_speed;
  const double speed_scale = free_speed_scale(problem_, ops_);    // V (core/residual.h)
  Targets targets{bodies.recovery_speed, speed_scale, settings.tol};
  // Frictionless rows that pushed keep shallow overlaps while solves stay within a budget
  // (core/kept_overlaps.h); the paper's clearing without a warm start or with friction, and
  // for the reference solver
  const bool may_keep = history && block_ == 1 && solver.traits().iterative &&
                        settings.maxiter >= KeptOverlaps::kBudgetDivisor;
  const bool keep = may_keep && kept_.begin_step();
  if (keep) {
    targets.kept_overlaps = &kept_;
    targets.warm = &mu_;
    targets.block = block_;
  }
  // The effects' terms on u_free (cohesion: core/cohesion.h), before any row is targeted.
  // The first round's solves take this V (the same rows and u_free, one reduction fewer)
  // unless an effect moved u_free since; a later round's new rows may too (below).
  EffectStep effect_step{lmp, problem_, ops_, settings.tol};
  bool moved_free = false;
  for (Effect *e : effects_) moved_free = e->begin_step(effect_step) || moved_free;
  problem_.speed_scale = moved_free ? -1.0 : speed_scale;
  // the targets of rows first..: the common terms, then each effect's
  auto target_rows = [&](int first) {
    targets.apply(problem_, first);
    for (Effect *e : effects_) e->target_rows(effect_step, first);
  };
  int targeted = 0;    // rows before it have their targets (and friction, its frames)
  auto prepare_rows = [&]() {
    if (law_.friction) {    // the law's coefficients per row, as the effects read theirs
      effect_step.pair_values(*law_.friction, targeted, problem_.friction);
      if (law_.wall_friction && !law_.wall_friction->empty())
        wall_values_of_rows(*law_.wall_friction, targeted, problem_.friction);
      for (int r = 0; r < kResistances; ++r)
        if (law_.resistance[r])
          effect_step.pair_values(*law_.resistance[r], targeted, problem_.resistance[r]);
      problem_.complete_frames(targeted);
    }
    // Warm start: each row starts from the multiplier its pair had at the last step, if any
    // (after the frames, which its tangential parts are projected on; before the targets,
    // which read who pushed). Rows of later rounds start from 0.
    if (targeted == 0) {
      if (history) history->load(problem_, atom->tag, mu_);
      else mu_.assign(static_cast<size_t>(block_) * problem_.n_contacts(), 0.0);
    }
    target_rows(targeted);
    targeted = problem_.n_contacts();
  };
  prepare_rows();
  // A budget only where some process kept an overlap: a step without any (a cold start, a
  // scene in flight) is solved exactly as with the paper's targets. Later rounds add rows
  // that did not push: they keep nothing.
  bool budgeted = keep && ops_.sum_all(static_cast<double>(kept_.rows_raised())) > 0.0;
  const bool cleared_from_start = may_keep && !budgeted;

  StepResult result;
  for (;;) {
    if (targeted < problem_.n_contacts()) prepare_rows();
    // a later round has new rows on some process: its solves find V again (all processes
    // alike: a reduction)
    if (result.rounds > 0) problem_.speed_scale = -1.0;
    if (budgeted) {
      // a solve with kept overlaps within its budget; stopped there, it goes on from its
      // multipliers with the paper's targets and the rest of maxiter (kept_overlaps.h)
      SolverSettings within = settings;
      within.maxiter = kept_.budget(settings.maxiter);
      result.report = solver.solve(problem_, within, ops_, mu_, u_);
      if (!result.report.converged) {
        kept_.undo();
        target_rows(0);      // every row's target from its gap again: the paper's
        budgeted = false;    // undo() ended the keeping: later rounds' rows clear
        ++result.kept_undone;
        const int spent = result.report.iterations;
        SolverSettings rest = settings;
        rest.maxiter = settings.maxiter - within.maxiter;
        result.report = solver.solve(problem_, rest, ops_, mu_, u_);
        result.report.iterations += spent;    // the round's report covers both solves
      }
    } else {
      result.report = solver.solve(problem_, settings, ops_, mu_, u_);    // from the mu so far
    }
    result.iterations += result.report.iterations;
    ++result.rounds;
    // An unconverged solve is not refined further: its violations are reported, not chased.
    if (!result.report.converged) break;
    sink.begin_missed(u_, result.report.speed_scale, settings.tol, speed_);
    offer_rows(bodies, sink);
    if (ops_.sum_all(sink.added()) == 0.0) break;
    if (result.rounds == MAX_ROUNDS) {
      result.report.converged = false;
      mu_.resize(static_cast<size_t>(block_) * problem_.n_contacts(), 0.0);    // not solved
      break;
    }
  }
  // what clearing costs now sets the next budgets (kept_overlaps.h)
  if (cleared_from_start) kept_.cleared(result.iterations);
  if (history) history->store(problem_, atom->tag, mu_);    // mu': the solver's variable
  reported_ = nullptr;
  for (Effect *e : effects_)
    if (const std::vector<double> *f = e->reported_forces(problem_, mu_, block_)) reported_ = f;
  // The kinetic energy the solve may add (residual.h, energy_within_bound): the work of the
  // forces clearing overlaps present at q^n, sum mu max(0, -D) over the rows; this
  // process's part (the outputs sum it with their own figures, in one reduction).
  result.clearing_work = clearing_work(problem_, mu_, block_);
  return result;
}

void ContactStep::find_overlaps(const Solver &solver)
{
  const Bodies bodies = build_bodies(solver.traits().needs_owner_map, false);
  RowSink sink(problem_, atom->tag, atom->nlocal, free_speed_);
  sink.begin_candidates(0.0);
  offer_rows(bodies, sink);
}

void ContactStep::clear()
{
  mu_.clear();
  problem_.clear_contacts();
}

double ContactStep::memory_usage() const
{
  double bytes = (sizeof(int) * 2 + sizeof(double) * 7) * problem_.body_i.capacity();
  bytes += sizeof(double) * 7 * problem_.inv_mass.capacity();
  return bytes;
}

void ContactStep::wall_values_of_rows(const std::vector<double> &by_wall, int first,
                                      std::vector<double> &out)
{
  const int nc = problem_.n_contacts();
  for (int c = first; c < nc; ++c) {
    const int j = problem_.body_j[c];
    if (!is_wall(j)) continue;
    const double v = by_wall[wall_index(j)];
    if (FixOptions::own_friction(v)) out[c] = v;
  }
}

void ContactStep::offer_rows(const Bodies &bodies, RowSink &sink) const
{
  for (const ContactSource *source : sources_) source->visit(bodies, sink);
}

// Radius and mass must be usable, and no value may be NaN or infinite: a NaN would spread to
// every body through the solve.
void ContactStep::check_bodies(const std::vector<PlaneWall> &walls) const
{
  double **x = atom->x, **v = atom->v;
  double *radius = atom->radius, *rmass = atom->rmass;
  int *mask = atom->mask;
  tagint bad[3] = {0, 0, 0};    // non-finite, non-positive radius/mass, behind a wall
  for (int i = 0; i < atom->nlocal; ++i) {
    if (!(mask[i] & groupbit_)) continue;
    bool finite = std::isfinite(radius[i]) && std::isfinite(rmass[i]);
    for (int k = 0; k < 3; ++k) finite = finite && std::isfinite(x[i][k]) && std::isfinite(v[i][k]);
    if (!finite && !bad[0]) bad[0] = atom->tag[i];
    if ((radius[i] <= 0.0 || rmass[i] <= 0.0) && !bad[1]) bad[1] = atom->tag[i];
    for (const auto &w : walls)
      if (w.gap(x[i], radius[i]) < -radius[i] && !bad[2]) bad[2] = atom->tag[i];
  }
  tagint all[3];
  MPI_Allreduce(bad, all, 3, MPI_LMP_TAGINT, MPI_MAX, world);
  if (all[0])
    compat::error_all(error, FLERR,
                      "Fix hardcontact: atom {} has a non-finite position, velocity, radius or "
                      "mass: fix the data file or the commands that set it",
                      all[0]);
  if (all[1])
    compat::error_all(error, FLERR,
                      "Fix hardcontact: atom {} has radius or mass <= 0: every atom of the "
                      "group needs a positive diameter and density (set diameter / set density)",
                      all[1]);
  if (all[2])
    compat::error_all(error, FLERR,
                      "Fix hardcontact: the centre of atom {} is behind a wall: move the wall "
                      "or the atom",
                      all[2]);
}

// Eq. 14: u_free = u^n + h M^-1 f^{n+1}, f evaluated at q^n (LAMMPS's forces of this state).
// Atoms outside the group are obstacles: contacts do not change their velocity (inv_mass 0).
Bodies ContactStep::build_bodies(bool needs_owner_map, bool rotates)
{
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  double **v = atom->v, **f = atom->f;
  double *rmass = atom->rmass;
  int *mask = atom->mask;
  const double dtfm = update->dt * force->ftm2v;

  problem_.h = update->dt;
  problem_.n_owned = nlocal;
  // a new neighbour list may have sorted or exchanged the atoms: local indices changed
  problem_.renumbered = neighbor->ago == 0;
  problem_.inv_mass.resize(nall);
  // the velocities, then with friction the spins (ContactProblem::u_free)
  problem_.u_free.resize(rotates ? 2 * static_cast<size_t>(nall) : nall);
  for (int i = 0; i < nall; ++i)
    problem_.inv_mass[i] = (mask[i] & groupbit_) ? force->ftm2v / rmass[i] : 0.0;

  // One reduction (MAX) for what the step needs of all processes here: the first atom with a
  // non-finite free velocity (its ID as a double: exact below 2^53), the largest velocity
  // change from the forces, the largest radius, and the largest free speed (the gap's
  // round-off, below). A NaN speed would poison the maximum: it is taken over finite ones.
  enum { kBad, kKick, kRadius, kSpeed, kValues };
  double local[kValues] = {0.0, 0.0, 0.0, 0.0};
  for (int i = 0; i < nlocal; ++i) {
    Vec3 u(v[i]);
    if (mask[i] & groupbit_) {
      const Vec3 kick = (dtfm / rmass[i]) * Vec3(f[i]);
      u += kick;
      local[kKick] = MAX(local[kKick], kick.norm());
      local[kRadius] = MAX(local[kRadius], atom->radius[i]);
    }
    if (!u.allFinite()) {
      if (local[kBad] == 0.0) local[kBad] = static_cast<double>(atom->tag[i]);
    } else {
      local[kSpeed] = MAX(local[kSpeed], u.norm());
    }
    problem_.u_free[i] = u;
  }
  double global[kValues];
  MPI_Allreduce(local, global, kValues, MPI_DOUBLE, MPI_MAX, world);
  if (global[kBad] != 0.0)
    compat::error_all(error, FLERR,
                      "Fix hardcontact: atom {} has a non-finite velocity or force at step {}: "
                      "check the forces acting on it",
                      static_cast<tagint>(global[kBad]), update->ntimestep);
  reach_.check_radius(global[kRadius]);

  // Friction: the bodies rotate. omega^n + h I^-1 torque, as fix nve/sphere would (its full
  // step); obstacles (outside the group) have 1/I = 0.
  if (rotates) {
    problem_.inv_inertia.resize(nall);
    problem_.radius.assign(atom->radius, atom->radius + nall);
    double **omega = atom->omega, **torque = atom->torque;
    for (int i = 0; i < nall; ++i) {
      const double inertia = law_.inertia * rmass[i] * atom->radius[i] * atom->radius[i];
      problem_.inv_inertia[i] = (mask[i] & groupbit_) ? force->ftm2v / inertia : 0.0;
    }
    for (int i = 0; i < nlocal; ++i) {
      Vec3 w(omega[i]);
      if (mask[i] & groupbit_) w += (update->dt * problem_.inv_inertia[i]) * Vec3(torque[i]);
      problem_.u_free[nall + i] = w;
    }
  } else {
    problem_.inv_inertia.clear();
    problem_.radius.clear();
  }
  // the ghosts' velocities and spins, in one exchange
  ops_.forward(doubles(problem_.u_free), kDoublesPerVec3, rotates ? 2 : 1,
               static_cast<long>(kDoublesPerVec3) * nall);

  // The owners' coordinates on the ghosts, unshifted: a pair across a periodic boundary is
  // then measured as (x_j - x_i) + k L on both processes holding it (PairSource).
  x_owner_.resize(nall);
  for (int i = 0; i < nlocal; ++i) x_owner_[i] = Vec3(atom->x[i]);
  ops_.forward(doubles(x_owner_), kDoublesPerVec3);

  // Round-off of a predicted gap: coordinates of size X carry errors of eps X, and h u of
  // eps h |u|. The solvers never ask for less (core/residual.h).
  double extent = 0.0;
  for (int d = 0; d < 3; ++d)
    extent = MAX(extent, MAX(fabs(domain->boxlo[d]), fabs(domain->boxhi[d])));
  problem_.gap_roundoff = 16.0 * DBL_EPSILON * (extent + problem_.h * global[kSpeed]);

  // The exact solver assembles the operator: on one process, ghosts are periodic images.
  problem_.owner.clear();
  if (needs_owner_map) {
    owner_index_.clear();
    for (int i = 0; i < nlocal; ++i) owner_index_[atom->tag[i]] = i;
    problem_.owner.resize(nall);
    for (int i = 0; i < nall; ++i) {
      const auto it = owner_index_.find(atom->tag[i]);
      problem_.owner[i] = it == owner_index_.end() ? -1 : it->second;
    }
  }
  return {problem_.u_free, x_owner_, global[kKick]};
}

}    // namespace hardcontact
