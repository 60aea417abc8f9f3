// The core's DistributedOps on top of LAMMPS: ghost copies are refreshed with the fix's own
// forward communication (LAMMPS's swap pattern), reductions go over the world communicator.
// Each call is counted and timed (MPI_Wtime, tens of ns against the microseconds of a call):
// the time includes the wait for the slowest process, which is what a solver's iteration
// pays for its synchronisation points (HARDCONTACT_COMM_TIMES, fix_hardcontact.cpp).
#pragma once

#include "../core/contact_problem.h"
#include "../core/distributed_ops.h"
#include "lammps_compat.h"

#include "error.h"

#include <mpi.h>

#include <algorithm>

namespace hardcontact {

constexpr int kDoublesPerVec3 = static_cast<int>(sizeof(Vec3) / sizeof(double));

class LammpsOps : public DistributedOps {
 public:
  // The widest value forwarded per body: the core's (u in the solvers: a velocity and a spin;
  // degrees) and the step's own (u_free likewise, the owners' coordinates). Sizes
  // comm_forward.
  static constexpr int kMaxPerBody =
      kMaxForwardPerBody > kDoublesPerVec3 ? kMaxForwardPerBody : kDoublesPerVec3;

  void attach(LAMMPS_NS::Fix *fix, LAMMPS_NS::Comm *comm, LAMMPS_NS::Error *error,
              MPI_Comm world)
  {
    fix_ = fix;
    error_ = error;
    comm_ = comm;
    world_ = world;
  }
  using DistributedOps::forward;
  void forward(double *data, int per_body, int blocks, long block_stride) override
  {
    // LAMMPS sized its buffers for comm_forward = kMaxPerBody doubles per atom
    if (per_body * blocks > kMaxPerBody)
      compat::error_one(error_, FLERR,
                        "Fix hardcontact: forward of {} values per atom exceeds comm_forward {}",
                        per_body * blocks, kMaxPerBody);
    data_ = data;
    per_body_ = per_body;
    blocks_ = blocks;
    block_stride_ = block_stride;
    const double t0 = MPI_Wtime();
    compat::forward_comm(comm_, fix_);
    times_.forward_s += MPI_Wtime() - t0;
    ++times_.forwards;
  }
  double max_all(double local) override { return allreduce(local, MPI_MAX); }
  double sum_all(double local) override { return allreduce(local, MPI_SUM); }
  void sum_all(double *values, int n) override
  {
    const double t0 = MPI_Wtime();
    MPI_Allreduce(MPI_IN_PLACE, values, n, MPI_DOUBLE, MPI_SUM, world_);
    reduced(t0);
  }
  // One MPI_Allreduce with a user operation over [n_sum, sums..., maxima...]: the leading
  // count tells the operation where the sums end (it is the same on every process, so the
  // operation leaves it unchanged).
  void sum_max_all(double *values, int n_sum, int n_max) override
  {
    const int n = n_sum + n_max;
    if (n > kMaxSumMax)
      compat::error_one(error_, FLERR, "Fix hardcontact: {} reduced values exceed {}", n,
                        kMaxSumMax);
    double buffer[kMaxSumMax + 1];
    buffer[0] = n_sum;
    std::copy(values, values + n, buffer + 1);
    const double t0 = MPI_Wtime();
    MPI_Allreduce(MPI_IN_PLACE, buffer, n + 1, MPI_DOUBLE, sum_max_op(), world_);
    reduced(t0);
    std::copy(buffer + 1, buffer + 1 + n, values);
  }

  // Read by the fix's pack/unpack_forward_comm: what is being sent, per LAMMPS atom index
  // (per_body() doubles of each of blocks() arrays, block_stride() doubles apart), and in all
  // per atom (values_per_atom()).
  double *data() const { return data_; }
  int per_body() const { return per_body_; }
  int blocks() const { return blocks_; }
  long block_stride() const { return block_stride_; }
  int values_per_atom() const { return per_body_ * blocks_; }

  // Calls and seconds since the last take_times(), on this process.
  struct Times {
    long forwards = 0, reductions = 0;
    double forward_s = 0.0, reduce_s = 0.0;
  };
  Times take_times()
  {
    const Times t = times_;
    times_ = Times();
    return t;
  }

 private:
  static constexpr int kMaxSumMax = 8;
  void reduced(double t0)
  {
    times_.reduce_s += MPI_Wtime() - t0;
    ++times_.reductions;
  }
  // one double over every process, timed and counted
  double allreduce(double local, MPI_Op op)
  {
    double global = 0.0;
    const double t0 = MPI_Wtime();
    MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, op, world_);
    reduced(t0);
    return global;
  }
  // [count, sums..., maxima...] combined element by element (core/distributed_ops.h)
  static void combine(void *in, void *inout, int *len, MPI_Datatype *)
  {
    combine_sum_max(static_cast<const double *>(in), static_cast<double *>(inout), *len);
  }
  // Created at the first use and kept for the process's life: MPI frees user operations at
  // MPI_Finalize, and a fix may be deleted after it (a Python driver's interpreter exit).
  static MPI_Op sum_max_op()
  {
    static MPI_Op op = [] {
      MPI_Op o;
      MPI_Op_create(&combine, 1, &o);
      return o;
    }();
    return op;
  }

  LAMMPS_NS::Fix *fix_ = nullptr;
  LAMMPS_NS::Comm *comm_ = nullptr;
  LAMMPS_NS::Error *error_ = nullptr;
  MPI_Comm world_ = MPI_COMM_NULL;
  double *data_ = nullptr;
  int per_body_ = 0;
  int blocks_ = 1;
  long block_stride_ = 0;
  Times times_;
};

}    // namespace hardcontact
