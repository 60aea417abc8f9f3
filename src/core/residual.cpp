#include "residual.h"

#include <algorithm>
#include <cmath>

namespace hardcontact {

double free_speed_scale(const ContactProblem &p, DistributedOps &ops)
{
  double v = 0.0;
  const int nc = p.n_contacts();
  for (int c = 0; c < nc; ++c) v = std::max(v, std::abs(p.normal_speed(c, p.u_free)));
  return ops.max_all(v);
}

double contact_speed_scale(const ContactProblem &p, DistributedOps &ops)
{
  double v = 0.0;
  const int nc = p.n_contacts();
  for (int c = 0; c < nc; ++c) v = std::max(v, p.slip_velocity(c, p.u_free).norm());
  return ops.max_all(v);
}

double row_scales(const ContactProblem &p, double tol, DistributedOps &ops,
                  std::vector<double> &scale)
{
  const double v = p.speed_scale >= 0.0 ? p.speed_scale : free_speed_scale(p, ops);
  const int nc = p.n_contacts();
  scale.resize(nc);
  for (int c = 0; c < nc; ++c) scale[c] = row_scale(p.size[c], p.h, v, tol, p.gap_roundoff);
  return v;
}

double clearing_work(const ContactProblem &p, const std::vector<double> &mu, int block)
{
  double work = 0.0;
  const int nc = p.n_contacts();
  for (int c = 0; c < nc; ++c) {
    const double *m = &mu[static_cast<size_t>(block) * c];
    if (!p.counted[c] || m[0] <= 0.0) continue;
    work += m[0] * std::max(0.0, -p.target[c]);
    // A wall sliding under a sphere (tangential velocity w_t) works on it through friction:
    // its share of the affine term, -h (m_1 t_1 + m_2 t_2) . w, where that is positive.
    if (block > 1 && !p.wall_velocity.empty() && is_wall(p.body_j[c])) {
      const Vec3 &w = p.wall_velocity[c];
      const double b = p.h * (m[1] * p.tangent1[c].dot(w) + m[2] * p.tangent2[c].dot(w));
      work += std::max(0.0, -b);
    }
  }
  return work;
}

bool energy_within_bound(const ContactProblem &p, const std::vector<double> &mu,
                         const std::vector<Vec3> &u, DistributedOps &ops, int block)
{
  // sums: gain of kinetic energy, kinetic energy of u_free, allowed work (each body and each
  // row counted once over all processes)
  double sums[3] = {0.0, 0.0, clearing_work(p, mu, block)};
  for (int b = 0; b < p.n_owned; ++b) {
    if (p.inv_mass[b] <= 0.0) continue;    // an obstacle: u = u_free
    const double m = 1.0 / p.inv_mass[b];
    sums[0] += 0.5 * m * (u[b] - p.u_free[b]).dot(u[b] + p.u_free[b]);
    sums[1] += 0.5 * m * p.u_free[b].squaredNorm();
  }
  if (p.rotates()) {
    const int nb = p.n_bodies();
    for (int b = 0; b < p.n_owned; ++b) {
      if (p.inv_inertia[b] <= 0.0) continue;
      const double inertia = 1.0 / p.inv_inertia[b];
      const Vec3 &w_free = p.u_free[nb + b];
      sums[0] += 0.5 * inertia * (u[nb + b] - w_free).dot(u[nb + b] + w_free);
      sums[1] += 0.5 * inertia * w_free.squaredNorm();
    }
  }
  const int nc = p.n_contacts();
  for (int c = 0; c < nc; ++c) {
    const double mc = mu[static_cast<size_t>(block) * c];
    if (!p.counted[c] || mc <= 0.0) continue;
    sums[2] += mc * p.gap_roundoff;
    // round-off: the kinetic energy of moving the pair kGapRoundoff size apart in one step
    const int i = p.body_i[c], j = p.body_j[c];
    const double w = p.inv_mass[i] + (j >= 0 ? p.inv_mass[j] : 0.0);
    const double v = kGapRoundoff * p.size[c] / p.h;
    if (w > 0.0) sums[2] += 0.5 * v * v / w;
  }
  ops.sum_all(sums, 3);
  return sums[0] <= sums[2] + kEnergyRoundoff * sums[1];
}

}    // namespace hardcontact
