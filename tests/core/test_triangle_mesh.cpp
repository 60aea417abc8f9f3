// Triangle-mesh walls: reading STL files (ASCII, binary, bad files) and the rows a sphere has
// with a mesh (the nearest features, none pushed twice), against geometry worked out by hand
// and a brute-force search over every triangle.
#include "mesh/stl_reader.h"
#include "mesh/triangle_mesh.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>
#include <string>

using hardcontact::MeshContact;
using hardcontact::read_stl;
using hardcontact::StlError;
using hardcontact::Triangle;
using hardcontact::TriangleMesh;
using V = Eigen::Vector3d;

namespace {

std::string temp_file(const std::string &name, const std::string &bytes)
{
  const std::string path = ::testing::TempDir() + "hc_" + name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

std::string binary_stl(const std::vector<Triangle> &tris, const std::string &header)
{
  std::string b(80, ' ');
  std::memcpy(&b[0], header.data(), std::min<size_t>(header.size(), 80));
  const auto put32 = [&](std::uint32_t x) {
    for (int k = 0; k < 4; ++k) b.push_back(static_cast<char>((x >> (8 * k)) & 0xff));
  };
  put32(static_cast<std::uint32_t>(tris.size()));
  for (const Triangle &t : tris) {
    for (int k = 0; k < 3; ++k) put32(0);    // the normal: not read
    for (const V &v : t)
      for (int d = 0; d < 3; ++d) {
        const float f = static_cast<float>(v[d]);
        std::uint32_t bits;
        std::memcpy(&bits, &f, 4);
        put32(bits);
      }
    b.push_back(0);
    b.push_back(0);
  }
  return b;
}

std::string error_of(const std::string &path)
{
  try {
    read_stl(path);
  } catch (const StlError &e) {
    return e.what();
  }
  return "";
}

// The unit square [0,1]^2 at z = 0 split into 2 n^2 triangles.
std::vector<Triangle> floor_grid(int n)
{
  std::vector<Triangle> t;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x0 = double(i) / n, x1 = double(i + 1) / n;
      const double y0 = double(j) / n, y1 = double(j + 1) / n;
      t.push_back({V(x0, y0, 0), V(x1, y0, 0), V(x1, y1, 0)});
      t.push_back({V(x0, y0, 0), V(x1, y1, 0), V(x0, y1, 0)});
    }
  return t;
}

// The unit cube [0,1]^3, 12 triangles.
std::vector<Triangle> cube()
{
  std::vector<Triangle> t;
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const int a = (axis + 1) % 3, b = (axis + 2) % 3;
      auto corner = [&](int u, int v) {
        V p = V::Zero();
        p[axis] = side;
        p[a] = u;
        p[b] = v;
        return p;
      };
      t.push_back({corner(0, 0), corner(1, 0), corner(1, 1)});
      t.push_back({corner(0, 0), corner(1, 1), corner(0, 1)});
    }
  return t;
}

double nearest_brute(const std::vector<Triangle> &tris, const V &p)
{
  double best = 1e300;
  for (const Triangle &t : tris) {
    TriangleMesh one({t});
    std::vector<MeshContact> c;
    one.contacts(p, 1e300, c);
    for (const auto &m : c) best = std::min(best, m.distance);
  }
  return best;
}

}    // namespace

TEST(StlReader, AsciiKeepsTheFilesNumbers)
{
  const std::string path = temp_file("one.stl",
                                     "solid part\n"
                                     "  facet normal 0 0 1\n"
                                     "    outer loop\n"
                                     "      vertex 0.1 0.2 0.3\n"
                                     "      vertex 1.000000000001 0 0\n"
                                     "      vertex 0 1 -2.5e-1\n"
                                     "    endloop\n"
                                     "  endfacet\n"
                                     "endsolid part\n");
  const auto s = read_stl(path, 2.0);
  ASSERT_EQ(s.triangles.size(), 1u);
  EXPECT_FALSE(s.binary);
  EXPECT_EQ(s.triangles[0][0], V(0.2, 0.4, 0.6));
  EXPECT_EQ(s.triangles[0][1][0], 2.000000000002);    // doubles, not floats
  EXPECT_EQ(s.triangles[0][2][2], -0.5);
}

TEST(StlReader, BinaryEvenWithAHeaderSayingSolid)
{
  const std::vector<Triangle> tris = {{V(0, 0, 0), V(1, 0, 0), V(0, 1, 0)},
                                      {V(1, 0, 0), V(1, 1, 0.5), V(0, 1, 0)}};
  const std::string path = temp_file("two.stl", binary_stl(tris, "solid exported by a CAD tool"));
  const auto s = read_stl(path);
  ASSERT_EQ(s.triangles.size(), 2u);
  EXPECT_TRUE(s.binary);
  EXPECT_EQ(s.triangles[1][1], V(1, 1, 0.5));
}

TEST(StlReader, DegenerateTrianglesAreCountedAndLeftOut)
{
  const std::vector<Triangle> tris = {{V(0, 0, 0), V(1, 0, 0), V(0, 1, 0)},
                                      {V(0, 0, 0), V(1, 1, 1), V(2, 2, 2)}};    // collinear
  const auto s = read_stl(temp_file("flat.stl", binary_stl(tris, "x")));
  EXPECT_EQ(s.triangles.size(), 1u);
  EXPECT_EQ(s.degenerate, 1);
}

TEST(StlReader, BadFilesNameTheFileAndTheProblem)
{
  EXPECT_NE(error_of("/nonexistent/part.stl").find("/nonexistent/part.stl: cannot be opened"),
            std::string::npos);
  const std::string junk = temp_file("junk.stl", "this is not a mesh\n");
  EXPECT_NE(error_of(junk).find("neither ASCII STL"), std::string::npos) << error_of(junk);
  const std::string nan = temp_file("nan.stl",
                                    "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"
                                    "vertex 1 0 x\nvertex 0 1 0\nendloop\nendfacet\nendsolid\n");
  EXPECT_NE(error_of(nan).find("line 5: 'x' is not a number"), std::string::npos) << error_of(nan);
  const std::string cut = temp_file("cut.stl",
                                    "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"
                                    "vertex 1 0 0\n");
  EXPECT_NE(error_of(cut).find("ends"), std::string::npos) << error_of(cut);
  const std::string word = temp_file("word.stl",
                                     "solid s\nfacet normal 0 0 1\nouter lop\n");
  EXPECT_NE(error_of(word).find("line 3: expected 'loop', found 'lop'"), std::string::npos)
      << error_of(word);
  const std::string empty = temp_file("empty.stl", "solid s\nendsolid s\n");
  EXPECT_NE(error_of(empty).find("no triangle"), std::string::npos) << error_of(empty);
  // a binary file cut short is not binary by its size, and not ASCII
  std::string b = binary_stl({{V(0, 0, 0), V(1, 0, 0), V(0, 1, 0)}}, "bin");
  b.resize(b.size() - 7);
  b[0] = '\x01';
  EXPECT_NE(error_of(temp_file("short.stl", b)).find("neither ASCII STL"), std::string::npos);
}

TEST(TriangleMesh, WeldsVerticesAndSharesEdges)
{
  TriangleMesh m(cube());
  EXPECT_EQ(m.n_vertices(), 8);
  EXPECT_EQ(m.n_edges(), 18);    // 12 cube edges + 6 face diagonals
  EXPECT_EQ(m.n_triangles(), 12);
  EXPECT_EQ(m.n_boundary_edges(), 0);    // closed
  TriangleMesh f(floor_grid(3));
  EXPECT_EQ(f.n_boundary_edges(), 12);
}

// Vertices repeated to within round-off (a file written from computed coordinates) are one:
// the floor's cells built as o + i du in one triangle and (o + (i - 1) du) + du in the next.
TEST(TriangleMesh, WeldsVerticesRepeatedToWithinRoundOff)
{
  std::vector<Triangle> t;
  const double du = 0.1;
  for (int i = 0; i < 10; ++i) {
    double x0 = 0.0;
    for (int k = 0; k < i; ++k) x0 += du;    // a running sum: not i * du to the bit
    const double x1 = x0 + du;
    t.push_back({V(x0, 0, 0), V(x1, 0, 0), V(x1, 1, 0)});
    t.push_back({V(x0, 0, 0), V(x1, 1, 0), V(x0, 1, 0)});
  }
  TriangleMesh m(t);
  EXPECT_EQ(m.n_vertices(), 22);
  EXPECT_EQ(m.n_boundary_edges(), 22);    // the rim only
  std::vector<MeshContact> c;
  m.contacts(V(0.3, 0.5, 0.2), 0.3, c);    // over the shared edge x = 0.3
  EXPECT_EQ(c.size(), 1u);
}

// A sphere over a flat floor made of many triangles has one row whatever it is over (a face,
// a shared edge, a shared vertex), with the floor's normal: never an edge's tilted one.
TEST(TriangleMesh, FlatFloorGivesOneRowEverywhere)
{
  TriangleMesh m(floor_grid(4));
  std::vector<MeshContact> c;
  for (const V &p : {V(0.3, 0.4, 0.2), V(0.5, 0.5, 0.2), V(0.25, 0.6, 0.2), V(0.5, 0.3, 0.2),
                     V(0.375, 0.375, 0.2), V(0.25 + 1e-13, 0.5, 0.2)}) {
    m.contacts(p, 0.3, c);
    ASSERT_EQ(c.size(), 1u) << p.transpose() << " first " << c[0].feature << " at "
                            << c[0].point.transpose() << ", second " << c[1].feature << " at "
                            << c[1].point.transpose();
    EXPECT_NEAR(c[0].distance, 0.2, 1e-15);
    EXPECT_NEAR(c[0].point.z(), 0.0, 1e-15);
    EXPECT_NEAR((c[0].point - p).normalized().dot(V(0, 0, -1)), 1.0, 1e-14);
  }
  // beyond the floor's rim: its edge, with the normal towards it
  m.contacts(V(1.1, 0.5, 0.1), 0.3, c);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_NEAR(c[0].distance, std::sqrt(0.02), 1e-15);
  m.contacts(V(0.5, 0.5, 0.35), 0.3, c);
  EXPECT_TRUE(c.empty());
}

// Outside a cube: over a face one row, at an edge one, at a corner one (the corner vertex).
// Inside near a corner: the three faces.
TEST(TriangleMesh, CubeFeaturesFromOutsideAndInside)
{
  TriangleMesh m(cube());
  std::vector<MeshContact> c;
  m.contacts(V(0.5, 0.5, 1.2), 0.3, c);    // over the top face's diagonal
  ASSERT_EQ(c.size(), 1u);
  EXPECT_NEAR(c[0].distance, 0.2, 1e-15);
  m.contacts(V(0.5, 1.1, 1.1), 0.3, c);    // at the top edge y = 1
  ASSERT_EQ(c.size(), 1u);
  EXPECT_NEAR(c[0].distance, std::sqrt(0.02), 1e-15);
  EXPECT_LT(c[0].feature, m.n_vertices() + m.n_edges());    // an edge
  EXPECT_GE(c[0].feature, m.n_vertices());
  m.contacts(V(1.1, 1.1, 1.1), 0.3, c);    // at the corner
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].point, V(1, 1, 1));
  EXPECT_LT(c[0].feature, m.n_vertices());
  m.contacts(V(0.1, 0.15, 0.2), 0.25, c);    // inside, in a corner: three walls
  ASSERT_EQ(c.size(), 3u);
  std::vector<double> d;
  for (const auto &x : c) d.push_back(x.distance);
  std::sort(d.begin(), d.end());
  EXPECT_NEAR(d[0], 0.1, 1e-15);
  EXPECT_NEAR(d[1], 0.15, 1e-15);
  EXPECT_NEAR(d[2], 0.2, 1e-15);
}

// A roof (a convex ridge): over the ridge line the ridge itself; beside it the face.
TEST(TriangleMesh, RidgeGivesItsEdgeOnce)
{
  const std::vector<Triangle> roof = {{V(0, 0, 0), V(1, 0, 1), V(1, 1, 1)},
                                      {V(0, 0, 0), V(1, 1, 1), V(0, 1, 0)},
                                      {V(1, 0, 1), V(2, 0, 0), V(2, 1, 0)},
                                      {V(1, 0, 1), V(2, 1, 0), V(1, 1, 1)}};
  TriangleMesh m(roof);
  std::vector<MeshContact> c;
  m.contacts(V(1, 0.5, 1.3), 0.5, c);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_NEAR(c[0].distance, 0.3, 1e-15);
  EXPECT_EQ(c[0].point, V(1, 0.5, 1));
  m.contacts(V(0.5, 0.5, 0.5 + 0.3 * std::sqrt(2.0)), 0.5, c);    // over the left slope
  ASSERT_EQ(c.size(), 1u);
  EXPECT_NEAR(c[0].distance, 0.3, 1e-14);
}

// In a V-shaped valley (a concave fold) a sphere near the bottom touches both slopes.
TEST(TriangleMesh, ValleyGivesBothSlopes)
{
  const std::vector<Triangle> valley = {{V(-1, 0, 1), V(0, 0, 0), V(0, 1, 0)},
                                        {V(-1, 0, 1), V(0, 1, 0), V(-1, 1, 1)},
                                        {V(0, 0, 0), V(1, 0, 1), V(1, 1, 1)},
                                        {V(0, 0, 0), V(1, 1, 1), V(0, 1, 0)}};
  TriangleMesh m(valley);
  std::vector<MeshContact> c;
  const double r = 0.2;
  m.contacts(V(0, 0.5, r * std::sqrt(2.0)), 0.25, c);    // resting in the valley
  ASSERT_EQ(c.size(), 2u);
  for (const auto &x : c) EXPECT_NEAR(x.distance, r, 1e-15);
}

// The search by cells finds every triangle a brute-force search finds: on a tessellated sphere
// and random points, the nearest row is the nearest point of the mesh, and every row's
// distance is its feature's.
TEST(TriangleMesh, GridSearchAgreesWithBruteForce)
{
  std::vector<Triangle> ball;
  const int nth = 12, nph = 24;
  auto at = [](double th, double ph) {
    if (th == 0.0) return V(0, 0, 1);    // the poles, once
    if (th > 3.14159) return V(0, 0, -1);
    return V(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
  };
  const double pi = std::acos(-1.0);
  for (int i = 0; i < nth; ++i)
    for (int j = 0; j < nph; ++j) {
      const double t0 = pi * i / nth, t1 = pi * (i + 1) / nth;
      // the last column closes on the first: the same angles, so the same vertices to the bit
      const double p0 = 2 * pi * j / nph, p1 = 2 * pi * ((j + 1) % nph) / nph;
      if (i > 0) ball.push_back({at(t0, p0), at(t1, p0), at(t0, p1)});
      if (i < nth - 1) ball.push_back({at(t0, p1), at(t1, p0), at(t1, p1)});
    }
  TriangleMesh m(ball);
  EXPECT_EQ(m.n_boundary_edges(), 0);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.3, 1.3);
  std::vector<MeshContact> c;
  int with_rows = 0;
  for (int k = 0; k < 400; ++k) {
    const V p(u(rng), u(rng), u(rng));
    const double reach = 0.3;
    m.contacts(p, reach, c);
    const double brute = nearest_brute(ball, p);
    if (brute > reach) {
      EXPECT_TRUE(c.empty());
      continue;
    }
    ++with_rows;
    ASSERT_FALSE(c.empty()) << p.transpose();
    double best = 1e300;
    for (const auto &x : c) {
      best = std::min(best, x.distance);
      EXPECT_NEAR(m.distance(x.feature, p), x.distance, 1e-14);
      EXPECT_LE(x.distance, reach);
    }
    EXPECT_NEAR(best, brute, 1e-14) << p.transpose();
  }
  EXPECT_GT(with_rows, 50);
}
