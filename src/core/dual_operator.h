// The only code that applies G and G^T of eq. 15-16 (G_c = grad D_c: -n_c on body i, +n_c on
// body j, eq. 1), so that every solver shares one definition of the dual operator
// A = h^2 G M^-1 G^T of section 3.3. Bound to a problem once per solve; its scratch (degrees)
// is kept between solves, so no call allocates once sizes have settled. Each law owns its rows
// of G (laws/normal.h, laws/disc_law.h: gap_block, apply_block, block_diagonal(s),
// add_forces): the operator loops over rows and bodies, whatever the law.
#pragma once

#include "contact_problem.h"
#include "container_bytes.h"
#include "distributed_ops.h"
#include "laws/normal.h"

#include <Eigen/SparseCore>

#include <algorithm>
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
  // side applies its own half exactly once. Law: the rows' law (Law::block multipliers per row,
  // mu[B c..]).
  template <class Law = NormalLaw>
  void velocities(const std::vector<int> &rows, const std::vector<double> &mu,
                  std::vector<Vec3> &u) const
  {
    constexpr int B = Law::block;
    velocities_with<Law>(rows, [&](int c) { return &mu[static_cast<size_t>(B) * c]; }, u);
  }
  // The same with each row's block computed as the row is applied (mu_of(c) -> pointer to
  // its B multipliers): a solver's update of mu fused into the one pass over the rows.
  template <class Law = NormalLaw, class MuOf>
  void velocities_with(const std::vector<int> &rows, MuOf &&mu_of, std::vector<Vec3> &u) const
  {
    constexpr int B = Law::block;
    start_velocities(u);
    if constexpr (B == 1) {    // the paper's law: one row per contact, its kernel inlined
      const RowKernel k(*p_);
      double *v = doubles(u);
      for (const int c : rows) {
        const double *m = mu_of(c);
        if (m[0] != 0.0) k.apply(c, m[0], v);
      }
    } else {
      for (const int c : rows) {
        const double *m = mu_of(c);
        if (nonzero<B>(m)) Law::apply_block(*p_, c, m, u);
      }
    }
    forward(u);
  }
  // The same over every row.
  template <class Law = NormalLaw>
  void velocities(const std::vector<double> &mu, std::vector<Vec3> &u) const
  {
    constexpr int B = Law::block;
    start_velocities(u);
    const int nc = p_->n_contacts();
    for (int c = 0; c < nc; ++c) {
      const double *m = &mu[static_cast<size_t>(B) * c];
      if (nonzero<B>(m)) Law::apply_block(*p_, c, m, u);
    }
    forward(u);
  }
  // w = h M^-1 G^T m over the listed rows, from rest (no u_free): the velocity change of the
  // impulses m alone, so that h G_c w is A m (Krylov solvers). Ghosts from their owners.
  // moved: when given, the owned bodies the rows touch, and w must be 0 on every other owned
  // body (the caller zeroed it once): only these are cleared, so a product costs the rows and
  // their bodies, not every body (a bed forming under a million falling spheres).
  template <class MOf>
  void impulse_velocities_with(const std::vector<int> &rows, MOf &&m_of, std::vector<Vec3> &w,
                               const std::vector<int> *moved = nullptr) const
  {
    const ContactProblem &p = *p_;
    w.resize(p.n_dof());
    const int nb = p.n_bodies();
    if (moved == nullptr) {
      std::fill(w.begin(), w.begin() + p.n_owned, Vec3::Zero());
      if (p.rotates()) std::fill(w.begin() + nb, w.begin() + nb + p.n_owned, Vec3::Zero());
    } else {
      for (const int b : *moved) w[b] = Vec3::Zero();
      if (p.rotates())
        for (const int b : *moved) w[nb + b] = Vec3::Zero();
    }
    const RowKernel k(p);
    double *v = doubles(w);
    for (const int c : rows) {
      const double m = m_of(c);
      if (m != 0.0) k.apply(c, m, v);
    }
    forward(w);
  }
  // u = u_free (mu = 0).
  void free_velocities(std::vector<Vec3> &u) const
  {
    start_velocities(u);
    forward(u);
  }
  // Ghost copies of u from their owners (after in-place updates with apply()).
  void forward(std::vector<Vec3> &u) const
  {
    ops_->forward(doubles(u), 3, p_->rotates() ? 2 : 1, 3L * p_->n_bodies());
  }

  // g_c(u) = D_c + h G_c u, eq. 15: also the gradient of the dual objective at mu(u).
  double gap(int c, const std::vector<Vec3> &u) const { return p_->predicted_gap(c, u); }
  // The Law::block components of h G_c u + D_c for row c: the gap, then (friction) the
  // discs' (laws/disc_rows.h). Linear in u: De Saxce's shift of the gap (laws/disc_law.h) is
  // the solver's (IterativeSolver::gradient_block).
  template <class Law>
  void gap_block(int c, const std::vector<Vec3> &u, double *g) const
  {
    Law::gap_block(*p_, c, u, g);
  }
  // Adds the velocity change of an impulse h dmu G_c to the owned bodies of row c.
  void apply(int c, double dmu, std::vector<Vec3> &u) const
  {
    RowKernel(*p_).apply(c, dmu, doubles(u));
  }
  // The same for a block of the law's multipliers.
  template <class Law>
  void apply_block(int c, const double *dm, std::vector<Vec3> &u) const
  {
    Law::apply_block(*p_, c, dm, u);
  }

  // A_cc = h^2 (w_i + w_j): the exact step along one row (Gauss-Seidel).
  double diagonal(int c) const { return NormalLaw::block_diagonal(*p_, c); }
  // At least the largest eigenvalue of the block A_cc (the law's bound).
  template <class Law>
  double block_diagonal(int c) const
  {
    return Law::block_diagonal(*p_, c);
  }
  // The diagonal of the block A_cc, d[0..B).
  template <class Law>
  void block_diagonals(int c, double *d) const
  {
    Law::block_diagonals(*p_, c, d);
  }
  // Gershgorin: the off-diagonal entries of row c are h^2 w_k n_c.n_d for rows d sharing body
  // k, so |A_cc| + sum |A_cd| <= h^2 (w_i deg_i + w_j deg_j) with deg_k the rows touching k.
  // With friction each of the B components of a row meets B of every row d on body k, each
  // entry at most w_k + A_k^2 / I_k, A_k the longest arm on k (a rolling radius is shorter
  // than either arm). count_degrees() over the listed
  // rows first (owners count, ghosts receive: an owner holds every row of its own bodies).
  void count_degrees(const std::vector<int> &rows);
  template <class Law = NormalLaw>
  double gershgorin_row(int c) const
  {
    constexpr int B = Law::block;
    const ContactProblem &p = *p_;
    const int i = p.body_i[c], j = p.body_j[c];
    if constexpr (B == 1) {
      double row = p.inv_mass[i] * deg_[i];
      if (!is_wall(j)) row += p.inv_mass[j] * deg_[j];
      return p.h * p.h * row;
    } else {
      double row = body_weight(i) * deg_[i];
      if (!is_wall(j)) row += body_weight(j) * deg_[j];
      return B * p.h * p.h * row;
    }
  }
  // L >= largest eigenvalue of A restricted to the listed rows, over all processes (Remark 8
  // for any radii and masses: 2 kappa h^2 / m with equal masses and kappa rows per body).
  // 0 when there is no row. Counts degrees.
  template <class Law = NormalLaw>
  double bound(const std::vector<int> &rows)
  {
    count_degrees(rows);
    double b = 0.0;
    for (const int c : rows) {
      const double r = gershgorin_row<Law>(c);
      b = b > r ? b : r;
    }
    return ops_->max_all(b);
  }

  // The assembled A over every row, for direct solvers (normal law); ghosts count as their
  // owned copy (ContactProblem::owner; throws if a body is owned by another process).
  Eigen::SparseMatrix<double> assembled() const;

  // sum_c G_c^T mu_c on each owned body: the contact force (eq. 16 divided by h), per body,
  // and with friction the contact torque (torque: null to skip).
  template <class Law = NormalLaw>
  void forces(const std::vector<double> &mu, std::vector<Vec3> &force,
              std::vector<Vec3> *torque = nullptr) const;

  double memory_usage() const { return bytes_of(deg_, arm2_); }

 private:
  // u = u_free on the owned bodies (their velocities, then their spins).
  void start_velocities(std::vector<Vec3> &u) const
  {
    const ContactProblem &p = *p_;
    const int nb = p.n_bodies();
    u.resize(p.n_dof());
    for (int b = 0; b < p.n_owned; ++b) u[b] = p.u_free[b];
    if (p.rotates())
      for (int b = 0; b < p.n_owned; ++b) u[nb + b] = p.u_free[nb + b];
  }
  template <int B>
  static bool nonzero(const double *m)
  {
    for (int k = 0; k < B; ++k)
      if (m[k] != 0.0) return true;
    return false;
  }
  // w + A^2 / I: bounds the inverse effective mass of a body's contact points in a
  // tangential direction (A^2 from count_degrees)
  double body_weight(int b) const
  {
    const ContactProblem &p = *p_;
    return p.inv_mass[b] + (p.rotates() ? p.inv_inertia[b] * arm2_[b] : 0.0);
  }

  const ContactProblem *p_ = nullptr;
  DistributedOps *ops_ = nullptr;
  std::vector<double> deg_;      // per body, from count_degrees()
  std::vector<double> arm2_;     // per body, the longest arm squared (friction), ditto
};

// One-off forms of the above, for the host and tests (they bind an operator of their own).
double dual_operator_bound(const ContactProblem &p, DistributedOps &ops);
double dual_operator_bound(const ContactProblem &p, const std::vector<int> &rows,
                           DistributedOps &ops);
template <class Law = NormalLaw>
void contact_forces(const ContactProblem &p, const std::vector<double> &mu,
                    std::vector<Vec3> &force, std::vector<Vec3> *torque = nullptr);

}    // namespace hardcontact
