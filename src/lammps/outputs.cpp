#include "outputs.h"

#include "sources/contact_source.h"
#include "lammps_compat.h"

#include "../core/dual_operator.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix.h"
#include "memory.h"
#include "update.h"

#include <algorithm>

using namespace LAMMPS_NS;

namespace hardcontact {

Outputs::~Outputs()
{
  memory->destroy(fix_->array_atom);
  memory->destroy(fix_->array_local);
}

double Outputs::memory_usage() const
{
  double bytes = per_atom_columns() * sizeof(double) * atom->nmax;
  bytes += local_columns() * sizeof(double) * nlocal_rows_max_;
  return bytes;
}

// Per-atom output follows its atom when atoms migrate or are sorted (it is computed in
// initial_integrate, before the exchange of the same step).
void Outputs::grow_per_atom(int nmax)
{
  memory->grow(fix_->array_atom, nmax, per_atom_columns(), "hardcontact:array_atom");
}

void Outputs::clear_per_atom(int i)
{
  for (int k = 0; k < per_atom_columns(); ++k) fix_->array_atom[i][k] = 0.0;
}

void Outputs::start_of_run(const ContactProblem &p, const WallGaps &walls,
                           double tol)
{
  double worst[2], all[2];
  local_overlaps(p, nullptr, 0.0, walls, worst);
  MPI_Allreduce(worst, all, 2, MPI_DOUBLE, MPI_MAX, world);
  diag_[MAX_OVERLAP] = all[0];
  diag_[MAX_OVERLAP_RELATIVE] = all[1];
  diag_[ITERATIONS] = diag_[CANDIDATES] = diag_[ACTIVE] = diag_[RESIDUAL] = 0.0;
  diag_[RHO] = diag_[ROUNDS] = diag_[CLEARING_WORK] = diag_[FRICTION_WORK] = 0.0;
  diag_[MAXITER_HITS] = static_cast<double>(maxiter_hits_);
  diag_[KEPT_UNDONE] = static_cast<double>(kept_undone_);
  if (diag_[MAX_OVERLAP_RELATIVE] > tol && comm->me == 0)
    compat::warning(error, FLERR,
                    "Fix hardcontact: the run starts with overlapping spheres (largest "
                    "overlap {:.6g}, {:.3g} of the contact size); each step clears at most "
                    "h x the velocity the forces give in one step, plus 2 tol x its row "
                    "scale, so that no energy explodes (see the doc page)",
                    diag_[MAX_OVERLAP], diag_[MAX_OVERLAP_RELATIVE]);
  fix_->size_local_rows = 0;
  for (int i = 0; i < atom->nlocal; ++i) clear_per_atom(i);
}

void Outputs::record_step(const StepResult &r, const ContactProblem &p,
                          const std::vector<double> &mu, ContactLaw law,
                          const std::vector<Vec3> &u, const WallGaps &walls,
                          const SolverSettings &settings, DistributedOps &ops)
{
  record_solve(r, settings);
  // sums: rows, active rows, friction's work, the clearing work; maxima: overlap, relative
  double v[6];
  per_atom_and_local(p, mu, law, u, v);
  v[3] = r.clearing_work;
  local_overlaps(p, &u, update->dt, walls, v + 4);
  ops.sum_max_all(v, 4, 2);
  diag_[CANDIDATES] = v[0];
  diag_[ACTIVE] = v[1];
  diag_[FRICTION_WORK] = v[2];
  diag_[CLEARING_WORK] = v[3];
  diag_[MAX_OVERLAP] = v[4];
  diag_[MAX_OVERLAP_RELATIVE] = v[5];
}

void Outputs::record_solve(const StepResult &r, const SolverSettings &settings)
{
  if (!r.report.converged) {
    ++maxiter_hits_;
    ++maxiter_hits_run_;
    if (maxiter_hits_run_ == 1 && comm->me == 0)
      compat::warning(error, FLERR,
                      "Fix hardcontact: the solve of step {} stopped unconverged after {} "
                      "iterations (maxiter {}) with residual {:.3g} > tol {:.3g}; overlaps "
                      "up to that size may remain. Raise maxiter or tol (counted in "
                      "f_{}[{}]; reported once per run)",
                      update->ntimestep, r.report.iterations, settings.maxiter, r.report.residual,
                      settings.tol, fix_->id, MAXITER_HITS + 1);
  }
  diag_[ITERATIONS] = r.iterations;
  diag_[RESIDUAL] = r.report.residual;
  diag_[RHO] = r.report.rho;
  diag_[ROUNDS] = r.rounds;
  diag_[MAXITER_HITS] = static_cast<double>(maxiter_hits_);
  kept_undone_ += r.kept_undone;
  diag_[KEPT_UNDONE] = static_cast<double>(kept_undone_);
}

void Outputs::end_of_run(const SolverSettings &settings)
{
  if (maxiter_hits_run_ > 0 && comm->me == 0)
    compat::warning(error, FLERR,
                    "Fix hardcontact: {} solve(s) of this run stopped unconverged "
                    "(maxiter {})",
                    maxiter_hits_run_, settings.maxiter);
  maxiter_hits_run_ = 0;
}

// A row is counted once over all processes (ContactProblem::counted): a pair across processes
// is held by both, and counted by the side whose atom has the smaller ID.
void Outputs::per_atom_and_local(const ContactProblem &p, const std::vector<double> &mu,
                                 ContactLaw law, const std::vector<Vec3> &u, double *counts)
{
  const int nlocal = atom->nlocal;
  const int nc = p.n_contacts();
  double **array_atom = fix_->array_atom;
  const int block = law_block(law);
  with_law(law, [&](auto rows_law) {
    using Law = decltype(rows_law);
    contact_forces<Law>(p, mu, force_, Law::block > 1 ? &torque_ : nullptr);
  });
  auto normal_force = [&](int c) { return mu[static_cast<size_t>(block) * c]; };

  for (int i = 0; i < nlocal; ++i) {
    array_atom[i][0] = 0.0;
    for (int k = 0; k < 3; ++k) array_atom[i][k + 1] = force_[i][k];
    if (block > 1)
      for (int k = 0; k < 3; ++k) array_atom[i][k + 4] = torque_[i][k];
  }
  // rows, active rows, energy dissipated by friction in the step. Since u^{n+1} - u_free =
  // h M^-1 sum_c G_c^T mu_c (eq. 16), the kinetic energy the contacts change is exactly
  // h sum_c mu_c . G_c (u_free + u^{n+1}) / 2: the tangential terms, -h F_t . (mean slip),
  // are what friction dissipates (>= 0: Coulomb's force opposes the slip).
  counts[0] = counts[1] = counts[2] = 0.0;
  int nrows = 0;
  with_law(law, [&](auto rows_law) {    // the law's type once, not per row
    using Law = decltype(rows_law);
    for (int c = 0; c < nc; ++c) {
      const int i = p.body_i[c], j = p.body_j[c];
      const bool here = p.counted[c] != 0;
      if (here) counts[0] += 1.0;
      if (normal_force(c) == 0.0) continue;    // active: a force, pushing or (cohesion) pulling
      if (i < nlocal) array_atom[i][0] += 1.0;
      if (!is_wall(j) && j < nlocal) array_atom[j][0] += 1.0;
      if (!here) continue;
      counts[1] += 1.0;
      if (listed(j)) ++nrows;
      // each disc's work: -h m_q . (its mean rate), laws/disc_rows.h
      if constexpr (Law::block > 1)
        Law::subtract_work(p, c, &mu[static_cast<size_t>(block) * c], u, p.u_free, counts[2]);
    }
  });

  const int ncols = local_columns();
  if (nrows > nlocal_rows_max_) {
    nlocal_rows_max_ = nrows;
    memory->destroy(fix_->array_local);
    memory->create(fix_->array_local, nlocal_rows_max_, ncols, "hardcontact:array_local");
  }
  fix_->size_local_rows = nrows;
  int m = 0;
  for (int c = 0; c < nc; ++c) {
    const int j = p.body_j[c];
    if (normal_force(c) == 0.0 || !p.counted[c] || !listed(j)) continue;
    double *row = fix_->array_local[m++];
    row[0] = atom->tag[p.body_i[c]];
    row[1] = is_wall(j) ? 0 : atom->tag[j];
    row[2] = normal_force(c);
    for (int k = 0; k < 3; ++k) row[3 + k] = p.normal[c][k];
    row[6] = is_wall(j) ? 1 + wall_index(j) : 0;    // in the order of the fix command, from 1
    if (block == 1) continue;
    const double *f = &mu[static_cast<size_t>(block) * c];
    const Vec3 ft = f[1] * p.tangent1[c] + f[2] * p.tangent2[c];
    for (int k = 0; k < 3; ++k) row[7 + k] = ft[k];
    // on the cone up to the solver's round-off: sliding
    row[10] = ft.norm() >= (1.0 - 1e-6) * p.friction[c] * f[0] && p.friction[c] > 0.0 ? 1.0 : 0.0;
  }
}

// Largest overlap over the rows at positions q + h u (h = 0: at q), in distance units and
// relative to the contact size. Other listed pairs satisfy eq. 15 (the missed-row check), and
// D >= linearised gap (D is convex), so they cannot overlap beyond the tolerance either.
void Outputs::local_overlaps(const ContactProblem &p, const std::vector<Vec3> *u, double h,
                             const WallGaps &walls, double *worst) const
{
  double **x = atom->x;
  double *radius = atom->radius;
  worst[0] = worst[1] = 0.0;
  const int nc = p.n_contacts();
  for (int c = 0; c < nc; ++c) {
    const int i = p.body_i[c], j = p.body_j[c];
    Vec3 xi(x[i]);
    if (h > 0.0) xi += h * (*u)[i];
    double d;
    if (!is_wall(j)) {
      Vec3 xj(x[j]);
      if (h > 0.0) xj += h * (*u)[j];
      d = (xj - xi).norm() - radius[i] - radius[j];
    } else {
      d = walls.wall_gap(wall_index(j), xi, radius[i]);
    }
    if (d < 0.0) {
      worst[0] = MAX(worst[0], -d);
      worst[1] = MAX(worst[1], -d / p.size[c]);
    }
  }
}

}    // namespace hardcontact
