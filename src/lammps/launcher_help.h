// `-h` of the launchers (main.cpp for LAMMPS, src/liggghts/main.cpp for LIGGGHTS): the host
// prints its help text and exits inside its constructor, before the fix can be registered, and
// its style lists are compiled in. To list `hardcontact` among the fix styles, rank 0 sends
// stdout to a temporary file while the host prints the help, and an atexit() handler copies it
// to the real stdout with the style added at the end of the "* Fix styles" list. Host-free: the
// two hosts differ only in the layout of that list, which insert_fix_style() reads.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <unistd.h>

namespace hardcontact {
namespace launcher_help {

inline const char *&program_name()
{
  static const char *name = "hardcontact launcher";
  return name;
}

// After the "* Fix styles" heading (and the blank line LAMMPS puts after it, none in LIGGGHTS)
// the styles run until the next blank line: the style goes on a line of its own there.
inline void insert_fix_style(std::string &text, const std::string &style)
{
  size_t line_end = text.find("* Fix styles");
  if (line_end != std::string::npos) line_end = text.find('\n', line_end);
  if (line_end != std::string::npos)
    while (line_end + 1 < text.size() && text[line_end + 1] == '\n') ++line_end;
  const size_t end = line_end == std::string::npos ? line_end : text.find("\n\n", line_end + 1);
  if (end != std::string::npos) {
    text.insert(end + 1, style + "\n");
  } else {
    text += std::string("\n* Fix styles added by ") + program_name() + "\n\n" + style + "\n";
  }
}

struct Capture {
  int saved_stdout = -1;
  std::FILE *file = nullptr;
};

inline Capture &capture()
{
  static Capture c;
  return c;
}

inline void flush()
{
  Capture &c = capture();
  if (!c.file) return;
  std::fflush(stdout);
  dup2(c.saved_stdout, fileno(stdout));
  close(c.saved_stdout);

  std::string text;
  std::rewind(c.file);
  char buf[4096];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof(buf), c.file)) > 0) text.append(buf, n);
  std::fclose(c.file);
  c.file = nullptr;

  insert_fix_style(text, "hardcontact");
  std::fwrite(text.data(), 1, text.size(), stdout);
  std::fflush(stdout);
}

inline bool is_flag(const char *arg, const char *shrt, const char *lng)
{
  return std::strcmp(arg, shrt) == 0 || std::strcmp(arg, lng) == 0;
}

// help requested and printed to stdout (no -screen redirection)?
inline bool requested(int argc, char **argv)
{
  bool help = false, screen = false;
  for (int i = 1; i < argc; ++i) {
    if (is_flag(argv[i], "-h", "-help")) help = true;
    if (is_flag(argv[i], "-sc", "-screen")) screen = true;
  }
  return help && !screen;
}

// Call on rank 0 before the host is created, when requested().
inline void start(const char *program)
{
  program_name() = program;
  Capture &c = capture();
  c.file = std::tmpfile();
  if (!c.file) return;
  std::fflush(stdout);
  c.saved_stdout = dup(fileno(stdout));
  if (c.saved_stdout < 0 || dup2(fileno(c.file), fileno(stdout)) < 0) {
    std::fclose(c.file);
    c.file = nullptr;
    return;
  }
  std::atexit(flush);
}

}    // namespace launcher_help
}    // namespace hardcontact
