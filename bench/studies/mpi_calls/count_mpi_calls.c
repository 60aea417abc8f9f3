/* Counts the MPI calls of a run, per process, through the MPI profiling interface (PMPI):
 * built as a shared library and preloaded (LD_PRELOAD) into an unchanged launcher, it
 * forwards every call to PMPI_ and, at MPI_Finalize, appends one line per process to the
 * file named by MPI_CALL_COUNTS (default mpi_call_counts.txt):
 *   rank <r> allreduce <n> send <n> isend <n> recv <n> irecv <n> sendrecv <n> wait <n> bcast <n>
 * bench/studies/mpi_calls/run.sh divides these by the solver iterations of the run. */
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>

static long n_allreduce, n_send, n_isend, n_recv, n_irecv, n_sendrecv, n_wait, n_bcast;

int MPI_Allreduce(const void *s, void *r, int n, MPI_Datatype t, MPI_Op o, MPI_Comm c)
{
  ++n_allreduce;
  return PMPI_Allreduce(s, r, n, t, o, c);
}
int MPI_Send(const void *b, int n, MPI_Datatype t, int d, int tag, MPI_Comm c)
{
  ++n_send;
  return PMPI_Send(b, n, t, d, tag, c);
}
int MPI_Isend(const void *b, int n, MPI_Datatype t, int d, int tag, MPI_Comm c, MPI_Request *q)
{
  ++n_isend;
  return PMPI_Isend(b, n, t, d, tag, c, q);
}
int MPI_Recv(void *b, int n, MPI_Datatype t, int s, int tag, MPI_Comm c, MPI_Status *st)
{
  ++n_recv;
  return PMPI_Recv(b, n, t, s, tag, c, st);
}
int MPI_Irecv(void *b, int n, MPI_Datatype t, int s, int tag, MPI_Comm c, MPI_Request *q)
{
  ++n_irecv;
  return PMPI_Irecv(b, n, t, s, tag, c, q);
}
int MPI_Sendrecv(const void *sb, int sn, MPI_Datatype st, int d, int stag, void *rb, int rn,
                 MPI_Datatype rt, int s, int rtag, MPI_Comm c, MPI_Status *status)
{
  ++n_sendrecv;
  return PMPI_Sendrecv(sb, sn, st, d, stag, rb, rn, rt, s, rtag, c, status);
}
int MPI_Wait(MPI_Request *q, MPI_Status *st)
{
  ++n_wait;
  return PMPI_Wait(q, st);
}
int MPI_Bcast(void *b, int n, MPI_Datatype t, int root, MPI_Comm c)
{
  ++n_bcast;
  return PMPI_Bcast(b, n, t, root, c);
}
int MPI_Finalize(void)
{
  int rank = 0;
  PMPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const char *path = getenv("MPI_CALL_COUNTS");
  FILE *f = fopen(path && *path ? path : "mpi_call_counts.txt", "a");
  if (f) {
    fprintf(f, "rank %d allreduce %ld send %ld isend %ld recv %ld irecv %ld sendrecv %ld wait %ld bcast %ld\n",
            rank, n_allreduce, n_send, n_isend, n_recv, n_irecv, n_sendrecv, n_wait, n_bcast);
    fclose(f);
  }
  return PMPI_Finalize();
}
