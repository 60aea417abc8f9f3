#include "triangle_mesh.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace hardcontact {

using Vec = Eigen::Vector3d;

TriangleMesh::TriangleMesh(const std::vector<Triangle> &triangles)
{
  // Vertices closer than weld apart are one (kWeld of the mesh's extent): an STL file repeats
  // each vertex per triangle, and a file written from computed coordinates (o + i du in one
  // triangle, (o + (i-1) du) + du in the next) repeats them to within round-off only. Found
  // through cells of that size: a vertex's twin lies in its cell or a neighbouring one.
  Eigen::AlignedBox3d all;
  all.setEmpty();
  for (const Triangle &t : triangles)
    for (const Vec &v : t) all.extend(v);
  const double weld = all.isEmpty() ? 0.0 : kWeld * all.diagonal().norm();
  std::map<std::array<long long, 3>, std::vector<int>> cells;
  auto cell_of = [&](const Vec &v) {
    std::array<long long, 3> k{};
    for (int d = 0; d < 3; ++d)
      k[d] = weld > 0.0 ? static_cast<long long>(std::floor((v[d] - all.min()[d]) / weld)) : 0;
    return k;
  };
  auto vertex_id = [&](const Vec &v) {
    const std::array<long long, 3> k = cell_of(v);
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy)
        for (long long dz = -1; dz <= 1; ++dz) {
          const auto it = cells.find({{k[0] + dx, k[1] + dy, k[2] + dz}});
          if (it == cells.end()) continue;
          for (const int id : it->second)
            if ((vertex_[id] - v).norm() <= weld) return id;
        }
    const int id = static_cast<int>(vertex_.size());
    vertex_.push_back(v);
    cells[k].push_back(id);
    return id;
  };
  std::map<std::pair<int, int>, int> eid;
  for (const Triangle &t : triangles) {
    std::array<int, 3> ids{};
    for (int k = 0; k < 3; ++k) ids[k] = vertex_id(t[k]);
    if (ids[0] == ids[1] || ids[1] == ids[2] || ids[0] == ids[2]) continue;    // welded flat
    std::array<int, 3> edges{};
    for (int k = 0; k < 3; ++k) {
      const int a = std::min(ids[k], ids[(k + 1) % 3]), b = std::max(ids[k], ids[(k + 1) % 3]);
      const auto it = eid.emplace(std::make_pair(a, b), static_cast<int>(edge_.size()));
      if (it.second) {
        edge_.push_back({{a, b}});
        edge_count_.push_back(0);
      }
      edges[k] = it.first->second;
      ++edge_count_[edges[k]];
    }
    tri_.push_back(ids);
    tri_edge_.push_back(edges);
  }
  // the triangles holding each vertex and each edge (CSR)
  const auto incidence = [&](int n, int per, auto &&item, std::vector<int> &start,
                             std::vector<int> &list) {
    start.assign(n + 1, 0);
    for (int t = 0; t < n_triangles(); ++t)
      for (int k = 0; k < per; ++k) ++start[item(t, k) + 1];
    for (int i = 0; i < n; ++i) start[i + 1] += start[i];
    list.assign(static_cast<size_t>(start[n]), 0);
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (int t = 0; t < n_triangles(); ++t)
      for (int k = 0; k < per; ++k) list[fill[item(t, k)]++] = t;
  };
  incidence(n_vertices(), 3, [&](int t, int k) { return tri_[t][k]; }, vertex_tri_start_,
            vertex_tri_);
  incidence(n_edges(), 3, [&](int t, int k) { return tri_edge_[t][k]; }, edge_tri_start_,
            edge_tri_);
  bounds_ = all;
  build_grid(0.0);
}

int TriangleMesh::n_boundary_edges() const
{
  return static_cast<int>(
      std::count_if(edge_count_.begin(), edge_count_.end(), [](int n) { return n != 2; }));
}

// Cells about the size of a typical triangle: a query then visits a few cells and each cell
// holds a few triangles. At most about 4 million cells (a grid of a mesh with triangles of very
// different sizes stays that small by growing its cells).
void TriangleMesh::index(double min_cell) { build_grid(min_cell); }

void TriangleMesh::build_grid(double min_cell)
{
  const int nt = n_triangles();
  double mean = 0.0;
  ball_centre_.resize(nt);
  ball_radius_.resize(nt);
  for (int t = 0; t < nt; ++t) {
    Eigen::AlignedBox3d b(vertex_[tri_[t][0]]);
    b.extend(vertex_[tri_[t][1]]).extend(vertex_[tri_[t][2]]);
    mean += b.sizes().maxCoeff();
    ball_centre_[t] = b.center();
    ball_radius_[t] = 0.5 * b.sizes().norm();
  }
  const Vec size = bounds_.isEmpty() ? Vec(Vec::Ones()) : Vec(bounds_.sizes());
  cell_ = nt > 0 ? mean / nt : 1.0;
  cell_ = std::max(cell_, min_cell);
  if (!(cell_ > 0.0)) cell_ = std::max(size.maxCoeff(), 1.0);
  for (;;) {
    double cells = 1.0;
    for (int d = 0; d < 3; ++d) cells *= std::floor(size[d] / cell_) + 1.0;
    if (cells <= 4e6) break;
    cell_ *= 2.0;
  }
  origin_ = bounds_.isEmpty() ? Vec(Vec::Zero()) : Vec(bounds_.min());
  for (int d = 0; d < 3; ++d) dims_[d] = static_cast<int>(std::floor(size[d] / cell_)) + 1;
  const size_t ncell = static_cast<size_t>(dims_[0]) * dims_[1] * dims_[2];
  // two passes: count, then fill (CSR)
  auto cells_of = [&](int t, auto &&visit) {
    Eigen::AlignedBox3d b(vertex_[tri_[t][0]]);
    b.extend(vertex_[tri_[t][1]]).extend(vertex_[tri_[t][2]]);
    std::array<int, 3> lo{}, hi{};
    for (int d = 0; d < 3; ++d) {
      lo[d] = std::clamp(static_cast<int>(std::floor((b.min()[d] - origin_[d]) / cell_)), 0,
                         dims_[d] - 1);
      hi[d] = std::clamp(static_cast<int>(std::floor((b.max()[d] - origin_[d]) / cell_)), 0,
                         dims_[d] - 1);
    }
    for (int x = lo[0]; x <= hi[0]; ++x)
      for (int y = lo[1]; y <= hi[1]; ++y)
        for (int z = lo[2]; z <= hi[2]; ++z)
          visit((static_cast<size_t>(x) * dims_[1] + y) * dims_[2] + z);
  };
  cell_start_.assign(ncell + 1, 0);
  for (int t = 0; t < nt; ++t) cells_of(t, [&](size_t c) { ++cell_start_[c + 1]; });
  for (size_t c = 0; c < ncell; ++c) cell_start_[c + 1] += cell_start_[c];
  cell_tri_.assign(static_cast<size_t>(cell_start_[ncell]), 0);
  std::vector<int> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (int t = 0; t < nt; ++t) cells_of(t, [&](size_t c) { cell_tri_[fill[c]++] = t; });
  stamp_.assign(nt, 0);
  report_.assign(nt, -1);
}

// The nearest point of triangle t to p and the feature it lies on, from the signs of the
// projections of p on the edges (the Voronoi regions of the vertices, the edges and the face;
// Ericson, Real-Time Collision Detection, 5.1.5).
TriangleMesh::Nearest TriangleMesh::nearest_on_triangle(int t, const Vec &p) const
{
  const std::array<int, 3> &v = tri_[t];
  const std::array<int, 3> &e = tri_edge_[t];    // e[0] = (v0 v1), e[1] = (v1 v2), e[2] = (v2 v0)
  const Vec &a = vertex_[v[0]], &b = vertex_[v[1]], &c = vertex_[v[2]];
  const Vec ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return {kVertex, v[0], a};
  const Vec bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return {kVertex, v[1], b};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return {kEdge, e[0], a + (d1 / (d1 - d3)) * ab};
  const Vec cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return {kVertex, v[2], c};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return {kEdge, e[2], a + (d2 / (d2 - d6)) * ac};
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0)
    return {kEdge, e[1], b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b)};
  const double s = 1.0 / (va + vb + vc);
  return {kFace, t, a + (vb * s) * ab + (vc * s) * ac};
}

int TriangleMesh::feature_of(const Nearest &f) const
{
  switch (f.kind) {
    case kVertex: return f.id;
    case kEdge: return n_vertices() + f.id;
    default: return n_vertices() + n_edges() + f.id;
  }
}

// Feature f (an edge or a vertex) is the nearest point of triangle t to p; it is a nearest
// point of the surface around it only if every triangle holding it has its nearest point
// there too. Else some triangle holding it comes nearer elsewhere - over its face (a flat
// floor, a fold towards the sphere) or along an edge through a vertex - and the surface has
// no row there. Each triangle's report: report_[t] when stamp_[t] is this query's.
bool TriangleMesh::nearest_of_surface(const Nearest &f) const
{
  if (f.kind == kFace) return true;
  const std::vector<int> &start = f.kind == kEdge ? edge_tri_start_ : vertex_tri_start_;
  const std::vector<int> &list = f.kind == kEdge ? edge_tri_ : vertex_tri_;
  for (int k = start[f.id]; k < start[f.id + 1]; ++k) {
    const int t = list[k];
    // a triangle holding f is at most as far as f: out of reach only by round-off
    if (stamp_[t] != stamp_now_ || report_[t] < 0) continue;
    const Nearest &g = found_[report_[t]].second;
    if (g.kind != f.kind || g.id != f.id) return false;
  }
  return true;
}

void TriangleMesh::contacts(const Vec &p, double reach, std::vector<MeshContact> &out) const
{
  out.clear();
  found_.clear();
  if (tri_.empty()) return;
  std::array<int, 3> lo{}, hi{};
  for (int d = 0; d < 3; ++d) {
    const double a = (p[d] - reach - origin_[d]) / cell_, b = (p[d] + reach - origin_[d]) / cell_;
    if (b < 0.0 || a >= dims_[d]) return;    // the reach misses the mesh's box
    // clamped as doubles: a reach far beyond the mesh must not overflow an int
    lo[d] = static_cast<int>(std::max(0.0, std::floor(a)));
    hi[d] = static_cast<int>(std::min(dims_[d] - 1.0, std::floor(b)));
  }
  if (++stamp_now_ == 0) {    // wrapped: clear the stamps
    std::fill(stamp_.begin(), stamp_.end(), 0);
    stamp_now_ = 1;
  }
  for (int x = lo[0]; x <= hi[0]; ++x)
    for (int y = lo[1]; y <= hi[1]; ++y)
      for (int z = lo[2]; z <= hi[2]; ++z) {
        const size_t c = (static_cast<size_t>(x) * dims_[1] + y) * dims_[2] + z;
        for (int k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
          const int t = cell_tri_[k];
          if (stamp_[t] == stamp_now_) continue;
          stamp_[t] = stamp_now_;
          report_[t] = -1;
          if ((p - ball_centre_[t]).norm() > reach + ball_radius_[t]) continue;
          const Nearest n = nearest_on_triangle(t, p);
          if ((n.point - p).norm() > reach) continue;
          report_[t] = static_cast<int>(found_.size());
          found_.push_back({t, n});
        }
      }
  for (const auto &[t, n] : found_) {
    (void)t;
    if (!nearest_of_surface(n)) continue;
    const int f = feature_of(n);
    if (std::any_of(out.begin(), out.end(), [f](const MeshContact &m) { return m.feature == f; }))
      continue;    // a ridge or corner reached from several triangles: one row
    out.push_back({f, n.point, (n.point - p).norm()});
  }
}

double TriangleMesh::distance(int feature, const Vec &p) const
{
  if (feature < n_vertices()) return (vertex_[feature] - p).norm();
  feature -= n_vertices();
  if (feature < n_edges()) {
    const Vec &a = vertex_[edge_[feature][0]], &b = vertex_[edge_[feature][1]];
    const Vec ab = b - a;
    const double s = std::clamp(ab.dot(p - a) / ab.squaredNorm(), 0.0, 1.0);
    return (a + s * ab - p).norm();
  }
  return (nearest_on_triangle(feature - n_edges(), p).point - p).norm();
}

}    // namespace hardcontact
