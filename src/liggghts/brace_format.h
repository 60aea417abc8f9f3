// Messages with fmt-style placeholders ("atom {} at {:.6g}") for LIGGGHTS 3.8, which bundles no
// fmt library and whose Error takes a finished C string. Used only by lammps_compat.h's
// LIGGGHTS branch, so that the adapter's messages read the same on every host.
//
// Supported: "{}" (strings, integers, doubles: the shortest text that reads back as the same
// double, as fmt prints them) and "{:<printf spec>}" for numbers ("{:.6g}", "{:.3g}"); "{{" and
// "}}" print braces. That is all the adapter's messages use; anything else prints as given.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <type_traits>

namespace hardcontact {
namespace brace_format {

inline std::string shortest(double v)
{
  char buf[40];
  for (int precision = 1; precision <= 17; ++precision) {
    std::snprintf(buf, sizeof(buf), "%.*g", precision, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

// One argument as text; spec is what follows ':' in the placeholder ("" for "{}").
inline std::string text(const std::string &spec, const char *s) { (void) spec; return s ? s : "(null)"; }
inline std::string text(const std::string &spec, const std::string &s) { (void) spec; return s; }
inline std::string text(const std::string &spec, double v)
{
  if (spec.empty()) return shortest(v);
  char buf[64];
  std::snprintf(buf, sizeof(buf), ("%" + spec).c_str(), v);
  return buf;
}
template <typename Int, typename = std::enable_if_t<std::is_integral<Int>::value>>
std::string text(const std::string &spec, Int v)
{
  if (!spec.empty()) return text(spec, static_cast<double>(v));
  return std::to_string(v);
}

inline void append_until_placeholder(std::string &out, const char *&p, std::string *spec)
{
  while (*p) {
    if (p[0] == '{' && p[1] == '{') { out += '{'; p += 2; continue; }
    if (p[0] == '}' && p[1] == '}') { out += '}'; p += 2; continue; }
    if (p[0] == '{' && spec) {
      const char *close = std::strchr(p, '}');
      if (close) {
        spec->assign(p + 1, close);
        if (!spec->empty() && (*spec)[0] == ':') spec->erase(0, 1);
        p = close + 1;
        return;
      }
    }
    out += *p++;
  }
}

inline void format_into(std::string &out, const char *&p) { append_until_placeholder(out, p, nullptr); }

template <typename First, typename... Rest>
void format_into(std::string &out, const char *&p, const First &first, const Rest &...rest)
{
  std::string spec;
  append_until_placeholder(out, p, &spec);
  out += text(spec, first);
  format_into(out, p, rest...);
}

}    // namespace brace_format

template <typename... Args>
std::string format(const char *format, const Args &...args)
{
  std::string out;
  const char *p = format;
  brace_format::format_into(out, p, args...);
  return out;
}

}    // namespace hardcontact
