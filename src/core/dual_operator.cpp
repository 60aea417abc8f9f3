#include "dual_operator.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace hardcontact {

void DualOperator::free_velocities(std::vector<Vec3> &u) const
{
  u.resize(p_->n_bodies());
  for (int b = 0; b < p_->n_owned; ++b) u[b] = p_->u_free[b];
  forward(u);
}

void DualOperator::velocities(const std::vector<int> &rows, const std::vector<double> &mu,
                              std::vector<Vec3> &u) const
{
  u.resize(p_->n_bodies());
  for (int b = 0; b < p_->n_owned; ++b) u[b] = p_->u_free[b];
  for (const int c : rows)
    if (mu[c] != 0.0) apply(c, mu[c], u);
  forward(u);
}

void DualOperator::velocities(const std::vector<double> &mu, std::vector<Vec3> &u) const
{
  u.resize(p_->n_bodies());
  for (int b = 0; b < p_->n_owned; ++b) u[b] = p_->u_free[b];
  const int nc = p_->n_contacts();
  for (int c = 0; c < nc; ++c)
    if (mu[c] != 0.0) apply(c, mu[c], u);
  forward(u);
}

void DualOperator::count_degrees(const std::vector<int> &rows)
{
  const ContactProblem &p = *p_;
  deg_.assign(p.n_bodies(), 0.0);
  for (const int c : rows) {
    const int i = p.body_i[c], j = p.body_j[c];
    if (i < p.n_owned) deg_[i] += 1.0;
    if (j >= 0 && j < p.n_owned) deg_[j] += 1.0;
  }
  ops_->forward(deg_.data(), 1);
}

double DualOperator::bound(const std::vector<int> &rows)
{
  count_degrees(rows);
  double b = 0.0;
  for (const int c : rows) b = std::max(b, gershgorin_row(c));
  return ops_->max_all(b);
}

Eigen::SparseMatrix<double> DualOperator::assembled() const
{
  const ContactProblem &p = *p_;
  const int nc = p.n_contacts();
  auto body_of = [&](int b) {
    if (b < p.n_owned) return b;
    const int o = p.owner.empty() ? -1 : p.owner[b];
    if (o < 0) throw std::runtime_error("the assembled operator needs every body on one process");
    return o;
  };
  // rows c and d sharing body k couple by h^2 w_k s_c s_d n_c.n_d, s = -1 on i, +1 on j
  std::vector<std::vector<std::pair<int, double>>> rows_of(p.n_owned);    // (row, sign)
  for (int c = 0; c < nc; ++c) {
    rows_of[body_of(p.body_i[c])].push_back({c, -1.0});
    if (p.body_j[c] >= 0) rows_of[body_of(p.body_j[c])].push_back({c, 1.0});
  }
  std::vector<Eigen::Triplet<double>> t;
  const double h2 = p.h * p.h;
  for (int k = 0; k < p.n_owned; ++k) {
    const double w = h2 * p.inv_mass[k];
    if (w == 0.0) continue;
    for (const auto &a : rows_of[k])
      for (const auto &b : rows_of[k])
        t.emplace_back(a.first, b.first,
                       w * a.second * b.second * p.normal[a.first].dot(p.normal[b.first]));
  }
  Eigen::SparseMatrix<double> A(nc, nc);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

void DualOperator::forces(const std::vector<double> &mu, std::vector<Vec3> &force) const
{
  const ContactProblem &p = *p_;
  force.assign(p.n_bodies(), Vec3::Zero());
  const int nc = p.n_contacts();
  for (int c = 0; c < nc; ++c) {
    if (mu[c] == 0.0) continue;
    const Vec3 f = mu[c] * p.normal[c];
    const int i = p.body_i[c], j = p.body_j[c];
    if (i < p.n_owned) force[i] -= f;
    if (j >= 0 && j < p.n_owned) force[j] += f;
  }
}

double dual_operator_bound(const ContactProblem &p, const std::vector<int> &rows,
                           DistributedOps &ops)
{
  DualOperator op;
  op.bind(p, ops);
  return op.bound(rows);
}

double dual_operator_bound(const ContactProblem &p, DistributedOps &ops)
{
  std::vector<int> all(p.n_contacts());
  for (int c = 0; c < p.n_contacts(); ++c) all[c] = c;
  return dual_operator_bound(p, all, ops);
}

void contact_forces(const ContactProblem &p, const std::vector<double> &mu,
                    std::vector<Vec3> &force)
{
  SerialOps none;    // forces need no communication
  DualOperator op;
  op.bind(p, none);
  op.forces(mu, force);
}

}    // namespace hardcontact
