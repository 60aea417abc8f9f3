// What a solver needs from the host when bodies are spread over processes (DESIGN.md): the
// host copies owned values to their ghost copies and reduces scalars over all processes.
// The serial implementation makes the core usable and testable on its own.
#pragma once

namespace hardcontact {

// The element-wise step of sum_max_all over a message [n_sum, sums..., maxima...] of len
// doubles: inout = in combined with inout (sums added, maxima compared). Commutative, and the
// leading count is the same on every process, so it is left as it is. A host's reduction
// calls it (LammpsOps: the user operation of one MPI_Allreduce).
inline void combine_sum_max(const double *in, double *inout, int len)
{
  const int n_sum = static_cast<int>(in[0]);
  for (int k = 1; k <= n_sum; ++k) inout[k] += in[k];
  for (int k = n_sum + 1; k < len; ++k) inout[k] = inout[k] > in[k] ? inout[k] : in[k];
}

// The widest value the core forwards per body: a body's velocity and spin (two blocks of 3
// doubles; contact degrees are one). A host sizes its communication buffers with it.
constexpr int kMaxForwardPerBody = 6;

class DistributedOps {
 public:
  virtual ~DistributedOps() = default;
  // Copy `per_body` doubles per owned body to every ghost copy, for `blocks` arrays at once
  // (the k-th at data + k block_stride, per_body doubles per body): a velocity vector's linear
  // and angular halves in one exchange. per_body x blocks <= kMaxForwardPerBody.
  virtual void forward(double *data, int per_body, int blocks, long block_stride) = 0;
  void forward(double *data, int per_body) { forward(data, per_body, 1, 0); }
  virtual double max_all(double local) = 0;
  virtual double sum_all(double local) = 0;
  // In place, n values at once (one message instead of n).
  virtual void sum_all(double *values, int n) = 0;
  // In place, in one message: values[0..n_sum) summed and the n_max values after them
  // maximised. Every reduction is a point where all processes wait for the slowest, so a
  // solver that needs a sum and a maximum at the same point asks for both at once.
  virtual void sum_max_all(double *values, int n_sum, int n_max) = 0;
};

class SerialOps : public DistributedOps {
 public:
  using DistributedOps::forward;
  void forward(double *, int, int, long) override {}
  double max_all(double local) override { return local; }
  double sum_all(double local) override { return local; }
  void sum_all(double *, int) override {}
  void sum_max_all(double *, int, int) override {}
};

}    // namespace hardcontact
