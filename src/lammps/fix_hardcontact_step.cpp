// One step of scheme (S) inside LAMMPS's Verlet loop. At initial_integrate of step n+1, LAMMPS
// holds q^n (x, ghosts current), u^n (v) and f(q^n) (computed in step n or in setup), and the
// neighbour list of the last build. This is exactly the data of eq. 14-19, so the whole step
// happens here: u_free, projection onto K_h(q^n), then q^{n+1} = q^n + h u^{n+1}.
#include "fix_hardcontact.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"

#include "../core/residual.h"

#include <cfloat>
#include <cmath>
#include "../core/velocity_update.h"

#include <cmath>
#include <unordered_map>

using namespace LAMMPS_NS;
using hardcontact::Vec3;

namespace {
const int MAX_ROUNDS = 1000;    // a safety net: each round adds rows, and there are finitely many
const double SPHERE_INERTIA = 0.4;    // I = 0.4 m r^2, as fix nve/sphere
}    // namespace

void FixHardContact::initial_integrate(int)
{
  build_bodies();
  solve();
  fill_outputs();
  move_and_check();
}

// Eq. 14: u_free = u^n + h M^-1 f^{n+1}, f evaluated at q^n (LAMMPS's forces of this state).
// Atoms outside the group are obstacles: contacts do not change their velocity (inv_mass 0).
void FixHardContact::build_bodies()
{
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  double **v = atom->v, **f = atom->f;
  double *rmass = atom->rmass;
  int *mask = atom->mask;
  const double dtfm = update->dt * force->ftm2v;

  problem_.h = update->dt;
  problem_.n_owned = nlocal;
  problem_.inv_mass.resize(nall);
  problem_.u_free.resize(nall);
  for (int i = 0; i < nall; ++i)
    problem_.inv_mass[i] = (mask[i] & groupbit) ? force->ftm2v / rmass[i] : 0.0;

  tagint bad = 0;
  double local[2] = {0.0, 0.0};    // largest velocity change from the forces, largest radius
  for (int i = 0; i < nlocal; ++i) {
    Vec3 u(v[i]);
    if (mask[i] & groupbit) {
      const Vec3 kick = (dtfm / rmass[i]) * Vec3(f[i]);
      u += kick;
      local[0] = MAX(local[0], kick.norm());
      local[1] = MAX(local[1], atom->radius[i]);
    }
    if (!u.allFinite() && !bad) bad = atom->tag[i];
    problem_.u_free[i] = u;
  }
  tagint bad_all;
  MPI_Allreduce(&bad, &bad_all, 1, MPI_LMP_TAGINT, MPI_MAX, world);
  if (bad_all)
    error->all(FLERR, "Fix hardcontact: atom {} has a non-finite velocity or force at step {}: "
                      "check the forces acting on it", bad_all, update->ntimestep);
  double global[2];
  MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_MAX, world);
  recovery_speed_ = global[0];
  // Radii may change during a run (fix adapt): the list and ghosts only reach 2 r_max + skin.
  if (global[1] > rmax_) radius_grew(global[1]);
  ops_.forward(problem_.u_free.data()->data(), 3);

  // The owners' coordinates on the ghosts, unshifted: a pair across a periodic boundary is
  // then measured as (x_j - x_i) + k L on both processes holding it (see visit_pairs).
  xowner_.resize(nall);
  for (int i = 0; i < nlocal; ++i) xowner_[i] = Vec3(atom->x[i]);
  ops_.forward(xowner_.data()->data(), 3);

  // Round-off of a predicted gap: coordinates of size X carry errors of eps X, and h u of
  // eps h |u|. The solvers never ask for less (core/residual.h).
  double extent = 0.0;
  for (int d = 0; d < 3; ++d)
    extent = MAX(extent, MAX(fabs(domain->boxlo[d]), fabs(domain->boxhi[d])));
  double speed = 0.0;
  for (int i = 0; i < nlocal; ++i) speed = MAX(speed, problem_.u_free[i].norm());
  double speed_all;
  MPI_Allreduce(&speed, &speed_all, 1, MPI_DOUBLE, MPI_MAX, world);
  problem_.gap_roundoff = 16.0 * DBL_EPSILON * (extent + problem_.h * speed_all);

  // The exact solver assembles the operator: on one process, ghosts are periodic images.
  problem_.owner.clear();
  if (solver_->traits().needs_owner_map) {
    std::unordered_map<tagint, int> index;
    for (int i = 0; i < nlocal; ++i) index[atom->tag[i]] = i;
    problem_.owner.resize(nall);
    for (int i = 0; i < nall; ++i) {
      const auto it = index.find(atom->tag[i]);
      problem_.owner[i] = it == index.end() ? -1 : it->second;
    }
  }
}

// Candidate rows (Remark 7): a listed pair, or a wall of an owned atom, whose gap at q^n the
// free speeds could close within the step, D <= h (|u_i| + |u_j|) (scale 1), or that overlaps
// (scale 0, for the diagnostics of step 0). The list holds each pair with an owned atom first;
// a pair across processes is held by both (newton off), each side pushing only its own atom.
// Returns the pairs and walls left out, for missed_rows().
void FixHardContact::build_candidates(double scale)
{
  problem_.clear_contacts();
  const double h = problem_.h;
  const std::vector<Vec3> &uf = problem_.u_free;
  visit_pairs([&](int i, int j, const Vec3 &n, double d, double size) {
    if (d <= scale * h * (uf[i].norm() + uf[j].norm())) add_row(i, j, n, d, size);
  });
  visit_walls([&](int i, int w, double d) {
    if (d <= scale * h * uf[i].norm())
      add_row(i, -1 - w, walls_[w].normal(), d, atom->radius[i]);
  });
  speed_scale_ = hardcontact::free_speed_scale(problem_, ops_);
  apply_overlap_policy(0);
}

// Overlap policy: a pair overlapping at q^n (D < 0) is asked to separate by no more than h
// times the largest velocity the external forces give in one step (g h under gravity), plus
// twice the solver tolerance on its row scale (residual.h). The first part does not feed on
// itself: clearing overlaps adds at most about m (g h)^2 per atom and step, and with no force
// large overlaps stay as they are. The second clears what a solve stopped at tol leaves (at
// most tol times the scale per step), so such overlaps never add up. For D >= 0, the normal
// case, this is eq. 15 unchanged.
void FixHardContact::apply_overlap_policy(int first_row)
{
  const int nc = problem_.n_contacts();
  const double h = problem_.h;
  const double tol = settings_.tol;
  for (int c = first_row; c < nc; ++c) {
    if (problem_.gap[c] >= 0.0) continue;
    // the row scale without its round-off floor: at rest with no force nothing may move
    const double s = MIN(problem_.size[c], h * speed_scale_);
    problem_.gap[c] = MAX(problem_.gap[c], -(h * recovery_speed_ + 2.0 * tol * s));
  }
}

// After a solve: a pair outside the candidates may still be violated when a speed grew above
// its free value (a light sphere struck by a heavy one). Such pairs become rows and the solve
// goes on; then u satisfies eq. 15 for every listed pair. Returns whether any process added.
bool FixHardContact::add_missed_rows()
{
  const double h = problem_.h;
  const std::vector<Vec3> &uf = problem_.u_free;
  const double tol = settings_.tol;
  // the scale the solve just used (V over its rows), so that every row meets one criterion
  const double v = last_speed_scale_;
  const int first = problem_.n_contacts();
  int added = 0;
  visit_pairs([&](int i, int j, const Vec3 &n, double d, double size) {
    if (d <= h * (uf[i].norm() + uf[j].norm())) return;    // a candidate already
    const double g = d + h * n.dot(u_[j] - u_[i]);
    if (hardcontact::row_violation(g, 0.0, hardcontact::row_scale(size, h, v, tol, problem_.gap_roundoff)) <= tol) return;
    add_row(i, j, n, d, size);
    ++added;
  });
  visit_walls([&](int i, int w, double d) {
    if (d <= h * uf[i].norm()) return;
    const double g = d - h * walls_[w].normal().dot(u_[i]);
    const double size = atom->radius[i];
    if (hardcontact::row_violation(g, 0.0, hardcontact::row_scale(size, h, v, tol, problem_.gap_roundoff)) <= tol) return;
    add_row(i, -1 - w, walls_[w].normal(), d, size);
    ++added;
  });
  apply_overlap_policy(first);
  return ops_.sum_all(added) > 0.0;
}

void FixHardContact::add_row(int i, int j, const Vec3 &n, double d, double size)
{
  const bool counted = j < 0 || j < atom->nlocal || atom->tag[i] < atom->tag[j];
  problem_.add_contact(i, j, n, d, size, counted);    // D < 0: see apply_overlap_policy()
}

template <class F> void FixHardContact::visit_pairs(F &&f)
{
  double **x = atom->x;
  double *radius = atom->radius;
  int *mask = atom->mask;
  tagint *tag = atom->tag;
  const int inum = list_->inum;
  const int *ilist = list_->ilist;
  for (int ii = 0; ii < inum; ++ii) {
    const int i = ilist[ii];
    const int *jlist = list_->firstneigh[i];
    const int jnum = list_->numneigh[i];
    for (int jj = 0; jj < jnum; ++jj) {
      const int j = jlist[jj] & NEIGHMASK;
      if (!(mask[i] & groupbit) && !(mask[j] & groupbit)) continue;
      if (tag[i] == tag[j]) continue;    // a sphere and its own periodic image
      const Vec3 dx = pair_vector(i, j, x);
      const double r = dx.norm();
      const Vec3 n = r > 0.0 ? Vec3(dx / r) : coincident_normal(i, j);
      f(i, j, n, r - radius[i] - radius[j], radius[i] + radius[j]);
    }
  }
}

// x_j - x_i for a listed pair. A pair across processes (newton off) is a row on both, and
// Prop. 4 (exact momentum) needs the two rows to evolve identically: same D, opposite normals,
// bit for bit. A ghost copied without a periodic shift has exactly its owner's coordinates, so
// the plain difference is antisymmetric. Across a periodic boundary the ghost holds
// x_owner + k L rounded, and the two processes would round differently: there the difference
// of the owners' coordinates (xowner_) is taken, then k L added, which rounds antisymmetrically.
Vec3 FixHardContact::pair_vector(int i, int j, double **x) const
{
  const Vec3 plain = Vec3(x[j]) - Vec3(x[i]);
  if (j < atom->nlocal) return plain;
  const Vec3 shift = Vec3(x[j]) - xowner_[j];
  if (shift.isZero(0.0)) return plain;
  Vec3 dx = xowner_[j] - Vec3(x[i]);
  for (int d = 0; d < 3; ++d) {
    if (shift[d] == 0.0) continue;
    const double k = std::nearbyint(shift[d] / domain->prd[d]);
    dx[d] += k * domain->prd[d];
  }
  return dx;
}

// Coincident centres: D is not differentiable and any unit vector is a valid G (subgradient).
// Every free motion moves such a pair apart, so take the direction of the free relative
// velocity: the constraint then lets the pair go on as it moves, instead of stopping it on an
// arbitrary axis. At rest, orient by atom ID. Both processes holding the pair see the same
// u_free (forwarded to ghosts) and atom IDs, so they pick opposite vectors of one normal.
Vec3 FixHardContact::coincident_normal(int i, int j) const
{
  const Vec3 du = problem_.u_free[j] - problem_.u_free[i];
  const double speed = du.norm();
  if (speed > 0.0) return du / speed;
  return Vec3::UnitX() * (atom->tag[i] < atom->tag[j] ? 1.0 : -1.0);
}

template <class F> void FixHardContact::visit_walls(F &&f)
{
  const int nw = static_cast<int>(walls_.size());
  if (nw == 0) return;
  double **x = atom->x;
  int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; ++i) {
    if (!(mask[i] & groupbit)) continue;
    for (int w = 0; w < nw; ++w) f(i, w, walls_[w].gap(x[i], atom->radius[i]));
  }
}

void FixHardContact::solve()
{
  build_candidates(1.0);
  // Warm start: each row starts from the multiplier its pair had at the last step, if any.
  const int nc = problem_.n_contacts();
  mu_.assign(nc, 0.0);
  if (warmstart_)
    for (int c = 0; c < nc; ++c) mu_[c] = warm_.find(problem_.body_i[c], partner_key(c));
  hardcontact::SolveReport report;
  int iterations = 0;
  int rounds = 0;
  for (;;) {
    report = solver_->solve(problem_, settings_, ops_, mu_, u_);    // from the mu found so far
    iterations += report.iterations;
    last_speed_scale_ = report.speed_scale;
    ++rounds;
    // An unconverged solve is not refined further: its violations are reported, not chased.
    if (!report.converged || !add_missed_rows()) break;
    if (rounds == MAX_ROUNDS) {
      report.converged = false;
      break;
    }
  }
  if (!report.converged) {
    ++maxiter_hits_;
    ++maxiter_hits_run_;
    if (maxiter_hits_run_ == 1 && comm->me == 0)
      error->warning(FLERR, "Fix hardcontact: the solve of step {} stopped unconverged after {} "
                            "iterations (maxiter {}) with residual {:.3g} > tol {:.3g}; overlaps "
                            "up to that size may remain. Raise maxiter or tol (counted in "
                            "f_{}[{}]; reported once per run)",
                     update->ntimestep, report.iterations, settings_.maxiter, report.residual,
                     settings_.tol,
                     id, MAXITER_HITS + 1);
  }
  remember_multipliers();
  // The kinetic energy the solve may add (residual.h, energy_within_bound): the work of the
  // forces clearing overlaps present at q^n, sum mu max(0, -D) over the rows.
  diag_[CLEARING_WORK] = ops_.sum_all(hardcontact::clearing_work(problem_, mu_));
  diag_[ITERATIONS] = iterations;
  diag_[RESIDUAL] = report.residual;
  diag_[RHO] = report.rho;
  diag_[ROUNDS] = rounds;
  diag_[MAXITER_HITS] = static_cast<double>(maxiter_hits_);
}

// A row is counted once over all processes: a pair across processes is held by both, and
// counted by the side whose atom has the smaller ID.
bool FixHardContact::counted_here(int c) const
{
  return problem_.counted[c] != 0;
}

void FixHardContact::fill_outputs()
{
  const int nlocal = atom->nlocal;
  const int nc = problem_.n_contacts();
  hardcontact::contact_forces(problem_, mu_, force_);

  for (int i = 0; i < nlocal; ++i) {
    array_atom[i][0] = 0.0;
    for (int k = 0; k < 3; ++k) array_atom[i][k + 1] = force_[i][k];
  }
  double counts[2] = {0.0, 0.0};    // rows, active rows
  int nrows = 0;
  for (int c = 0; c < nc; ++c) {
    const int i = problem_.body_i[c], j = problem_.body_j[c];
    const bool here = counted_here(c);
    if (here) counts[0] += 1.0;
    if (mu_[c] <= 0.0) continue;
    if (i < nlocal) array_atom[i][0] += 1.0;
    if (j >= 0 && j < nlocal) array_atom[j][0] += 1.0;
    if (here) {
      counts[1] += 1.0;
      ++nrows;
    }
  }
  double all[2];
  MPI_Allreduce(counts, all, 2, MPI_DOUBLE, MPI_SUM, world);
  diag_[CANDIDATES] = all[0];
  diag_[ACTIVE] = all[1];

  if (nrows > nlocal_rows_max_) {
    nlocal_rows_max_ = nrows;
    memory->destroy(array_local);
    memory->create(array_local, nlocal_rows_max_, size_local_cols, "hardcontact:array_local");
  }
  size_local_rows = nrows;
  int m = 0;
  for (int c = 0; c < nc; ++c) {
    if (mu_[c] <= 0.0 || !counted_here(c)) continue;
    const int j = problem_.body_j[c];
    double *row = array_local[m++];
    row[0] = atom->tag[problem_.body_i[c]];
    row[1] = j >= 0 ? atom->tag[j] : 0;
    row[2] = mu_[c];
    for (int k = 0; k < 3; ++k) row[3 + k] = problem_.normal[c][k];
    row[6] = j >= 0 ? 0 : -j;    // wall number in the order of the fix command, 0 for a pair
  }
}

namespace {
// The two largest values over all processes (of distinct atoms): what a pair can add up to.
void two_largest(double v, double top[2])
{
  if (v > top[0]) {
    top[1] = top[0];
    top[0] = v;
  } else if (v > top[1]) {
    top[1] = v;
  }
}
}    // namespace

// Eq. 19, plus the guarantee that no contact was missed: a pair absent from the list was at
// least r_i + r_j + skin apart at the last build, so it cannot overlap while the two atoms
// together have moved less than the skin since (d_i + d_j < skin). A rebuild is forced as soon
// as the next step could break that even if speeds doubled (gravity, collisions).
void FixHardContact::move_and_check()
{
  const int nlocal = atom->nlocal;
  double **x = atom->x, **v = atom->v, **omega = atom->omega, **torque = atom->torque;
  double *rmass = atom->rmass, *radius = atom->radius;
  int *mask = atom->mask;
  const double dt = update->dt;
  const double dtfrot = dt * force->ftm2v / SPHERE_INERTIA;

  overlap_diagnostics(dt);

  // [0..1] largest displacements since the build, [2..3] same after two more such steps,
  // [4] largest move of this step
  double mine[5] = {0.0, 0.0, 0.0, 0.0, 0.0};
  for (int i = 0; i < nlocal; ++i) {
    if (!(mask[i] & groupbit)) continue;
    for (int k = 0; k < 3; ++k) {
      v[i][k] = u_[i][k];
      x[i][k] += dt * u_[i][k];
    }
    // Frictionless contacts exert no torque: spins change only by external torques.
    if (omega && torque) {
      const double s = dtfrot / (rmass[i] * radius[i] * radius[i]);
      for (int k = 0; k < 3; ++k) omega[i][k] += s * torque[i][k];
    }
    const double step = dt * u_[i].norm();
    const double disp = (Vec3(x[i]) - xhold_[i]).norm();
    two_largest(disp, mine);
    two_largest(disp + 2.0 * step, mine + 2);
    mine[4] = MAX(mine[4], step);
  }
  std::vector<double> all(5 * comm->nprocs);
  MPI_Allgather(mine, 5, MPI_DOUBLE, all.data(), 5, MPI_DOUBLE, world);
  double now[2] = {0.0, 0.0}, ahead[2] = {0.0, 0.0}, step_max = 0.0;
  for (int p = 0; p < comm->nprocs; ++p) {
    for (int k = 0; k < 2; ++k) {
      two_largest(all[5 * p + k], now);
      two_largest(all[5 * p + 2 + k], ahead);
    }
    step_max = MAX(step_max, all[5 * p + 4]);
  }
  const double skin = neighbor->skin;
  if (now[0] + now[1] >= skin)
    error->all(FLERR, "Fix hardcontact: at step {} two atoms moved {:.6g} and {:.6g} since the "
                      "last neighbor list build, together more than the skin ({:.6g}), so a "
                      "contact may have been missed. The largest move in one step was {:.6g}: "
                      "use 'neighbor {:.3g} bin' or a smaller timestep", update->ntimestep,
               now[0], now[1], skin, step_max, MAX(2.0 * skin, 8.0 * step_max));
  if (ahead[0] + ahead[1] >= skin) next_reneighbor = update->ntimestep;
}

// Largest overlap over the rows at positions q + h u (h = 0: at q), in distance units and
// relative to the contact size. Other listed pairs satisfy eq. 15 (add_missed_rows), and
// D >= linearised gap (D is convex), so they cannot overlap beyond the tolerance either.
void FixHardContact::overlap_diagnostics(double h)
{
  double **x = atom->x;
  double *radius = atom->radius;
  double worst[2] = {0.0, 0.0};
  const int nc = problem_.n_contacts();
  for (int c = 0; c < nc; ++c) {
    const int i = problem_.body_i[c], j = problem_.body_j[c];
    Vec3 xi(x[i]);
    if (h > 0.0) xi += h * u_[i];
    double d;
    if (j >= 0) {
      Vec3 xj(x[j]);
      if (h > 0.0) xj += h * u_[j];
      d = (xj - xi).norm() - radius[i] - radius[j];
    } else {
      d = walls_[-1 - j].gap(xi.data(), radius[i]);
    }
    if (d < 0.0) {
      worst[0] = MAX(worst[0], -d);
      worst[1] = MAX(worst[1], -d / problem_.size[c]);
    }
  }
  double all[2];
  MPI_Allreduce(worst, all, 2, MPI_DOUBLE, MPI_MAX, world);
  diag_[MAX_OVERLAP] = all[0];
  diag_[MAX_OVERLAP_RELATIVE] = all[1];
}

// The key under which an atom stores a row: the other atom's ID, or -(w+1) for wall w.
double FixHardContact::partner_key(int c) const
{
  const int j = problem_.body_j[c];
  return j >= 0 ? static_cast<double>(atom->tag[j]) : static_cast<double>(j);
}

void FixHardContact::remember_multipliers()
{
  if (!warmstart_) return;
  const int nlocal = atom->nlocal;
  for (int i = 0; i < nlocal; ++i) warm_.clear(i);
  const int nc = problem_.n_contacts();
  for (int c = 0; c < nc; ++c) {
    if (mu_[c] <= 0.0) continue;
    const int i = problem_.body_i[c], j = problem_.body_j[c];
    if (i < nlocal) warm_.add(i, partner_key(c), mu_[c]);
    if (j >= 0 && j < nlocal) warm_.add(j, static_cast<double>(atom->tag[i]), mu_[c]);
  }
  maxexchange = 4 + warm_.max_packed_size();
}

void FixHardContact::post_run()
{
  if (maxiter_hits_run_ > 0 && comm->me == 0)
    error->warning(FLERR, "Fix hardcontact: {} solve(s) of this run stopped unconverged "
                          "(maxiter {})",
                   maxiter_hits_run_, settings_.maxiter);
  maxiter_hits_run_ = 0;
}
