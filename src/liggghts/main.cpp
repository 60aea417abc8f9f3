// liggghts_hardcontact: Debian's LIGGGHTS 3.8 `liggghts` executable with fix hardcontact
// registered.
//
// Behaves like LIGGGHTS's own main(): same command-line flags (-in, -var, -log, -echo, -screen,
// -help, ...), the same signal handlers (SIGINT/SIGTERM end the run cleanly, SIGUSR1 writes a
// restart file), same exit codes (LIGGGHTS's errors call exit or MPI_Abort themselves). Stdout
// is line-buffered (see main). The one addition: right after the LIGGGHTS instance is created, the fix style is put into its table
// of fix styles (fix_hardcontact_liggghts.cpp says how and why that way).
#include "fix_hardcontact_liggghts.h"
#include "launcher_help.h"

#include "input.h"
#include "lammps.h"
#include "signal_handling.h"

#include <mpi.h>

#include <csignal>
#include <cstdio>
#include <cstring>

using namespace LAMMPS_NS;

namespace {

void install_signal_handlers()
{
  struct sigaction int_action, usr1_action;
  std::memset(&int_action, 0, sizeof(int_action));
  std::memset(&usr1_action, 0, sizeof(usr1_action));
  int_action.sa_handler = SignalHandler::int_handler;
  // mpirun turns a SIGINT into a SIGTERM to its children: both end the run the same way
  sigaction(SIGINT, &int_action, nullptr);
  sigaction(SIGTERM, &int_action, nullptr);
  usr1_action.sa_handler = SignalHandler::usr1_handler;
  sigaction(SIGUSR1, &usr1_action, nullptr);
}

}    // namespace

int main(int argc, char **argv)
{
  install_signal_handlers();
  // LIGGGHTS's error->one prints to the screen (stdout) and calls MPI_Abort without flushing:
  // with stdout redirected to a file its message would be lost. Line buffering keeps it.
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  MPI_Init(&argc, &argv);

  int me = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  if (me == 0 && hardcontact::launcher_help::requested(argc, argv))
    hardcontact::launcher_help::start("liggghts_hardcontact");

  auto *lmp = new LAMMPS(argc, argv, MPI_COMM_WORLD);
  register_fix_hardcontact(lmp);
  lmp->input->file();
  delete lmp;

  MPI_Finalize();
  return 0;
}
