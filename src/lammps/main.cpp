// lmp_hardcontact: the LAMMPS `lmp` executable with fix hardcontact registered.
//
// Behaves like LAMMPS's own main(): same command-line flags (-in, -var, -log, -echo, -screen,
// -h, ...), same exit codes. The only addition: right after the LAMMPS instance is created,
// lammpsplugin_init() (plugin.cpp, shared with hardcontactplugin.so) is called with a
// registration function that puts the fix creator into lmp->modify->fix_map. This needs no
// PLUGIN package in the system LAMMPS (Debian's has none).
#include "launcher_help.h"

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
  if (me == 0 && hardcontact::launcher_help::requested(argc, argv))
    hardcontact::launcher_help::start("lmp_hardcontact");

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
