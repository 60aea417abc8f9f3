#include "stl_reader.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

namespace hardcontact {

namespace {

[[noreturn]] void fail(const std::string &path, const std::string &what)
{
  throw StlError("STL file " + path + ": " + what);
}

bool degenerate(const Triangle &t)
{
  const Eigen::Vector3d n = (t[1] - t[0]).cross(t[2] - t[0]);
  const double scale = std::max({(t[1] - t[0]).squaredNorm(), (t[2] - t[0]).squaredNorm(),
                                 (t[2] - t[1]).squaredNorm()});
  // the normal's length is twice the area: zero, or round-off of the edges' products
  return !(n.squaredNorm() > 1e-28 * scale * scale);
}

void keep(StlContents &out, Triangle t, double scale)
{
  for (auto &v : t) v *= scale;
  if (degenerate(t)) {
    ++out.degenerate;
    return;
  }
  out.triangles.push_back(t);
}

float little_endian_float(const unsigned char *b)
{
  const std::uint32_t bits = static_cast<std::uint32_t>(b[0]) |
                             static_cast<std::uint32_t>(b[1]) << 8 |
                             static_cast<std::uint32_t>(b[2]) << 16 |
                             static_cast<std::uint32_t>(b[3]) << 24;
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

void read_binary(const std::string &path, const std::vector<unsigned char> &bytes,
                 std::uint32_t n, double scale, StlContents &out)
{
  out.binary = true;
  for (std::uint32_t k = 0; k < n; ++k) {
    const unsigned char *f = bytes.data() + 84 + 50 * static_cast<size_t>(k) + 12;    // skip the normal
    Triangle t;
    for (int v = 0; v < 3; ++v)
      for (int d = 0; d < 3; ++d) {
        const float x = little_endian_float(f + 12 * v + 4 * d);
        if (!std::isfinite(x))
          fail(path, "triangle " + std::to_string(k + 1) + " has a coordinate that is not a "
                         "finite number (a binary file written wrongly?)");
        t[v][d] = x;
      }
    keep(out, t, scale);
  }
}

// A token reader over the lines of an ASCII file that knows the line it is on.
class Tokens {
 public:
  Tokens(const std::string &path, const std::string &text) : path_(path), in_(text) {}
  bool next(std::string &tok)
  {
    for (;;) {
      if (line_ >> tok) return true;
      std::string l;
      if (!std::getline(in_, l)) return false;
      ++lineno_;
      line_.clear();
      line_.str(l);
    }
  }
  void expect(const char *word)
  {
    std::string tok;
    if (!next(tok)) fail(path_, std::string("ends where '") + word + "' was expected");
    if (tok != word)
      fail(path_, "line " + std::to_string(lineno_) + ": expected '" + word + "', found '" +
                      tok + "'");
  }
  double number()
  {
    std::string tok;
    if (!next(tok)) fail(path_, "ends in the middle of a facet");
    char *end = nullptr;
    const double x = std::strtod(tok.c_str(), &end);
    if (end == tok.c_str() || *end != '\0' || !std::isfinite(x))
      fail(path_, "line " + std::to_string(lineno_) + ": '" + tok + "' is not a number");
    return x;
  }
  void rest_of_line()
  {
    line_.clear();
    line_.str("");
  }
  int line() const { return lineno_; }

 private:
  std::string path_;
  std::istringstream in_;
  std::istringstream line_;
  int lineno_ = 0;
};

void read_ascii(const std::string &path, const std::string &text, double scale, StlContents &out)
{
  Tokens tk(path, text);
  std::string tok;
  bool solid = false;
  while (tk.next(tok)) {
    if (tok == "solid") {    // solid [name]: the name runs to the end of the line
      tk.rest_of_line();
      solid = true;
      continue;
    }
    if (tok == "endsolid") {
      tk.rest_of_line();
      solid = false;
      continue;
    }
    if (tok != "facet")
      fail(path, "line " + std::to_string(tk.line()) + ": expected 'facet' or 'endsolid', found '" +
                     tok + "'");
    if (!solid) fail(path, "line " + std::to_string(tk.line()) + ": 'facet' outside 'solid ... endsolid'");
    tk.expect("normal");
    for (int d = 0; d < 3; ++d) tk.number();
    tk.expect("outer");
    tk.expect("loop");
    Triangle t;
    for (int v = 0; v < 3; ++v) {
      tk.expect("vertex");
      for (int d = 0; d < 3; ++d) t[v][d] = tk.number();
    }
    tk.expect("endloop");
    tk.expect("endfacet");
    keep(out, t, scale);
  }
  if (solid) fail(path, "ends without 'endsolid'");
}

}    // namespace

StlContents read_stl(const std::string &path, double scale)
{
  if (!(scale > 0.0) || !std::isfinite(scale)) fail(path, "the scale must be a positive number");
  std::ifstream f(path, std::ios::binary);
  if (!f) fail(path, "cannot be opened for reading (" + std::string(std::strerror(errno)) + ")");
  std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(f)),
                                   std::istreambuf_iterator<char>());
  StlContents out;
  if (bytes.size() >= 84) {
    const std::uint32_t n = static_cast<std::uint32_t>(bytes[80]) |
                            static_cast<std::uint32_t>(bytes[81]) << 8 |
                            static_cast<std::uint32_t>(bytes[82]) << 16 |
                            static_cast<std::uint32_t>(bytes[83]) << 24;
    if (bytes.size() == 84 + 50 * static_cast<size_t>(n)) {
      read_binary(path, bytes, n, scale, out);
      if (out.triangles.empty()) fail(path, "holds no triangle of nonzero area");
      return out;
    }
  }
  std::string text(bytes.begin(), bytes.end());
  const size_t first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos || text.compare(first, 5, "solid") != 0)
    fail(path, "is neither ASCII STL (which starts with 'solid') nor binary STL (80 bytes of "
               "header, a triangle count n, then 50 bytes per triangle: " +
                   std::to_string(bytes.size()) + " bytes here)");
  read_ascii(path, text, scale, out);
  if (out.triangles.empty()) fail(path, "holds no triangle of nonzero area");
  return out;
}

}    // namespace hardcontact
