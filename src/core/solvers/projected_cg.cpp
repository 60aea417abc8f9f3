#include "projected_cg.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hardcontact {

// Notation (projected_cg.h): g = A mu + b is the gap of u(mu) (eq. 15, the dual's gradient),
// d = diag A. CG with the preconditioner D^-1: dir = D^-1 g - gamma dir on free rows, gamma =
// (D^-1 g_new).A dir / dir.A dir (A-conjugate to the last direction, the form that needs no
// old residual), step alpha = g.dir / dir.A dir along -dir (exact line search). Every sum runs
// over counted rows (a row held by two processes counts once) and is reduced over all
// processes; every per-row value is computed from forwarded velocities and reduced scalars,
// so two processes holding the same row compute the same multiplier: momentum stays exact.

void ProjectedCg::start(const SolverSettings &s, std::vector<double> &mu, std::vector<Vec3> &u)
{
  const ContactProblem &p = op_.problem();
  const int nc = p.n_contacts();
  // The past corrections follow the rows by their bodies (past_corrections.h)
  if (s.subspace > 0) {
    past_.follow(p, op_.ops());
    if (past_.due()) past_.rows_used([&](int c) { set_.include(c); });
    warm_.assign(mu.begin(), mu.begin() + nc);
  } else {
    past_.clear();
  }
  inv_d_.resize(nc);
  double dmax = 0.0;    // over the working set
  for (int c = 0; c < nc; ++c) {
    const double d = op_.diagonal(c);
    inv_d_[c] = d > 0.0 ? 1.0 / d : 1.0;    // a row no body can move: any scale
    if (set_.contains(c)) dmax = std::max(dmax, d);
  }
  for (auto *v : {&dir_, &q_, &clip_, &qc_}) v->assign(nc, 0.0);
  near_mark_.assign(nc, 0);
  body_mark_.assign(p.n_owned, 0);
  wc_.assign(p.n_dof(), Vec3::Zero());
  w_.assign(p.n_dof(), Vec3::Zero());    // products clear only the bodies of set rows (moved_)
  // u = u(m) and the gaps g on the set rows
  const auto regap = [&](const std::vector<double> &m, std::vector<double> &g,
                         std::vector<Vec3> &v) {
    op_.velocities(set_.rows(), m, v);
    for (const int c : set_.rows()) g[c] = op_.gap(c, v);
  };
  regap(mu, g_, u);
  index_rows();
  // the subspace start (past_corrections.h), forces clipped at 0
  if (s.subspace > 0 && past_.trying())
    past_.improve_start(p, set_.rows(), op_.ops(), mu, g_, u,
                        [](int, double *m) { m[0] = m[0] > 0.0 ? m[0] : 0.0; }, regap);
  refresh(mu);
  cg_ = false;
  // reported step (f_ID[8]): the preconditioner's step on its stiffest row, 1 / max diag(A)
  // (the exact step along that row alone), as apgd with friction reports its stiffest one
  dmax = op_.ops().max_all(dmax);
  rho_ = dmax > 0.0 ? 1.0 / dmax : 0.0;
}

void ProjectedCg::grown(const SolverSettings &, std::vector<double> &mu, std::vector<Vec3> &u)
{
  // new rows hold mu = 0 and u is unchanged: their gaps, and everyone's again from u (the
  // recurrence of g resynchronised); CG starts again on the larger set
  for (const int c : set_.rows()) g_[c] = op_.gap(c, u);
  index_rows();
  refresh(mu);
  cg_ = false;
}

void ProjectedCg::finished(const SolverSettings &s, const std::vector<double> &mu,
                           const std::vector<Vec3> &)
{
  if (s.subspace <= 0) return;
  const ContactProblem &p = op_.problem();
  const int nc = p.n_contacts();
  std::vector<double> d(nc), ad(nc, 0.0);
  for (int c = 0; c < nc; ++c) d[c] = mu[c] - warm_[c];
  // A d on the set rows (a correction is 0 outside them): one product, with this step's A
  const std::vector<int> &rows = set_.rows();
  op_.impulse_velocities_with(rows, [&](int c) { return d[c]; }, w_, &moved_);
  for (const int c : rows) ad[c] = p.h * p.normal_speed(c, w_);
  past_.record(std::move(d), std::move(ad), p, s.subspace);
}

double ProjectedCg::residual_all(const std::vector<double> &, const std::vector<Vec3> &)
{
  return residual_;
}

void ProjectedCg::index_rows()
{
  const ContactProblem &p = op_.problem();
  const int nb = p.n_bodies();
  row_start_.assign(nb + 1, 0);
  for (const int c : set_.rows()) {
    ++row_start_[p.body_i[c] + 1];
    if (!is_wall(p.body_j[c])) ++row_start_[p.body_j[c] + 1];
  }
  for (int b = 0; b < nb; ++b) row_start_[b + 1] += row_start_[b];
  moved_.clear();
  for (int b = 0; b < p.n_owned; ++b)
    if (row_start_[b + 1] > row_start_[b]) moved_.push_back(b);
  row_list_.resize(row_start_[nb]);
  std::vector<int> &at = touched_;    // scratch: the next free place per body
  at.assign(row_start_.begin(), row_start_.end() - 1);
  for (const int c : set_.rows()) {
    row_list_[at[p.body_i[c]]++] = c;
    if (!is_wall(p.body_j[c])) row_list_[at[p.body_j[c]]++] = c;
  }
  touched_.clear();
}

template <class Update>
void ProjectedCg::refresh_with(const std::vector<double> &mu, Update &&update)
{
  // local addresses, as in product(); the violation is set_.violation's (normal law)
  const char *counted = op_.problem().counted.data();
  const double *g = g_.data(), *inv_d = inv_d_.data(), *q = q_.data(), *m = mu.data();
  const double *scale = set_.scales().data();
  double r = 0.0, num = 0.0;
  for (const int c : set_.rows()) {
    update(c);
    r = std::max(r, NormalLaw::violation(g[c], m[c], scale[c]));
    if (counted[c] && (m[c] > 0.0 || g[c] < 0.0)) num += g[c] * inv_d[c] * q[c];    // free()
  }
  // one reduction where two would be: the stopping test reads residual_ (residual_all)
  double v[2] = {num, r};
  op_.ops().sum_max_all(v, 1, 1);
  gamma_num_ = v[0];
  residual_ = v[1];
}

void ProjectedCg::refresh(const std::vector<double> &mu)
{
  refresh_with(mu, [](int) {});
}

double ProjectedCg::product(const std::vector<double> &mu, double gamma)
{
  const ContactProblem &p = op_.problem();
  const std::vector<int> &rows = set_.rows();
  // the per-row arrays through local addresses (RowKernel: the stores below would otherwise
  // reload them), and the sums in registers rather than in the array sum_all takes
  double *dir = dir_.data(), *q = q_.data();
  const double *g = g_.data(), *inv_d = inv_d_.data(), *m = mu.data();
  op_.impulse_velocities_with(
      rows,
      [&](int c) {
        dir[c] = m[c] > 0.0 || g[c] < 0.0 ? g[c] * inv_d[c] - gamma * dir[c] : 0.0;    // free()
        return dir[c];
      },
      w_, &moved_);
  const RowKernel k(p);
  const double *w = doubles(w_);
  const char *counted = p.counted.data();
  double gd = 0.0, dq = 0.0;
  double ratio = 0.0;
  for (const int c : rows) {
    const double d = dir[c];
    const double qc = k.h * k.normal_speed(c, w);
    q[c] = qc;
    // The largest d / mu over the rows the direction lowers; a row at 0 it would lower (an
    // overlapping row joined with the old direction's share) gives d / 0 = inf: no step keeps
    // it feasible. No branch on the sign of d: where d <= 0 the quotient is <= 0, -inf or NaN
    // (0 / 0), all of which max() passes over (ratio >= 0), and mu <= 0 (or -0) is read as
    // +0. The sign of dir is a coin toss on a pile at rest: a branch on it mispredicted on
    // half the rows (0.75 x the loop time without it on a creeping 3D pile).
    const double mc = m[c] > 0.0 ? m[c] : 0.0;
    ratio = std::max(ratio, d / mc);
    if (!counted[c]) continue;
    gd += g[c] * d;
    dq += d * qc;
  }
  double s[3] = {gd, dq, ratio};
  op_.ops().sum_max_all(s, 2, 1);
  sums_[0] = s[0];
  sums_[1] = s[1];
  return s[2];
}

void ProjectedCg::move(double a, std::vector<double> &mu, std::vector<Vec3> &u)
{
  for (const int c : set_.rows()) move_row(c, a, mu);
  move_bodies(a, u);
}

// move() and refresh() in one pass over the rows (the CG step's common case)
void ProjectedCg::move_and_refresh(double a, std::vector<double> &mu, std::vector<Vec3> &u)
{
  double *m = mu.data(), *g = g_.data();
  const double *dir = dir_.data(), *q = q_.data();
  refresh_with(mu, [&](int c) {    // move_row(c, a, mu)
    m[c] -= a * dir[c];
    g[c] -= a * q[c];
  });
  move_bodies(a, u);
}

void ProjectedCg::move_bodies(double a, std::vector<Vec3> &u) const
{
  // w_ is 0 on the owned bodies no row of the set touches (zeroed in start, never applied)
  const ContactProblem &p = op_.problem();
  const int nb = p.n_bodies();
  for (const int b : moved_) u[b] -= a * w_[b];
  for (int b = p.n_owned; b < nb; ++b) u[b] -= a * w_[b];
  if (p.rotates()) {
    for (const int b : moved_) u[nb + b] -= a * w_[nb + b];
    for (int b = p.n_owned; b < nb; ++b) u[nb + b] -= a * w_[nb + b];
  }
}

// mu - a dir + clip with clip_c = a dir_c - mu_c on the rows that would go below 0 (they land
// on 0 exactly); u and g follow from w_, q_ and the clip's own velocity change, which touches
// only the bodies of clipped rows and, through them, the rows sharing those bodies. phi changes
// by g.delta + 1/2 delta.A delta with delta = -a dir + clip:
//   -a g.dir + a^2/2 dir.A dir + clip.(g - a q) + 1/2 clip.A clip.
bool ProjectedCg::projected_step(double a, double floor, std::vector<double> &mu,
                                 std::vector<Vec3> &u)
{
  const ContactProblem &p = op_.problem();
  clipped_.clear();
  for (const int c : set_.rows())
    // the rare test first: the sign of dir is a coin toss at rest (a mispredicted branch)
    if (mu[c] - a * dir_[c] < 0.0 && dir_[c] > 0.0) {
      clip_[c] = a * dir_[c] - mu[c];
      clipped_.push_back(c);
      op_.apply(c, clip_[c], wc_);
    }
  op_.forward(wc_);
  // bodies the clip moved (apply() changes only owned bodies' linear velocities): owned ones
  // from the clipped rows, ghosts (from their owners) by a scan of the ghost range only
  touched_.clear();
  const auto moved = [&](int b) { return wc_[b] != Vec3::Zero(); };
  for (const int c : clipped_)
    for (const int b : {p.body_i[c], p.body_j[c]})
      if (!is_wall(b) && b < p.n_owned && !body_mark_[b] && moved(b)) {
        body_mark_[b] = 1;
        touched_.push_back(b);
      }
  for (const int b : touched_) body_mark_[b] = 0;
  const int nb = p.n_bodies();
  for (int b = p.n_owned; b < nb; ++b)
    if (moved(b)) touched_.push_back(b);
  near_.clear();
  for (const int b : touched_)
    for (int k = row_start_[b]; k < row_start_[b + 1]; ++k) {
      const int c = row_list_[k];
      if (near_mark_[c]) continue;
      near_mark_[c] = 1;
      near_.push_back(c);
      qc_[c] = p.h * p.normal_speed(c, wc_);
    }
  double s = 0.0;
  for (const int c : clipped_)
    if (p.counted[c]) s += clip_[c] * (g_[c] - a * q_[c] + 0.5 * qc_[c]);
  const double change = -a * sums_[0] + 0.5 * a * a * sums_[1] + op_.ops().sum_all(s);
  const bool take = change <= floor;
  if (take) {
    move(a, mu, u);
    for (const int c : clipped_) mu[c] = 0.0;    // exactly, not a round-off away
    for (const int c : near_) g_[c] += qc_[c];
    for (const int b : touched_) u[b] += wc_[b];
  }
  for (const int c : clipped_) clip_[c] = 0.0;
  for (const int c : near_) {
    near_mark_[c] = 0;
    qc_[c] = 0.0;
  }
  for (const int b : touched_) wc_[b] = Vec3::Zero();
  return take;
}

bool ProjectedCg::step(const SolverSettings &, std::vector<double> &mu, std::vector<Vec3> &u)
{
  double ratio = product(mu, cg_ && pq_ > 0.0 ? gamma_num_ / pq_ : 0.0);
  if (!(sums_[0] > 0.0) && cg_) {
    // the conjugate direction no longer descends (the free rows changed under it): start
    // again from the preconditioned gradient
    cg_ = false;
    ratio = product(mu, 0.0);
  }
  if (!(sums_[0] > 0.0)) return false;    // no descent left on the free rows: nothing to do
  const double feasible = ratio > 0.0 ? 1.0 / ratio : std::numeric_limits<double>::infinity();
  // phi is convex: along -dir it is a parabola, or a line where dir.A dir = 0 (redundant
  // rows), which the bound stops
  const double alpha = sums_[1] > 0.0 ? sums_[0] / sums_[1] : feasible;
  if (!std::isfinite(alpha)) return false;    // unbounded: eq. 15 has no solution
  if (alpha <= feasible) {
    move_and_refresh(alpha, mu, u);
    pq_ = sums_[1];
    cg_ = true;
    return true;
  }
  // Forces would go below 0: the projected step, if it does at least as well as stopping at
  // the first bound; conjugacy is kept (the rows that stopped leave the free set)
  const double to_bound = -feasible * sums_[0] + 0.5 * feasible * feasible * sums_[1];
  if (projected_step(alpha, to_bound, mu, u)) {
    pq_ = sums_[1];
    refresh(mu);
    cg_ = true;
    return true;
  }
  // the step to the first bound, and CG again from the gradient
  move(feasible, mu, u);
  for (const int c : set_.rows())
    if (mu[c] <= 1e-12 * dir_[c] * feasible && dir_[c] > 0.0) mu[c] = 0.0;    // as above
  refresh(mu);
  cg_ = false;
  return true;
}

}    // namespace hardcontact
