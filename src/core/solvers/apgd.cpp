#include "apgd.h"

#include <algorithm>
#include <cmath>

namespace hardcontact {

// The dual of eq. 15 as a minimisation over the law's set:
//   phi(mu) = 1/2 mu.A mu + b.mu,  grad phi = A mu + b = g(u(mu)),  A = h^2 G M^-1 G^T,
// so the Uzawa step of section 3.3 is projected gradient descent with step rho, and
// phi(mu) = 1/2 mu.(g(mu) + b) costs no extra product. With friction mu and g have B = 3
// components per row (laws/coulomb.h) and b carries the shift of the normal target.
template <class Law>
double ApgdSolver<Law>::linear(int c, int k) const
{
  const double b = b_[static_cast<size_t>(B) * c + k];
  if constexpr (B == 1) return b;
  else return k == 0 ? b + this->shift(c) : b;
}

template <class Law>
void ApgdSolver<Law>::gaps(const std::vector<double> &m, std::vector<double> &g,
                           std::vector<Vec3> &u)
{
  this->op_.template velocities<Law>(this->set_.rows(), m, u);
  for (const int c : this->set_.rows()) this->gradient_block(c, u, &g[static_cast<size_t>(B) * c]);
}

template <class Law>
void ApgdSolver<Law>::restart(const std::vector<double> &mu)
{
  theta_ = 1.0;
  for (const int c : this->set_.rows())
    for (int k = 0; k < B; ++k) {
      const size_t a = static_cast<size_t>(B) * c + k;
      y_[a] = mu[a];
      gy_[a] = this->g_[a];
    }
}

// Friction: the tangential entries of a block of A are 3.5 x its normal one for solid spheres
// (a^2 / I = 2.5 / m), wall rows have half the entries of pair rows, and masses vary with the
// cube of the radii, so one global step 1/L is far too small for most components. The method
// runs instead on x = D^1/2 mu with D the diagonal of A (Jacobi preconditioning: FISTA, Beck &
// Teboulle 2009, applied to phi(D^-1/2 x), whose Hessian D^-1/2 A D^-1/2 has a unit
// diagonal), i.e. in mu the step is D^-1 g / L and the projection is taken in the D-norm. Within a block the
// tangential (and rolling) entries are equal, so in x the law's set is again a cone of the
// same form, with coefficients scaled by sqrt(d_t / d_n) (sqrt(d_r / d_n)): Law::project
// applies unchanged. A fixed step (s.rho) runs without it (D = I).
template <class Law>
void ApgdSolver<Law>::precondition(const SolverSettings &s)
{
  if constexpr (B > 1) {
    const int nc = this->op_.problem().n_contacts();
    d_.resize(static_cast<size_t>(B) * nc);
    sd_.resize(d_.size());
    isd_.resize(d_.size());
    kd_.resize(nc);
    dmax_ = 0.0;
    for (int c = 0; c < nc; ++c) {
      double *d = &d_[static_cast<size_t>(B) * c];
      Coefficients k = this->coef(c);
      this->op_.template block_diagonals<Law>(c, d);
      bool movable = true;
      for (int q = 0; q < B; ++q) movable = movable && d[q] > 0.0;
      if (s.rho > 0.0 || !movable)
        for (int q = 0; q < B; ++q) d[q] = 1.0;    // fixed step, or a row no body can move
      for (int q = 0; q < B; ++q) {
        sd_[static_cast<size_t>(B) * c + q] = std::sqrt(d[q]);
        isd_[static_cast<size_t>(B) * c + q] = 1.0 / sd_[static_cast<size_t>(B) * c + q];
        dmax_ = std::max(dmax_, d[q]);
      }
      Law::scale_coefficients(k, d);
      kd_[c] = k;
    }
  }
}

template <class Law>
void ApgdSolver<Law>::start(const SolverSettings &s, std::vector<double> &mu,
                            std::vector<Vec3> &u)
{
  const int nc = this->op_.problem().n_contacts();
  const size_t n = static_cast<size_t>(B) * nc;
  if (s.subspace > 0) {
    past_.follow(this->op_.problem(), this->op_.ops());
    if (past_.due()) past_.rows_used([&](int c) { this->set_.include(c); });
    warm_.assign(mu.begin(), mu.begin() + static_cast<std::ptrdiff_t>(n));
  } else {
    past_.clear();
  }
  for (auto *v : {&b_, &y_, &gy_, &next_, &gnext_}) v->assign(n, 0.0);
  std::fill(this->g_.begin(), this->g_.end(), 0.0);
  this->op_.free_velocities(u);
  for (int c = 0; c < nc; ++c)
    this->op_.template gap_block<Law>(c, u, &b_[static_cast<size_t>(B) * c]);
  gaps(mu, this->g_, u);
  // the subspace start, the blocks projected onto the law's set; the shifts stay those of the
  // warm start (the fixed point moves them, as after any start)
  if (s.subspace > 0 && past_.trying())
    past_.improve_start(
        this->op_.problem(), this->set_.rows(), this->op_.ops(), mu, this->g_, u,
        [&](int c, double *m) { Law::project(m, this->coef(c)); },
        [&](const std::vector<double> &m, std::vector<double> &g, std::vector<Vec3> &v) {
          gaps(m, g, v);
        });
  if constexpr (B == 1) {
    // Start L below the Gershgorin bound of the working set: backtracking raises it as needed.
    L_ = s.rho > 0.0 ? 1.0 / s.rho : 0.25 * this->op_.template bound<Law>(this->set_.rows());
  } else {
    // D^-1/2 A D^-1/2 has a unit diagonal: 1 <= its largest eigenvalue
    precondition(s);
    L_ = s.rho > 0.0 ? 1.0 / s.rho : 1.0;
  }
  restart(mu);
  this->rho_ = report_rho();
  residual_ready_ = false;
}

// The correction of this solve and its product A d (gaps of u(d) less the linear term, one
// product with this step's A), kept for the next solves' starts.
template <class Law>
void ApgdSolver<Law>::finished(const SolverSettings &s, const std::vector<double> &mu,
                               const std::vector<Vec3> &)
{
  if (s.subspace <= 0) return;
  const ContactProblem &p = this->op_.problem();
  const std::vector<int> &rows = this->set_.rows();
  const size_t n = static_cast<size_t>(B) * p.n_contacts();
  std::vector<double> d(n, 0.0), ad(n, 0.0);
  for (const int c : rows)
    for (int k = 0; k < B; ++k) {
      const size_t a = static_cast<size_t>(B) * c + k;
      d[a] = mu[a] - warm_[a];
    }
  this->op_.template velocities<Law>(rows, d, scratch_u_);
  for (const int c : rows) {
    double *q = &ad[static_cast<size_t>(B) * c];
    this->gradient_block(c, scratch_u_, q);
    for (int k = 0; k < B; ++k) q[k] -= linear(c, k);
  }
  past_.record(std::move(d), std::move(ad), p, s.subspace);
}

// g(mu) is maintained by the iteration: no product needed for the residual, and after a step
// it was taken in the step's last pass.
template <class Law>
double ApgdSolver<Law>::set_residual(const std::vector<double> &mu, const std::vector<Vec3> &)
{
  if (residual_ready_) {
    residual_ready_ = false;
    return residual_;
  }
  double r = 0.0;
  for (const int c : this->set_.rows()) r = std::max(r, this->set_violation(c, mu, r));
  return r;
}

// New rows enter at mu = y = 0 and the momentum of the others is kept: restarting here would
// turn the cascade of a large impact (rows joining a few at a time) into plain gradient steps.
// One extra product gives g(y) on the grown set; then back to u = u(mu), which the next check
// and the answer must see.
template <class Law>
void ApgdSolver<Law>::grown(const SolverSettings &, std::vector<double> &mu, std::vector<Vec3> &u)
{
  for (const int c : this->set_.rows())    // u = u(mu)
    this->gradient_block(c, u, &this->g_[static_cast<size_t>(B) * c]);
  gaps(y_, gy_, u);
  this->op_.template velocities<Law>(this->set_.rows(), mu, u);
  residual_ready_ = false;    // the set is larger
}

// Friction's shifts moved the linear term by shift_delta_ (g_ follows, base class): g(y)
// moves by as much, and the momentum is kept - a new problem near the old one, and restarting
// at each of the many small moves of the fixed point cost twice the iterations (measured).
template <class Law>
void ApgdSolver<Law>::shifted(const SolverSettings &, std::vector<double> &, std::vector<Vec3> &)
{
  if constexpr (B > 1)
    for (const int c : this->set_.rows()) gy_[static_cast<size_t>(B) * c] += this->shift_delta_[c];
  residual_ready_ = false;
}

// Three passes over the rows per iteration: the trial point fused with its velocities (eq. 16),
// its gaps fused with the sums of the backtracking test, and the update fused with the
// residual of the next verdict.
template <class Law>
bool ApgdSolver<Law>::step(const SolverSettings &, std::vector<double> &mu, std::vector<Vec3> &u)
{
  if (L_ <= 0.0) return false;
  const ContactProblem &p = this->op_.problem();
  const std::vector<int> &rows = this->set_.rows();
  std::vector<double> &g = this->g_;
  // Projected step from y with backtracking: accept when the quadratic model with L bounds
  // phi at the trial point (this is what makes 1/L a valid step without knowing ||A||):
  //   phi(next) <= phi(y) + gy.d + L/2 |d|^2,  d = next - y.
  // With friction the test is taken in its exact equivalent d.(gnext - gy) <= L |d|_D^2 (phi
  // is quadratic and g affine, so phi(next) - phi(y) - gy.d = 1/2 d.A d = 1/2 d.(gnext - gy)):
  // the curvature along d from a difference of gradients. From values of phi it compares two
  // numbers of the size of phi that differ by far less near the answer, and on a frictional
  // bed turned by a drum their round-off failed the test, doubled L, shortened the next step
  // and with it the margin: L ran up to 1e4-6e5 x the unit diagonal of the scaled operator and
  // solves stopped at maxiter with residuals of 1e-3 (bench/studies/friction_rest 10.6). Without
  // friction the form in phi is kept: apgd is not the default there, and its runs stay as
  // they were.
  // sums: B == 1: phi(y), phi(next), gy.d, |d|^2, gy.(next - mu); friction: d.(gnext - gy),
  // |d|_D^2, gy.(next - mu), sum |d| (|gnext| + |gy|) (the round-off scale of the first)
  double sums[5];
  constexpr int kRestartSum = B == 1 ? 4 : 2;
  for (;;) {
    [[maybe_unused]] const double inv_L = 1.0 / L_;
    this->op_.template velocities_with<Law>(
        rows,
        [&](int c) {
          double *m = &next_[static_cast<size_t>(B) * c];
          if constexpr (B == 1) {
            for (int k = 0; k < B; ++k) {
              const size_t a = static_cast<size_t>(B) * c + k;
              m[k] = y_[a] - gy_[a] / L_;
            }
            Law::project(m, this->coef(c));
          } else {
            // x = D^1/2 (y - D^-1 gy / L), projected, back to mu (products with D^-1/2 and
            // 1/L: divisions were a tenth of a frictional iteration)
            for (int k = 0; k < B; ++k) {
              const size_t a = static_cast<size_t>(B) * c + k;
              m[k] = sd_[a] * y_[a] - gy_[a] * (inv_L * isd_[a]);
            }
            Law::project(m, kd_[c]);
            for (int k = 0; k < B; ++k) m[k] *= isd_[static_cast<size_t>(B) * c + k];
          }
          return m;
        },
        u);
    // each row counted once
    for (double &v : sums) v = 0.0;
    for (const int c : rows) {
      this->gradient_block(c, u, &gnext_[static_cast<size_t>(B) * c]);
      if (!p.counted[c]) continue;
      for (int k = 0; k < B; ++k) {
        const size_t a = static_cast<size_t>(B) * c + k;
        const double d = next_[a] - y_[a];
        if constexpr (B == 1) {
          const double b = linear(c, k);
          sums[0] += 0.5 * y_[a] * (gy_[a] + b);
          sums[1] += 0.5 * next_[a] * (gnext_[a] + b);
          sums[2] += gy_[a] * d;
          sums[3] += d * d;
          sums[4] += gy_[a] * (next_[a] - mu[a]);
        } else {
          sums[0] += d * (gnext_[a] - gy_[a]);
          sums[1] += d_[a] * d * d;
          sums[2] += gy_[a] * (next_[a] - mu[a]);
          sums[3] += std::abs(d) * (std::abs(gnext_[a]) + std::abs(gy_[a]));
        }
      }
    }
    this->op_.ops().sum_all(sums, B == 1 ? 5 : 4);
    double step2;    // |d|^2: 0 when the step changes nothing
    if constexpr (B == 1) {
      const double slack = 1e-12 * (std::abs(sums[0]) + std::abs(sums[1]));
      if (sums[1] <= sums[0] + sums[2] + 0.5 * L_ * sums[3] + slack) break;
      step2 = sums[3];
    } else {
      // gy is carried by recurrence (g is affine), so it holds round-off of its own
      if (sums[0] <= L_ * sums[1] + 1e-12 * sums[3]) break;
      step2 = sums[1];
    }
    // A step too small to change anything cannot fail the test for a real reason (round-off):
    // accept it rather than let L run away.
    if (!(L_ < 1e300) || step2 == 0.0) break;
    L_ *= 2.0;
  }
  if (!(L_ < 1e300)) {    // the estimate broke down: report the iterate, unconverged
    this->op_.template velocities<Law>(rows, mu, u);
    this->rho_ = report_rho();
    residual_ready_ = false;
    return false;
  }

  // Nesterov momentum, dropped when it points uphill (gradient restart).
  double theta_next = 0.5 * (1.0 + std::sqrt(1.0 + 4.0 * theta_ * theta_));
  double beta = (theta_ - 1.0) / theta_next;
  if (sums[kRestartSum] > 0.0) {
    theta_next = 1.0;
    beta = 0.0;
  }
  double r = 0.0;
  for (const int c : rows) {
    for (int k = 0; k < B; ++k) {
      const size_t a = static_cast<size_t>(B) * c + k;
      y_[a] = next_[a] + beta * (next_[a] - mu[a]);
      gy_[a] = gnext_[a] + beta * (gnext_[a] - g[a]);
      mu[a] = next_[a];
      g[a] = gnext_[a];
    }
    r = std::max(r, this->set_violation(c, mu, r));
  }
  residual_ = r;
  residual_ready_ = true;
  theta_ = theta_next;
  L_ *= 0.9;    // let the estimate come back down where the problem is softer
  this->rho_ = report_rho();
  return true;
}

HARDCONTACT_INSTANTIATE_FOR_LAWS(ApgdSolver)

}    // namespace hardcontact
