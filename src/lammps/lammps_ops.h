// The core's DistributedOps on top of LAMMPS: ghost copies are refreshed with the fix's own
// forward communication (LAMMPS's swap pattern), reductions go over the world communicator.
#pragma once

#include "../core/distributed_ops.h"
#include "lammps_compat.h"

#include <mpi.h>

namespace hardcontact {

class LammpsOps : public DistributedOps {
 public:
  void attach(LAMMPS_NS::Fix *fix, LAMMPS_NS::Comm *comm, MPI_Comm world)
  {
    fix_ = fix;
    comm_ = comm;
    world_ = world;
  }
  void forward(double *data, int per_body) override
  {
    data_ = data;
    per_body_ = per_body;
    compat::forward_comm(comm_, fix_);
  }
  double max_all(double local) override
  {
    double global = 0.0;
    MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_MAX, world_);
    return global;
  }
  double sum_all(double local) override
  {
    double global = 0.0;
    MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_SUM, world_);
    return global;
  }
  void sum_all(double *values, int n) override
  {
    MPI_Allreduce(MPI_IN_PLACE, values, n, MPI_DOUBLE, MPI_SUM, world_);
  }

  // Read by the fix's pack/unpack_forward_comm: what is being sent, per LAMMPS atom index.
  double *data() const { return data_; }
  int per_body() const { return per_body_; }

 private:
  LAMMPS_NS::Fix *fix_ = nullptr;
  LAMMPS_NS::Comm *comm_ = nullptr;
  MPI_Comm world_ = MPI_COMM_NULL;
  double *data_ = nullptr;
  int per_body_ = 0;
};

}    // namespace hardcontact
