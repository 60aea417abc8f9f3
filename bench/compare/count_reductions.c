/* Counts the collective reductions a LAMMPS run makes (MPI_Allreduce, MPI_Reduce), through
 * the MPI profiling interface: LD_PRELOAD the library built from this file (count_reductions.sh
 * does) and rank 0 prints "reductions: allreduce N reduce M" at MPI_Finalize. */
#include <mpi.h>
#include <stdio.h>

static long long n_allreduce = 0, n_reduce = 0;

int MPI_Allreduce(const void *send, void *recv, int count, MPI_Datatype type, MPI_Op op,
                  MPI_Comm comm)
{
  ++n_allreduce;
  return PMPI_Allreduce(send, recv, count, type, op, comm);
}

int MPI_Reduce(const void *send, void *recv, int count, MPI_Datatype type, MPI_Op op, int root,
               MPI_Comm comm)
{
  ++n_reduce;
  return PMPI_Reduce(send, recv, count, type, op, root, comm);
}

int MPI_Finalize(void)
{
  int rank = 0;
  PMPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0) fprintf(stderr, "reductions: allreduce %lld reduce %lld\n", n_allreduce, n_reduce);
  return PMPI_Finalize();
}
