// Triangles from an STL file (ASCII or binary), for triangle-mesh walls (`wall stl`).
//
// Why a reader of our own rather than Debian's libadmesh (ADMesh 0.98): its stl_open() rejects
// an ASCII file shorter than 208 bytes as "empty" (a one- or two-triangle part), guesses an
// ASCII file's facet count from its line count (7 lines per facet), keeps vertices in float
// whatever the file holds, and reports a bad file only on stderr (stlinit.c). A wall needs the
// file's own numbers and an error that names the file, the line and what is wrong.
#pragma once

#include <Eigen/Core>

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace hardcontact {

using Triangle = std::array<Eigen::Vector3d, 3>;

// A file that cannot be read as STL: what() names the file and the problem (and the line of
// an ASCII file).
class StlError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct StlContents {
  std::vector<Triangle> triangles;    // in the file's order, scaled; degenerate ones left out
  int degenerate = 0;                 // triangles of zero area the file held (not in triangles)
  bool binary = false;
};

// Binary when the file's size is exactly 84 + 50 n bytes for the n its header announces (some
// exporters start binary headers with "solid"); else ASCII, which must start with "solid".
// The facet normals of the file are not read: a triangle's normal is that of its vertices.
StlContents read_stl(const std::string &path, double scale = 1.0);

}    // namespace hardcontact
