// Helpers shared by the core tests: building contact rows from geometry, the physical
// quantities the properties of section 4 talk about (momentum, kinetic energy), the dense
// operators of section 3.3 (G, A = h^2 G M^-1 G^T) and two exact reference solvers that have
// nothing in common with Uzawa (pool-adjacent-violators for 1D chains, projected Gauss-Seidel
// on the dense dual). Header-only, so that every tests/core/test_*.cpp stays one executable.
#pragma once

#include "contact_problem.h"
#include "distributed_ops.h"
#include "solver.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <vector>

namespace hctest {

using hardcontact::ContactProblem;
using hardcontact::Vec3;

// A problem with n bodies, all owned (serial), no rows yet.
inline ContactProblem make_problem(double h, const std::vector<double> &inv_mass,
                                   const std::vector<Vec3> &u_free)
{
  ContactProblem p;
  p.h = h;
  p.inv_mass = inv_mass;
  p.u_free = u_free;
  p.n_owned = static_cast<int>(inv_mass.size());
  return p;
}

// Row between spheres i and j from their centres and radii (section 2: D_ij, e_ij).
inline void add_pair(ContactProblem &p, int i, int j, const Vec3 &qi, const Vec3 &qj, double ri,
                     double rj)
{
  const Vec3 d = qj - qi;
  const double dist = d.norm();
  p.add_contact(i, j, d / dist, dist - ri - rj, ri + rj);
}

// Row between sphere i and the plane through x0 whose unit normal nw points into the domain
// (Remark 4): D = (q - x0).nw - r, and the row normal points towards the wall, i.e. -nw.
inline void add_wall(ContactProblem &p, int i, const Vec3 &qi, double ri, const Vec3 &x0,
                     const Vec3 &nw)
{
  p.add_contact(i, -1, -nw, (qi - x0).dot(nw) - ri, ri);
}

// Total momentum sum m u over the movable bodies (Prop. 4).
inline Vec3 momentum(const ContactProblem &p, const std::vector<Vec3> &u)
{
  Vec3 P = Vec3::Zero();
  for (int b = 0; b < p.n_bodies(); ++b)
    if (p.inv_mass[b] > 0.0) P += u[b] / p.inv_mass[b];
  return P;
}

// sum m |u|, the scale against which momentum round-off is judged.
inline double momentum_scale(const ContactProblem &p, const std::vector<Vec3> &u)
{
  double s = 0.0;
  for (int b = 0; b < p.n_bodies(); ++b)
    if (p.inv_mass[b] > 0.0) s += u[b].norm() / p.inv_mass[b];
  return s;
}

// |u|_M^2 (twice the kinetic energy) over the movable bodies.
inline double energy2(const ContactProblem &p, const std::vector<Vec3> &u)
{
  double e = 0.0;
  for (int b = 0; b < p.n_bodies(); ++b)
    if (p.inv_mass[b] > 0.0) e += u[b].squaredNorm() / p.inv_mass[b];
  return e;
}

// |u - v|_M^2.
inline double dist2_M(const ContactProblem &p, const std::vector<Vec3> &u,
                      const std::vector<Vec3> &v)
{
  double e = 0.0;
  for (int b = 0; b < p.n_bodies(); ++b)
    if (p.inv_mass[b] > 0.0) e += (u[b] - v[b]).squaredNorm() / p.inv_mass[b];
  return e;
}

// Dense G (rows x 3N): row c is G_c = grad D_c, -n on body i, +n on body j (eq. 1).
inline Eigen::MatrixXd dense_G(const ContactProblem &p)
{
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(p.n_contacts(), 3 * p.n_bodies());
  for (int c = 0; c < p.n_contacts(); ++c) {
    G.block<1, 3>(c, 3 * p.body_i[c]) -= p.normal[c].transpose();
    if (p.body_j[c] >= 0) G.block<1, 3>(c, 3 * p.body_j[c]) += p.normal[c].transpose();
  }
  return G;
}

// Dense dual operator A = h^2 G M^-1 G^T (= C M^-1 C^T with C = -h G).
inline Eigen::MatrixXd dense_A(const ContactProblem &p)
{
  const Eigen::MatrixXd G = dense_G(p);
  Eigen::VectorXd w(3 * p.n_bodies());
  for (int b = 0; b < p.n_bodies(); ++b) w.segment<3>(3 * b).setConstant(p.inv_mass[b]);
  return p.h * p.h * G * w.asDiagonal() * G.transpose();
}

inline double lambda_max(const Eigen::MatrixXd &A)
{
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(A, Eigen::EigenvaluesOnly);
  return es.eigenvalues().maxCoeff();
}

// Largest |M (u - u_free) - h sum mu G| over the bodies, computed from dense G: eq. 16 checked
// with code that is not the core's.
inline double eq16_defect(const ContactProblem &p, const std::vector<double> &mu,
                          const std::vector<Vec3> &u)
{
  const Eigen::MatrixXd G = dense_G(p);
  const Eigen::VectorXd m = Eigen::Map<const Eigen::VectorXd>(mu.data(), mu.size());
  const Eigen::VectorXd F = p.h * G.transpose() * m;
  double worst = 0.0;
  for (int b = 0; b < p.n_bodies(); ++b) {
    if (p.inv_mass[b] == 0.0) {
      worst = std::max(worst, (u[b] - p.u_free[b]).norm());
      continue;
    }
    const Vec3 d = (u[b] - p.u_free[b]) / p.inv_mass[b] - Vec3(F.segment<3>(3 * b));
    worst = std::max(worst, d.norm());
  }
  return worst;
}

// Exact reference solver 1: weighted isotonic regression (pool adjacent violators).
// Returns the non-decreasing z minimising sum w_k (z_k - y_k)^2.
inline std::vector<double> isotonic(const std::vector<double> &y, const std::vector<double> &w)
{
  struct Block {
    double value, weight;
    int count;
  };
  std::vector<Block> blocks;
  for (size_t k = 0; k < y.size(); ++k) {
    blocks.push_back({y[k], w[k], 1});
    while (blocks.size() > 1 && blocks[blocks.size() - 2].value > blocks.back().value) {
      const Block b = blocks.back();
      blocks.pop_back();
      Block &a = blocks.back();
      a.value = (a.value * a.weight + b.value * b.weight) / (a.weight + b.weight);
      a.weight += b.weight;
      a.count += b.count;
    }
  }
  std::vector<double> z;
  for (const Block &b : blocks) z.insert(z.end(), b.count, b.value);
  return z;
}

// The projection of scheme (S) for bodies on the x axis, ordered, each row coupling
// neighbours k, k+1 with gap_k: D_k + h (u_{k+1} - u_k) >= 0 is y_k <= y_{k+1} with
// y_k = u_k + (sum_{l<k} D_l) / h, so the M-projection is the isotonic regression of y.
inline std::vector<double> chain_projection(const std::vector<double> &u_free,
                                            const std::vector<double> &gaps,
                                            const std::vector<double> &mass, double h)
{
  const size_t n = u_free.size();
  std::vector<double> offset(n, 0.0), y(n);
  for (size_t k = 1; k < n; ++k) offset[k] = offset[k - 1] + gaps[k - 1];
  for (size_t k = 0; k < n; ++k) y[k] = u_free[k] + offset[k] / h;
  std::vector<double> z = isotonic(y, mass);
  for (size_t k = 0; k < n; ++k) z[k] -= offset[k] / h;
  return z;
}

// Exact reference solver 2: projected Gauss-Seidel on the dense dual
// min 1/2 mu.A mu + mu.g0, mu >= 0 (g0 = predicted gaps at u_free). Returns u from eq. 16.
inline std::vector<Vec3> pgs_solve(const ContactProblem &p, int sweeps,
                                   std::vector<double> *mu_out = nullptr)
{
  const Eigen::MatrixXd A = dense_A(p);
  const int nc = p.n_contacts();
  Eigen::VectorXd g0(nc);
  for (int c = 0; c < nc; ++c) g0[c] = p.predicted_gap(c, p.u_free);
  Eigen::VectorXd mu = Eigen::VectorXd::Zero(nc);
  Eigen::VectorXd Amu = Eigen::VectorXd::Zero(nc);
  for (int s = 0; s < sweeps; ++s)
    for (int c = 0; c < nc; ++c) {
      if (A(c, c) <= 0.0) continue;
      const double next = std::max(0.0, mu[c] - (Amu[c] + g0[c]) / A(c, c));
      const double d = next - mu[c];
      if (d != 0.0) {
        Amu += d * A.col(c);
        mu[c] = next;
      }
    }
  const Eigen::VectorXd F = p.h * dense_G(p).transpose() * mu;
  std::vector<Vec3> u(p.n_bodies());
  for (int b = 0; b < p.n_bodies(); ++b)
    u[b] = p.u_free[b] + p.inv_mass[b] * Vec3(F.segment<3>(3 * b));
  if (mu_out) mu_out->assign(mu.data(), mu.data() + nc);
  return u;
}

inline double max_diff(const std::vector<Vec3> &a, const std::vector<Vec3> &b)
{
  double d = 0.0;
  for (size_t k = 0; k < a.size(); ++k) d = std::max(d, (a[k] - b[k]).norm());
  return d;
}

}    // namespace hctest
