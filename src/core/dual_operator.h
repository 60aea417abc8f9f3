// The only code that applies G and G^T of eq. 15-16 (G_c = grad D_c: -n_c on body i, +n_c on
// body j, eq. 1), so that every solver shares one definition of the dual operator
// A = h^2 G M^-1 G^T of section 3.3. Bound to a problem once per solve; its scratch (degrees)
// is kept between solves, so no call allocates once sizes have settled.
#pragma once

#include "contact_problem.h"
#include "distributed_ops.h"

#include <Eigen/SparseCore>

#include <vector>

namespace hardcontact {

class DualOperator {
 public:
  void bind(const ContactProblem &p, DistributedOps &ops)
  {
    p_ = &p;
    ops_ = &ops;
  }
  const ContactProblem &problem() const { return *p_; }
  DistributedOps &ops() const { return *ops_; }

  // Eq. 16: u = u_free + h M^-1 G^T mu over the listed rows (rows outside hold mu = 0), for
  // owned bodies, then the ghosts' u from their owners. Each row pushes only its owned bodies:
  // a row coupling an owned body with a ghost is held by both processes (newton off), so each
  // side applies its own half exactly once.
  void velocities(const std::vector<int> &rows, const std::vector<double> &mu,
                  std::vector<Vec3> &u) const;
  // The same with each row's multiplier computed as the row is applied (mu_of(c) -> mu_c): a
  // solver's update of mu fused into the one pass over the rows.
  template <class MuOf>
  void velocities_with(const std::vector<int> &rows, MuOf &&mu_of, std::vector<Vec3> &u) const
  {
    u.resize(p_->n_bodies());
    for (int b = 0; b < p_->n_owned; ++b) u[b] = p_->u_free[b];
    for (const int c : rows) {
      const double m = mu_of(c);
      if (m != 0.0) apply(c, m, u);
    }
    forward(u);
  }
  // The same over every row.
  void velocities(const std::vector<double> &mu, std::vector<Vec3> &u) const;
  // u = u_free (mu = 0).
  void free_velocities(std::vector<Vec3> &u) const;
  // Ghost copies of u from their owners (after in-place updates with apply()).
  void forward(std::vector<Vec3> &u) const { ops_->forward(u.data()->data(), 3); }

  // g_c(u) = D_c + h G_c u, eq. 15: also the gradient of the dual objective at mu(u).
  double gap(int c, const std::vector<Vec3> &u) const { return p_->predicted_gap(c, u); }
  // Adds the velocity change of an impulse h dmu G_c to the owned bodies of row c.
  void apply(int c, double dmu, std::vector<Vec3> &u) const
  {
    const ContactProblem &p = *p_;
    const Vec3 impulse = (p.h * dmu) * p.normal[c];
    const int i = p.body_i[c], j = p.body_j[c];
    if (i < p.n_owned) u[i] -= p.inv_mass[i] * impulse;
    if (j >= 0 && j < p.n_owned) u[j] += p.inv_mass[j] * impulse;
  }

  // A_cc = h^2 (w_i + w_j): the exact step along one row (Gauss-Seidel).
  double diagonal(int c) const
  {
    const ContactProblem &p = *p_;
    const int j = p.body_j[c];
    return p.h * p.h * (p.inv_mass[p.body_i[c]] + (is_wall(j) ? 0.0 : p.inv_mass[j]));
  }
  // Gershgorin: the off-diagonal entries of row c are h^2 w_k n_c.n_d for rows d sharing body
  // k, so |A_cc| + sum |A_cd| <= h^2 (w_i deg_i + w_j deg_j) with deg_k the rows touching k.
  // count_degrees() over the listed rows first (owners count, ghosts receive: an owner holds
  // every row of its own bodies).
  void count_degrees(const std::vector<int> &rows);
  double gershgorin_row(int c) const
  {
    const ContactProblem &p = *p_;
    const int i = p.body_i[c], j = p.body_j[c];
    double row = p.inv_mass[i] * deg_[i];
    if (!is_wall(j)) row += p.inv_mass[j] * deg_[j];
    return p.h * p.h * row;
  }
  // L >= largest eigenvalue of A restricted to the listed rows, over all processes (Remark 8
  // for any radii and masses: 2 kappa h^2 / m with equal masses and kappa rows per body).
  // 0 when there is no row. Counts degrees.
  double bound(const std::vector<int> &rows);

  // The assembled A over every row, for direct solvers; ghosts count as their owned copy
  // (ContactProblem::owner; throws if a body is owned by another process).
  Eigen::SparseMatrix<double> assembled() const;

  // sum_c mu_c G_c on each owned body: the contact force (eq. 16 divided by h), per body.
  void forces(const std::vector<double> &mu, std::vector<Vec3> &force) const;

 private:
  const ContactProblem *p_ = nullptr;
  DistributedOps *ops_ = nullptr;
  std::vector<double> deg_;    // per body, from count_degrees()
};

// One-off forms of the above, for the host and tests (they bind an operator of their own).
double dual_operator_bound(const ContactProblem &p, DistributedOps &ops);
double dual_operator_bound(const ContactProblem &p, const std::vector<int> &rows,
                           DistributedOps &ops);
void contact_forces(const ContactProblem &p, const std::vector<double> &mu,
                    std::vector<Vec3> &force);

}    // namespace hardcontact
