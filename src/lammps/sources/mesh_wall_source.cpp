#include "mesh_wall_source.h"

#include "row_sink.h"

#include "../lammps_compat.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "lammps.h"
#include "input.h"
#include "modify.h"
#include "neighbor.h"
#include "update.h"
#include "variable.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cstdio>
#include <limits>

using namespace LAMMPS_NS;

namespace hardcontact {

namespace {

// Process 0 reads the file; the others receive its triangles (9 doubles each) or its error.
std::vector<Triangle> read_everywhere(LAMMPS *lmp, const MeshWallSource::Spec &spec)
{
  std::string message;
  std::vector<double> flat;
  int degenerate = 0;
  if (lmp->comm->me == 0) {
    try {
      const StlContents s = read_stl(spec.file, spec.scale);
      degenerate = s.degenerate;
      for (const Triangle &t : s.triangles)
        for (const auto &v : t) flat.insert(flat.end(), {v[0], v[1], v[2]});
    } catch (const StlError &e) {
      message = e.what();
    }
  }
  int len = static_cast<int>(message.size());
  MPI_Bcast(&len, 1, MPI_INT, 0, lmp->world);
  if (len > 0) {
    message.resize(len);
    MPI_Bcast(&message[0], len, MPI_CHAR, 0, lmp->world);
    compat::error_all(lmp->error, FLERR, "Fix hardcontact wall stl: {}", message);
  }
  long n = static_cast<long>(flat.size());
  MPI_Bcast(&n, 1, MPI_LONG, 0, lmp->world);
  flat.resize(n);
  if (n > 0) MPI_Bcast(flat.data(), static_cast<int>(n), MPI_DOUBLE, 0, lmp->world);
  if (degenerate > 0 && lmp->comm->me == 0)
    compat::warning(lmp->error, FLERR,
                    "Fix hardcontact wall stl {}: {} triangle(s) of zero area left out",
                    spec.file, degenerate);
  std::vector<Triangle> tris(flat.size() / 9);
  for (size_t t = 0; t < tris.size(); ++t)
    for (int v = 0; v < 3; ++v)
      for (int d = 0; d < 3; ++d) tris[t][v][d] = flat[9 * t + 3 * v + d];
  return tris;
}

}    // namespace

MeshWallSource::MeshWallSource(LAMMPS *lmp, int groupbit, const std::vector<Spec> &specs) :
    lmp_(lmp), groupbit_(groupbit)
{
  for (const Spec &spec : specs) {
    files_.push_back(spec.fix_id.empty() ? spec.file : "mesh " + spec.fix_id);
    specs_.push_back(spec);
    if (!spec.fix_id.empty()) {    // gathered at the first init
      meshes_.emplace_back(std::vector<Triangle>());
      continue;
    }
    meshes_.emplace_back(read_everywhere(lmp, spec));
    const TriangleMesh &m = meshes_.back();
    if (lmp->comm->me != 0) continue;
    char line[512];
    std::snprintf(line, sizeof line,
                  "Fix hardcontact wall stl %s: %d triangles, %d vertices, %d edges (%d on a rim "
                  "or shared by more than two), extent %.6g x %.6g x %.6g\n",
                  spec.file.c_str(), m.n_triangles(), m.n_vertices(), m.n_edges(),
                  m.n_boundary_edges(), m.bounds().sizes()[0], m.bounds().sizes()[1],
                  m.bounds().sizes()[2]);
    if (lmp->screen) std::fputs(line, lmp->screen);
    if (lmp->logfile) std::fputs(line, lmp->logfile);
  }
}

bool MeshWallSource::moving() const
{
  for (const Placement &p : place_)
    if (p.moves() || p.surface != 0) return true;
  return false;
}

// LIGGGHTS's surface velocity at contact point c of a row with normal n: the surface moves in
// its own plane (a conveyor belt, a turning disc) and the mesh stays where it is, so only the
// tangential part counts. With surface_vel LIGGGHTS turns the velocity into each triangle's
// plane at its full speed (a belt around a roller); here into the row's tangent plane.
Vec3 MeshWallSource::Placement::surface_velocity(const Vec3 &c, const Vec3 &n) const
{
  if (surface == 0) return Vec3::Zero();
  Vec3 u = surface == 1 ? surface_v : Vec3(surface_omega * surface_axis.cross(c - surface_origin));
  u -= n.dot(u) * n;
  if (surface == 1) {
    const double t = u.norm();
    if (t > 0.0) u *= surface_v.norm() / t;
  }
  return u;
}

void MeshWallSource::read_surface_velocity(size_t k)
{
  Placement &p = place_[k];
  if (specs_[k].fix_id.empty()) return;
  const compat::SurfaceVelocity s = compat::mesh_surface_velocity(lmp_, specs_[k].fix_id);
  p.surface = s.kind;
  p.surface_v = Vec3(s.v[0], s.v[1], s.v[2]);
  p.surface_origin = Vec3(s.origin[0], s.origin[1], s.origin[2]);
  p.surface_axis = Vec3(s.axis[0], s.axis[1], s.axis[2]).normalized();
  p.surface_omega = s.omega;
}

// The placement of mesh k from its variables now (LAMMPS's step counter gives the time).
void MeshWallSource::evaluate(size_t k)
{
  Placement &p = place_[k];
  if (!p.moves()) return;
  if (p.fix_moves) {
    place_fix_mesh(k);
    ++moves_;
    return;
  }
  lmp_->modify->clearstep_compute();
  auto value = [&](int ivar, const std::string &name) {
    const double v = lmp_->input->variable->compute_equal(ivar);
    if (!std::isfinite(v))
      compat::error_all(lmp_->error, FLERR,
                        "Fix hardcontact wall stl {}: variable {} is not a finite number at "
                        "step {}",
                        files_[k], name, lmp_->update->ntimestep);
    return v;
  };
  for (int d = 0; d < 3; ++d)
    if (p.move_var[d] >= 0) p.d[d] = value(p.move_var[d], specs_[k].move[d]);
  if (p.theta_var >= 0)
    p.rotation =
        Eigen::AngleAxisd(value(p.theta_var, specs_[k].theta), p.axis).toRotationMatrix();
  compat::addstep_compute(lmp_->modify, lmp_->update->ntimestep + 1);
  ++moves_;
}

void MeshWallSource::at_current_step()
{
  for (size_t k = 0; k < place_.size(); ++k) {
    read_surface_velocity(k);
    evaluate(k);
    place_[k].rotation_before = place_[k].rotation;
    place_[k].d_before = place_[k].d;
  }
  ahead_ = false;
}

void MeshWallSource::advance(double h)
{
  if (!moving()) return;
  for (size_t k = 0; k < place_.size(); ++k) {
    Placement &p = place_[k];
    read_surface_velocity(k);    // variables of a surface velocity: LIGGGHTS's values now
    if (!p.moves()) continue;
    p.rotation_before = p.rotation;
    p.d_before = p.d;
    evaluate(k);
  }
  ahead_ = true;
  h_ = h;
}

void MeshWallSource::init(const WallSourceInit &at)
{
  const double reach = at.reach;
  const int fix_index = at.fix_index;
  found_.clear();    // the skin may have changed
  place_.resize(meshes_.size());
  for (size_t k = 0; k < meshes_.size(); ++k) {
    Placement &p = place_[k];
    const Spec &spec = specs_[k];
    if (!spec.fix_id.empty()) {
      if (p.ref_gid < 0) gather_fix_mesh(k);
      read_surface_velocity(k);
      const std::string late = compat::mesh_mover_after(lmp_, spec.fix_id, fix_index);
      if (!late.empty())
        compat::error_all(lmp_->error, FLERR,
                          "Fix hardcontact wall mesh {}: fix {} (move/mesh) comes after this "
                          "fix, so the mesh would move after the contacts are solved: define "
                          "fix {} before fix hardcontact",
                          spec.fix_id, late, late);
      p.fix_moves = compat::mesh_moving(lmp_, spec.fix_id);
      evaluate(k);
      continue;
    }
    auto find = [&](const std::string &name) {
      if (name.empty()) return -1;
      const int ivar = compat::find_variable(lmp_->input->variable, name);
      if (ivar < 0)
        compat::error_all(lmp_->error, FLERR,
                          "Fix hardcontact wall stl {}: variable {} does not exist: define it "
                          "with 'variable {} equal ...' before the run",
                          spec.file, name, name);
      if (!lmp_->input->variable->equalstyle(ivar))
        compat::error_all(lmp_->error, FLERR,
                          "Fix hardcontact wall stl {}: variable {} is not equal-style: a "
                          "mesh's displacement or angle is one number ('variable {} equal ...')",
                          spec.file, name, name);
      return ivar;
    };
    for (int d = 0; d < 3; ++d) p.move_var[d] = find(spec.move[d]);
    p.theta_var = find(spec.theta);
    p.point = spec.point;
    p.axis = spec.axis.normalized();
    evaluate(k);
  }
  ahead_ = false;
  for (TriangleMesh &m : meshes_) m.index(reach);
  offset_.clear();
  int next = 0;
  for (const TriangleMesh &m : meshes_) {
    offset_.push_back(next);
    if (m.n_features() > std::numeric_limits<int>::max() / 4 - next)
      compat::error_all(lmp_->error, FLERR,
                        "Fix hardcontact wall stl: the meshes have too many features (vertices, "
                        "edges and triangles) to number: split or coarsen them");
    next += m.n_features();
  }
  n_walls_ = next;
}

// A mesh fix's triangles on every process, in the order of their global ids (each process
// owns some; before LIGGGHTS's first setup every process holds them all: duplicates go).
void MeshWallSource::gather_fix_mesh(size_t k)
{
  const std::string &id = specs_[k].fix_id;
  std::vector<int> ids;
  std::vector<double> nodes;
  const std::string bad = compat::mesh_owned(lmp_, id, ids, nodes);
  if (!bad.empty()) compat::error_all(lmp_->error, FLERR, "Fix hardcontact wall mesh {}: {}", id, bad);
  const int nprocs = lmp_->comm->nprocs;
  int mine = static_cast<int>(ids.size());
  std::vector<int> counts(nprocs), starts(nprocs + 1, 0);
  MPI_Allgather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, lmp_->world);
  for (int q = 0; q < nprocs; ++q) starts[q + 1] = starts[q] + counts[q];
  std::vector<int> all_ids(starts[nprocs]);
  MPI_Allgatherv(ids.data(), mine, MPI_INT, all_ids.data(), counts.data(), starts.data(),
                 MPI_INT, lmp_->world);
  for (int q = 0; q < nprocs; ++q) {
    counts[q] *= 9;
    starts[q] *= 9;
  }
  starts[nprocs] *= 9;
  std::vector<double> all_nodes(starts[nprocs]);
  MPI_Allgatherv(nodes.data(), 9 * mine, MPI_DOUBLE, all_nodes.data(), counts.data(),
                 starts.data(), MPI_DOUBLE, lmp_->world);
  std::vector<int> order(all_ids.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return all_ids[a] < all_ids[b]; });
  std::vector<Triangle> tris;
  int last = -1;
  Placement &p = place_[k];
  for (const int i : order) {
    if (all_ids[i] == last) continue;
    last = all_ids[i];
    Triangle t;
    for (int v = 0; v < 3; ++v)
      for (int d = 0; d < 3; ++d) t[v][d] = all_nodes[9 * i + 3 * v + d];
    const Vec3 e1 = t[1] - t[0], e2 = t[2] - t[0];
    if (p.ref_gid < 0 && e1.cross(e2).norm() > 1e-12 * e1.squaredNorm() + 0.0) {
      p.ref_gid = last;    // the first triangle of nonzero area: its frame places the mesh
      p.ref_origin = t[0];
      const Vec3 a = e1.normalized(), b = (e2 - e2.dot(a) * a).normalized();
      p.ref_frame.col(0) = a;
      p.ref_frame.col(1) = b;
      p.ref_frame.col(2) = a.cross(b);
    }
    tris.push_back(t);
  }
  if (tris.empty() || p.ref_gid < 0)
    compat::error_all(lmp_->error, FLERR, "Fix hardcontact wall mesh {}: the mesh holds no "
                      "triangle of nonzero area", id);
  meshes_[k] = TriangleMesh(tris);
  if (lmp_->comm->me == 0) {
    char line[256];
    const TriangleMesh &m = meshes_[k];
    std::snprintf(line, sizeof line,
                  "Fix hardcontact wall mesh %s: %d triangles, %d vertices, %d edges (%d on a "
                  "rim or shared by more than two)\n",
                  id.c_str(), m.n_triangles(), m.n_vertices(), m.n_edges(), m.n_boundary_edges());
    if (lmp_->screen) std::fputs(line, lmp_->screen);
    if (lmp_->logfile) std::fputs(line, lmp_->logfile);
  }
}

// A moved mesh fix's placement, from where its reference triangle's nodes are now (moves of
// fix move/mesh are rigid: one triangle's frame gives them all). The lowest process holding
// that triangle sends its nodes.
void MeshWallSource::place_fix_mesh(size_t k)
{
  Placement &p = place_[k];
  double nodes[9] = {0.0};
  const bool here = compat::mesh_triangle(lmp_, specs_[k].fix_id, p.ref_gid, nodes);
  int me = here ? lmp_->comm->me : lmp_->comm->nprocs, from = 0;
  MPI_Allreduce(&me, &from, 1, MPI_INT, MPI_MIN, lmp_->world);
  if (from >= lmp_->comm->nprocs)
    compat::error_all(lmp_->error, FLERR, "Fix hardcontact wall mesh {}: its triangle {} is "
                      "held by no process", specs_[k].fix_id, p.ref_gid);
  MPI_Bcast(nodes, 9, MPI_DOUBLE, from, lmp_->world);
  const Vec3 o(nodes[0], nodes[1], nodes[2]);
  const Vec3 e1 = Vec3(nodes[3], nodes[4], nodes[5]) - o, e2 = Vec3(nodes[6], nodes[7], nodes[8]) - o;
  Eigen::Matrix3d frame;
  const Vec3 a = e1.normalized(), b = (e2 - e2.dot(a) * a).normalized();
  frame.col(0) = a;
  frame.col(1) = b;
  frame.col(2) = a.cross(b);
  p.point = Vec3::Zero();
  p.rotation = frame * p.ref_frame.transpose();
  p.d = o - p.rotation * p.ref_origin;
}

// Every feature within the skin of an owned sphere: a sphere cannot move more than the skin in
// a step (the fix's skin check), so no feature it could reach is left out.
const MeshWallSource::Found &MeshWallSource::rows_of(size_t k) const
{
  const Atom *atom = lmp_->atom;
  double **x = atom->x;
  const double *radius = atom->radius;
  const int n = atom->nlocal;
  Found &f = found_[k];
  bool same = static_cast<int>(f.at.size()) == n && f.placement == moves_;
  for (int i = 0; same && i < n; ++i)
    same = f.at[i][0] == x[i][0] && f.at[i][1] == x[i][1] && f.at[i][2] == x[i][2] &&
           f.at[i][3] == radius[i];
  if (same) return f;
  const double skin = lmp_->neighbor->skin;
  const Placement &p = place_[k];
  f.placement = moves_;
  f.at.resize(n);
  f.start.assign(n + 1, 0);
  f.rows.clear();
  std::vector<MeshContact> &one = scratch_;
  for (int i = 0; i < n; ++i) {
    f.at[i] = {{x[i][0], x[i][1], x[i][2], radius[i]}};
    f.start[i] = static_cast<int>(f.rows.size());
    if (!(atom->mask[i] & groupbit_)) continue;
    const Vec3 centre(x[i][0], x[i][1], x[i][2]);
    meshes_[k].contacts(p.moves() ? p.to_mesh(centre) : centre, radius[i] + skin, one);
    for (MeshContact &c : one)
      if (p.moves()) c.point = p.to_world(c.point);    // distances are the same in either frame
    f.rows.insert(f.rows.end(), one.begin(), one.end());
  }
  f.start[n] = static_cast<int>(f.rows.size());
  return f;
}

// Every feature within the skin of an owned sphere: a sphere cannot move more than the skin in
// a step (the fix's skin check), so no feature it could reach is left out. A moving mesh's rows
// carry the velocity of its surface at the contact point over the step (the displacement of
// that material point, / h), and offer the gap at t^{n+1} less h n . u_wall (region_wall_source.cpp).
void MeshWallSource::visit(const Bodies &, RowSink &sink) const
{
  double **x = lmp_->atom->x;
  const double *radius = lmp_->atom->radius;
  found_.resize(meshes_.size());
  for (size_t k = 0; k < meshes_.size(); ++k) {
    const Found &f = rows_of(k);
    const Placement &p = place_[k];
    const int base = first_wall_ + offset_[k];
    for (int i = 0; i + 1 < static_cast<int>(f.start.size()); ++i) {
      if (f.start[i] == f.start[i + 1]) continue;
      const Vec3 centre(x[i][0], x[i][1], x[i][2]);
      for (int r = f.start[i]; r < f.start[i + 1]; ++r) {
        const MeshContact &c = f.rows[r];
        if (!(c.distance > 0.0)) continue;    // centre on the surface: no direction
        const Vec3 normal = (c.point - centre) / c.distance;
        Vec3 u_wall = p.surface_velocity(c.point, normal);
        if (p.moves() && ahead_) u_wall += (c.point - p.before(p.to_mesh(c.point))) / h_;
        const double d = c.distance - radius[i] - (ahead_ ? h_ * normal.dot(u_wall) : 0.0);
        sink.offer(i, wall_body(base + c.feature), normal, d, radius[i], u_wall);
      }
    }
  }
}

size_t MeshWallSource::mesh_of(int w) const
{
  const auto it = std::upper_bound(offset_.begin(), offset_.end(), w - first_wall_);
  return static_cast<size_t>(it - offset_.begin()) - 1;
}

double MeshWallSource::wall_gap(int w, const Vec3 &x, double radius) const
{
  const int local = w - first_wall_;
  const size_t k = mesh_of(w);
  const Placement &p = place_[k];
  return meshes_[k].distance(local - offset_[k], p.moves() ? p.to_mesh(x) : x) - radius;
}

}    // namespace hardcontact
