// Random sphere packings in a box for the property tests: fixed seeds, radii in [0.5, 1],
// masses log-uniform in [1, 1000], random u_free in [-1, 1]^3, and one row per pair (and per
// sphere-wall couple) that could meet within the step (Remark 7). The micro-benchmarks
// (bench/micro/) build their problems with it too.
#pragma once

#include "core_test_util.h"

#include <cmath>
#include <random>
#include <vector>

namespace hctest {

struct RandomConfig {
  ContactProblem p;
  std::vector<Vec3> q;
  std::vector<double> r;
};

struct RandomConfigOptions {
  int n = 300;
  double box = 12.0;      // cube [0, box]^3
  bool walls = true;      // the six faces are walls (rows for spheres near them)
  double max_overlap = 0.0;    // > 0: pairs may overlap by up to this much (gap >= -it)
  double h = 0.2;
  double mass_decades = 3.0;    // masses 10^[0, mass_decades]
};

// Spheres of the problem get I = 2/5 m r^2, spin w_free, and every row the coefficient mu
// (the rows' frames completed: call it after the rows are made).
inline void add_friction(ContactProblem &p, const std::vector<double> &r, double mu,
                         const std::vector<Vec3> &w_free = {})
{
  const int n = p.n_bodies();
  p.radius = r;
  p.inv_inertia.resize(n);
  for (int b = 0; b < n; ++b) p.inv_inertia[b] = p.inv_mass[b] / (0.4 * r[b] * r[b]);
  p.u_free.resize(2 * static_cast<size_t>(n), Vec3::Zero());    // the spins after the velocities
  if (!w_free.empty()) std::copy(w_free.begin(), w_free.end(), p.u_free.begin() + n);
  p.friction.assign(p.n_contacts(), mu);
  p.complete_frames(0);
}

inline RandomConfig random_config(unsigned seed, const RandomConfigOptions &o)
{
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> U01(0.0, 1.0), U(-1.0, 1.0);
  RandomConfig c;
  auto overlaps_any = [&](const Vec3 &x, double rx) {
    for (size_t k = 0; k < c.q.size(); ++k)
      if ((c.q[k] - x).norm() < c.r[k] + rx - o.max_overlap) return true;
    return false;
  };
  int guard = 0;
  while (static_cast<int>(c.q.size()) < o.n && guard++ < 200 * o.n) {
    const double rx = 0.5 + 0.5 * U01(gen);
    Vec3 x;
    if (!c.q.empty() && U01(gen) < 0.6) {
      // Next to an existing sphere, almost touching (gap in [-max_overlap, 0.05]).
      const int k = static_cast<int>(U01(gen) * c.q.size()) % static_cast<int>(c.q.size());
      Vec3 d(U(gen), U(gen), U(gen));
      if (d.norm() < 1e-3) continue;
      const double gap = -o.max_overlap + (0.05 + o.max_overlap) * U01(gen);
      x = c.q[k] + (c.r[k] + rx + gap) * d.normalized();
    } else {
      x = Vec3(U01(gen), U01(gen), U01(gen)) * o.box;
    }
    bool inside = true;
    for (int a = 0; a < 3; ++a) inside = inside && x[a] >= rx && x[a] <= o.box - rx;
    if (!inside) continue;
    if (overlaps_any(x, rx)) continue;
    c.q.push_back(x);
    c.r.push_back(rx);
  }
  const int n = static_cast<int>(c.q.size());
  std::vector<double> w(n);
  std::vector<Vec3> uf(n);
  for (int b = 0; b < n; ++b) {
    w[b] = std::pow(10.0, -o.mass_decades * U01(gen));
    uf[b] = Vec3(U(gen), U(gen), U(gen));
  }
  c.p = make_problem(o.h, w, uf);
  // Candidate rows: anything that can close within the step, |du| <= 2 sqrt(3).
  const double skin = o.h * 2.0 * std::sqrt(3.0);
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if ((c.q[j] - c.q[i]).norm() - c.r[i] - c.r[j] < skin)
        add_pair(c.p, i, j, c.q[i], c.q[j], c.r[i], c.r[j]);
  if (o.walls)
    for (int i = 0; i < n; ++i)
      for (int a = 0; a < 3; ++a) {
        Vec3 nw = Vec3::Zero();
        nw[a] = 1.0;
        if (c.q[i][a] - c.r[i] < 0.5 * skin) add_wall(c.p, i, c.q[i], c.r[i], Vec3::Zero(), nw);
        if (o.box - c.q[i][a] - c.r[i] < 0.5 * skin)
          add_wall(c.p, i, c.q[i], c.r[i], Vec3::Constant(o.box), -nw);
      }
  return c;
}

}    // namespace hctest
