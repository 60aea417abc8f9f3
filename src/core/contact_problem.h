// The contact problem of one time step of scheme (S): everything the projection of eq. 14-15
// needs, as flat arrays (structure of arrays), with no knowledge of the host code.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <vector>

namespace hardcontact {

using Vec3 = Eigen::Vector3d;
static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 arrays are exchanged as raw doubles");

// The doubles of a Vec3 array, 3 per element (nullptr when empty: v.data()->data() would call
// a member function through a null pointer, which UBSan reports, on a process without atoms).
inline double *doubles(std::vector<Vec3> &v) { return v.empty() ? nullptr : v[0].data(); }
inline const double *doubles(const std::vector<Vec3> &v)
{
  return v.empty() ? nullptr : v[0].data();
}

// Bodies 0..n_owned-1 are integrated here; bodies n_owned..n_bodies()-1 are copies owned
// elsewhere (ghosts): their velocities arrive through DistributedOps::forward.
// inv_mass = 0 marks a body whose velocity the contacts cannot change (an obstacle).
//
// Row c couples body i[c] with body j[c], or body i[c] with wall w when j[c] = wall_body(w) < 0
// (the one place that encoding is defined). With unit normal n pointing from i towards j
// (towards the wall), the linearised non-overlap constraint of eq. 15 reads
//   g_c(u) = gap_c + h n_c . (u_j - u_i) >= 0        (u_wall = 0),
// i.e. D_ij(q^n) + h G_ij(q^n) . u >= 0 with G_ij = grad D_ij (eq. 1). The solvers read the
// affine part as target_c: gap_c itself unless the host's target terms moved it (an overlap's
// clearing, a moving wall, restitution: targets.h), which leave gap_c as measured.
// The j of a row against wall w (w = 0, 1, ... in the host's order), and back.
constexpr int wall_body(int w) { return -1 - w; }
constexpr bool is_wall(int j) { return j < 0; }
constexpr int wall_index(int j) { return -1 - j; }

// Room for the resistances a frictional law composes beyond Coulomb's tangential disc (rolling,
// twisting, ...: laws/law_list.h, HARDCONTACT_RESISTANCES); each takes its own index.
constexpr int kResistances = 4;

struct ContactProblem {
  double h = 0.0;    // time step
  int n_owned = 0;
  std::vector<double> inv_mass;    // per body
  // u^n + h M^-1 f (eq. 14), laid out as every velocity vector (n_dof()): per body, then with
  // friction each body's spin omega^n + h I^-1 torque
  std::vector<Vec3> u_free;
  // Optional, for solvers that assemble the operator (exact): owner[b] = the owned body that
  // ghost b copies (a periodic image on this process), -1 if owned elsewhere. Empty = unknown.
  std::vector<int> owner;
  // Absolute round-off of a predicted gap (distance units), from the host's coordinates and
  // speeds; 0 if unknown. No solver is asked for a gap error below it (residual.h).
  double gap_roundoff = 0.0;
  // V, the free speed scale of the rows (residual.h, free_speed_scale), when the host has
  // found it for this solve round (it needs V itself, for its targets): the solver then
  // takes it instead of reducing it again. Negative: unknown, the solver finds it.
  double speed_scale = -1.0;
  // Friction: the slip conditions are measured against the contact points' speed V_t, the gap
  // conditions against the approach V (residual.h, contact_speed_scale;
  // SolverSettings::contact_speed, the fix's `speed contact`).
  bool contact_speed_scale = false;
  // The bodies may be numbered differently from the last solve's problem (the host's new
  // neighbour list moved them): what a solver keeps per row from one solve to the next
  // (ProjectedCg's subspace) is then stale. True unless the host knows better.
  bool renumbered = true;

  std::vector<int> body_i, body_j;
  std::vector<Vec3> normal;
  std::vector<double> gap;     // D_c(q^n), distance units, as the host measured it
  // what the solvers ask of row c: target_c + h G_c u >= 0 (eq. 15; gap_c where no target term
  // applies, targets.h)
  std::vector<double> target;
  std::vector<double> size;    // r_i + r_j (r_i for a wall): the scale of the tolerance
  // 1 if this process counts row c in global sums. A row coupling an owned body with a ghost
  // is held by both processes; exactly one of them counts it.
  std::vector<char> counted;

  // Friction (laws/coulomb.h), present only when a scene asks for it. The bodies then rotate:
  // a velocity vector holds n_bodies() linear velocities followed by n_bodies() angular ones
  // (n_dof(), u_free too). Per body: 1/I (0 for an obstacle), the radius. Per row: the
  // Coulomb coefficient, two tangents completing the normal to an orthonormal frame, and the
  // arms from each centre to the contact point (complete_frames).
  std::vector<double> inv_inertia;
  std::vector<double> radius;
  std::vector<double> friction;
  // per resistance r (rolling, twisting, ...: laws/disc_rows.h) its coefficient per row, empty
  // when no law of the scene reads it
  std::vector<double> resistance[kResistances];
  std::vector<Vec3> tangent1, tangent2;
  std::vector<double> arm_i, arm_j;

  // Moving obstacles, present only when a wall moves: per row, the velocity of the wall at
  // the contact point (zero on pair rows). Its normal part moves the row's target (Targets
  // adds h n . u_wall, core/targets.h); its tangential part is the wall's share of
  // the slip (a rotating drum drags the grains it touches).
  std::vector<Vec3> wall_velocity;

  bool rotates() const { return !inv_inertia.empty(); }
  // Length of a velocity vector: linear velocities, then angular ones if the bodies rotate.
  int n_dof() const { return rotates() ? 2 * n_bodies() : n_bodies(); }
  int n_bodies() const { return static_cast<int>(inv_mass.size()); }
  int n_contacts() const { return static_cast<int>(body_i.size()); }

  void clear_contacts()
  {
    body_i.clear();
    body_j.clear();
    normal.clear();
    gap.clear();
    target.clear();
    size.clear();
    counted.clear();
    friction.clear();
    for (auto &r : resistance) r.clear();
    tangent1.clear();
    tangent2.clear();
    arm_i.clear();
    arm_j.clear();
    wall_velocity.clear();
  }
  void add_contact(int i, int j, const Vec3 &n, double d, double s, bool count = true)
  {
    counted.push_back(count ? 1 : 0);
    body_i.push_back(i);
    body_j.push_back(j);
    normal.push_back(n);
    gap.push_back(d);
    target.push_back(d);
    size.push_back(s);
  }

  // G_c u / h = n_c . (u_j - u_i): the normal approach speed of row c (u_wall = 0). The one
  // definition of G (eq. 1); DualOperator holds its transpose.
  // Written on scalars: the innermost operation of every solver, and Eigen's 3-vectors
  // (two lanes and one) cost shuffles and a temporary here; same operations and order
  // ((n0 d0 + n1 d1) + n2 d2, d = u_j - u_i, 0 - u_i at a wall) as n.dot(u_j - u_i).
  double normal_speed(int c, const std::vector<Vec3> &u) const;
  // Tangents and arms of rows first.. (with friction), from the geometric gap (before any
  // target term). The tangents are a function of the normal alone, so that two processes
  // holding the same row, and the next step's warm start, see the same frame. The arms split
  // the distance of the centres d = size + gap in the ratio of the radii (a wall row: the
  // distance to the wall), so that they add up to d: the contact impulses then have no moment
  // about any point, and angular momentum is exact without walls.
  void complete_frames(int first)
  {
    const int nc = n_contacts();
    tangent1.resize(nc);
    tangent2.resize(nc);
    arm_i.resize(nc);
    arm_j.resize(nc);
    for (int c = first; c < nc; ++c) {
      const double stretch = 1.0 + gap[c] / size[c];
      arm_i[c] = radius[body_i[c]] * stretch;
      arm_j[c] = is_wall(body_j[c]) ? 0.0 : radius[body_j[c]] * stretch;
      const Vec3 &n = normal[c];
      // the axis least aligned with n gives the best-conditioned cross product
      int axis = 0;
      if (std::abs(n[1]) < std::abs(n[axis])) axis = 1;
      if (std::abs(n[2]) < std::abs(n[axis])) axis = 2;
      tangent1[c] = n.cross(Vec3::Unit(axis)).normalized();
      tangent2[c] = n.cross(tangent1[c]);
    }
  }
  // The relative velocity of the contact points of row c: n . of it is normal_speed (a
  // moving wall's normal speed is in the gap, so only its tangential part is added here).
  // The contact point sits at +a_i n from centre i and -a_j n from centre j (the arms), so
  // spins add a_i n x w_i + a_j n x w_j.
  // A pair held twice (across processes, or with a periodic image on one) is two rows with
  // opposite normals and tangents (-t_1, t_2) that must evolve bit for bit as mirror images
  // (Prop. 4: momentum exact). So the sum is taken as (u_j - u_i) + (spin terms), each part
  // antisymmetric in (i, j) to the bit (IEEE subtraction and commuted additions are exact
  // mirrors); summing the four terms one by one from -u_i rounds differently on the two rows,
  // and stick/slip decisions amplify that into forces that no longer cancel.
  Vec3 slip_velocity(int c, const std::vector<Vec3> &u) const
  {
    const int i = body_i[c], j = body_j[c], nb = n_bodies();
    const Vec3 &n = normal[c];
    if (!is_wall(j)) {
      Vec3 v = u[j] - u[i];
      if (rotates()) v += arm_i[c] * n.cross(u[nb + i]) + arm_j[c] * n.cross(u[nb + j]);
      return v;
    }
    Vec3 v = -u[i];
    if (rotates()) v += arm_i[c] * n.cross(u[nb + i]);
    if (!wall_velocity.empty()) {
      const Vec3 &w = wall_velocity[c];
      v += w - n.dot(w) * n;
    }
    return v;
  }

  // The rolling radius of row c: a_i a_j / (a_i + a_j), or a_i against a wall.
  double rolling_radius(int c) const
  {
    return is_wall(body_j[c]) ? arm_i[c] : arm_i[c] * arm_j[c] / (arm_i[c] + arm_j[c]);
  }
  // w_j - w_i of row c (w_wall = 0).
  Vec3 relative_spin(int c, const std::vector<Vec3> &u) const
  {
    const int nb = n_bodies(), j = body_j[c];
    return (is_wall(j) ? Vec3::Zero() : u[nb + j]) - u[nb + body_i[c]];
  }

  // g_c(u): the gap predicted after the step (eq. 15 left-hand side), from the row's target.
  double predicted_gap(int c, const std::vector<Vec3> &u) const
  {
    return target[c] + h * normal_speed(c, u);
  }
};

// The rows of a problem as raw arrays, for the innermost loops of the solvers (normal law): G_c
// and G_c^T on velocities stored as 3 doubles per body. Made once per pass over the rows, it
// holds the arrays' addresses in locals: through the problem's vectors the compiler reloads
// every address after each store to a velocity, and Eigen's 3-vectors (two lanes and one) add
// shuffles and temporaries - together 2 x the instructions of a cg iteration on a resting
// pile (callgrind). The operations and their order are those of the Eigen forms they replace.
struct RowKernel {
  explicit RowKernel(const ContactProblem &p)
      : h(p.h), n_owned(p.n_owned), body_i(p.body_i.data()), body_j(p.body_j.data()),
        normal(doubles(p.normal)), inv_mass(p.inv_mass.data())
  {
  }
  // n_c . (u_j - u_i) (u_wall = 0): (n0 d0 + n1 d1) + n2 d2, d = u_j - u_i or 0 - u_i
  double normal_speed(int c, const double *u) const
  {
    const int j = body_j[c];
    const double *n = normal + 3 * c, *ui = u + 3 * body_i[c];
    if (is_wall(j))
      return (n[0] * (0.0 - ui[0]) + n[1] * (0.0 - ui[1])) + n[2] * (0.0 - ui[2]);
    const double *uj = u + 3 * j;
    return (n[0] * (uj[0] - ui[0]) + n[1] * (uj[1] - ui[1])) + n[2] * (uj[2] - ui[2]);
  }
  // u_i -= w_i (h dmu) n_c, u_j += w_j (h dmu) n_c on the owned bodies of row c
  void apply(int c, double dmu, double *u) const
  {
    const double t = h * dmu;
    const double *n = normal + 3 * c;
    const double x = t * n[0], y = t * n[1], z = t * n[2];
    const int i = body_i[c], j = body_j[c];
    if (i < n_owned) {
      const double m = inv_mass[i];
      double *v = u + 3 * i;
      v[0] -= m * x;
      v[1] -= m * y;
      v[2] -= m * z;
    }
    if (j >= 0 && j < n_owned) {
      const double m = inv_mass[j];
      double *v = u + 3 * j;
      v[0] += m * x;
      v[1] += m * y;
      v[2] += m * z;
    }
  }

  double h;
  int n_owned;
  const int *body_i, *body_j;
  const double *normal, *inv_mass;
};

inline double ContactProblem::normal_speed(int c, const std::vector<Vec3> &u) const
{
  return RowKernel(*this).normal_speed(c, doubles(u));
}

}    // namespace hardcontact
