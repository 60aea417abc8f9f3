// lmp_hardcontact: the LAMMPS `lmp` executable with fix hardcontact registered.
//
// Behaves like LAMMPS's own main(): same command-line flags (-in, -var, -log, -echo, -screen,
// -h, ...), same exit codes. The only addition: right after the LAMMPS instance is created,
// lammpsplugin_init() (plugin.cpp, shared with hardcontactplugin.so) is called with a
// registration function that puts the fix creator into lmp->modify->fix_map. This needs no
// PLUGIN package in the system LAMMPS (Debian's has none).
#include "exceptions.h"
#include "input.h"
#include "lammps.h"
#include "lammpsplugin.h"
#include "library.h"
#include "modify.h"

#include <mpi.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <unistd.h>

using namespace LAMMPS_NS;

namespace {

// ---------------------------------------------------------------- registration
void register_style(lammpsplugin_t *plugin, void *ptr)
{
  auto *lmp = static_cast<LAMMPS *>(ptr);
  if (std::strcmp(plugin->style, "fix") != 0) {
    std::fprintf(stderr, "lmp_hardcontact: cannot register %s style %s\n", plugin->style,
                 plugin->name);
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  // same cast as LAMMPS's PLUGIN package does for fix styles
  (*lmp->modify->fix_map)[plugin->name] = reinterpret_cast<Modify::FixCreator>(plugin->creator.v2);
}

// ---------------------------------------------------------------- -h / -help
// LAMMPS prints its help text and calls exit(0) inside the LAMMPS constructor, before we
// could register anything, and its style lists are compiled in. To list `hardcontact` among
// the fix styles, rank 0 sends stdout to a temporary file while LAMMPS prints the help and an
// atexit() handler copies it to the real stdout with the style inserted.
int help_saved_stdout = -1;
std::FILE *help_capture = nullptr;

void help_flush()
{
  if (!help_capture) return;
  std::fflush(stdout);
  dup2(help_saved_stdout, fileno(stdout));
  close(help_saved_stdout);

  std::string text;
  std::rewind(help_capture);
  char buf[4096];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof(buf), help_capture)) > 0) text.append(buf, n);
  std::fclose(help_capture);
  help_capture = nullptr;

  // the fix style list: "* Fix styles\n\n<rows>\n\n"; append a row at its end
  const std::string entry = "hardcontact";
  size_t head = text.find("* Fix styles");
  size_t rows = (head == std::string::npos) ? head : text.find("\n\n", head);
  size_t end = (rows == std::string::npos) ? rows : text.find("\n\n", rows + 2);
  if (end != std::string::npos) {
    text.insert(end + 1, entry + "\n");
  } else {
    text += "\n* Fix styles added by lmp_hardcontact\n\n" + entry + "\n";
  }
  std::fwrite(text.data(), 1, text.size(), stdout);
  std::fflush(stdout);
}

bool is_flag(const char *arg, const char *shrt, const char *lng)
{
  return std::strcmp(arg, shrt) == 0 || std::strcmp(arg, lng) == 0;
}

// help requested and printed to stdout (no -screen redirection)?
bool help_to_stdout(int argc, char **argv)
{
  bool help = false, screen = false;
  for (int i = 1; i < argc; ++i) {
    if (is_flag(argv[i], "-h", "-help")) help = true;
    if (is_flag(argv[i], "-sc", "-screen")) screen = true;
  }
  return help && !screen;
}

void capture_help()
{
  help_capture = std::tmpfile();
  if (!help_capture) return;
  std::fflush(stdout);
  help_saved_stdout = dup(fileno(stdout));
  if (help_saved_stdout < 0 || dup2(fileno(help_capture), fileno(stdout)) < 0) {
    std::fclose(help_capture);
    help_capture = nullptr;
    return;
  }
  std::atexit(help_flush);
}

void finalize_helpers()
{
  lammps_kokkos_finalize();
  lammps_python_finalize();
}

}    // namespace

int main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);
  MPI_Comm lammps_comm = MPI_COMM_WORLD;

  int me = 0;
  MPI_Comm_rank(lammps_comm, &me);
  if (me == 0 && help_to_stdout(argc, argv)) capture_help();

  try {
    auto *lmp = new LAMMPS(argc, argv, lammps_comm);
    lammpsplugin_init(lmp, nullptr, reinterpret_cast<void *>(&register_style));
    lmp->input->file();
    delete lmp;
  } catch (LAMMPSAbortException &ae) {
    // an error on one rank only (error->one): the others cannot be reached collectively
    finalize_helpers();
    MPI_Abort(ae.universe, 1);
  } catch (LAMMPSException &) {
    // an error on all ranks (error->all): the message is already printed
    finalize_helpers();
    MPI_Barrier(lammps_comm);
    MPI_Finalize();
    std::exit(1);
  } catch (std::exception &e) {
    // e.g. fmt::format_error from a malformed message
    std::fprintf(stderr, "lmp_hardcontact: %s\n", e.what());
    finalize_helpers();
    MPI_Abort(MPI_COMM_WORLD, 1);
    std::exit(1);
  }
  finalize_helpers();
  MPI_Barrier(lammps_comm);
  MPI_Finalize();
  return 0;
}
