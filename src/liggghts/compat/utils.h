// LAMMPS's utils:: functions that the adapter (src/lammps/) calls, for LIGGGHTS 3.8, which has
// no utils.h. This directory is on the include path of the LIGGGHTS build only (CMakeLists.txt),
// so `#include "utils.h"` in the adapter finds this file there and LAMMPS's own elsewhere. Same
// signatures and, for what the adapter relies on, the same behaviour as in LAMMPS 2021:
// numbers are checked before they are converted and bad ones stop the run with an ERROR line.
#pragma once

#include "error.h"
#include "lammps.h"
#include "lmptype.h"

#include "brace_format.h"    // src/liggghts/

#include <cctype>
#include <cstdlib>
#include <regex>
#include <string>

namespace LAMMPS_NS {
namespace utils {

// a number as LAMMPS writes one: optional sign, digits with optional '.', optional exponent
inline bool is_double(const std::string &str)
{
  static const std::regex number(R"(^\s*[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?\s*$)");
  return std::regex_match(str, number);
}

inline bool is_integer(const std::string &str)
{
  static const std::regex integer(R"(^\s*[+-]?\d+\s*$)");
  return std::regex_match(str, integer);
}

// LAMMPS matches its own small regex dialect; the adapter only asks for anchored prefixes
// ("^respa"), which ECMAScript regexes read the same way.
inline bool strmatch(const std::string &text, const std::string &pattern)
{
  return std::regex_search(text, std::regex(pattern));
}

inline double numeric(const char *file, int line, const char *str, bool do_abort, LAMMPS *lmp)
{
  if (!str || !is_double(str)) {
    const std::string msg = hardcontact::format(
        "Expected floating point parameter instead of '{}' in input script or data file",
        str ? str : "(null)");
    if (do_abort) lmp->error->one(file, line, msg.c_str());
    lmp->error->all(file, line, msg.c_str());
  }
  return std::strtod(str, nullptr);
}

inline bigint bnumeric(const char *file, int line, const char *str, bool do_abort, LAMMPS *lmp)
{
  if (!str || !is_integer(str)) {
    const std::string msg = hardcontact::format(
        "Expected integer parameter instead of '{}' in input script or data file",
        str ? str : "(null)");
    if (do_abort) lmp->error->one(file, line, msg.c_str());
    lmp->error->all(file, line, msg.c_str());
  }
  return static_cast<bigint>(std::strtoll(str, nullptr, 10));
}

// Index bounds of a type range as LAMMPS reads them: "n", "*", "n*", "*n", "m*n".
inline void bounds(const char *file, int line, const std::string &str, bigint nmin, bigint nmax,
                   int &nlo, int &nhi, Error *error)
{
  static const std::regex range(R"(^(\d*)(\*?)(\d*)$)");
  std::smatch m;
  bigint lo = -1, hi = -1;
  if (std::regex_match(str, m, range) && !(m[2].length() == 0 && m[3].length() > 0)) {
    if (m[2].length() == 0) {
      if (m[1].length() > 0) lo = hi = std::strtoll(m[1].str().c_str(), nullptr, 10);
    } else {
      lo = m[1].length() > 0 ? std::strtoll(m[1].str().c_str(), nullptr, 10) : nmin;
      hi = m[3].length() > 0 ? std::strtoll(m[3].str().c_str(), nullptr, 10) : nmax;
    }
  }
  if (lo < 0 || hi < 0)
    error->all(file, line, hardcontact::format("Invalid range string: {}", str).c_str());
  if (lo < nmin || hi > nmax || hi < lo)
    error->all(file, line,
               hardcontact::format("Numeric index {} is out of bounds ({}-{})",
                                   lo < nmin ? lo : hi, nmin, nmax).c_str());
  nlo = static_cast<int>(lo);
  nhi = static_cast<int>(hi);
}

}    // namespace utils
}    // namespace LAMMPS_NS
