#include "kept_overlaps.h"

#include "container_bytes.h"

#include <algorithm>
#include <limits>

namespace hardcontact {

bool KeptOverlaps::begin_step()
{
  rows_.clear();
  by_.clear();
  active_ = skip_ == 0;
  if (skip_ > 0) --skip_;
  return active_;
}

void KeptOverlaps::undo(ContactProblem &p)
{
  // the raise was added last to the paper's target (after the overlap clamp, before the
  // wall and restitution terms, which add to it): subtracting it gives the paper's target
  for (size_t k = 0; k < rows_.size(); ++k) p.gap[rows_[k]] -= by_[k];
  rows_.clear();
  by_.clear();
  active_ = false;
  ++undone_;
  skip_ = backoff_;
  backoff_ = backoff_ < kMaxBackoff ? 2 * backoff_ : kMaxBackoff;
}

int KeptOverlaps::budget(int maxiter) const
{
  int b = maxiter / kBudgetDivisor;
  if (cleared_iterations_ >= 0) {
    // in long arithmetic: factor x iterations may pass INT_MAX when maxiter is huge
    const long follow = std::max(static_cast<long>(kMinBudget),
                                 static_cast<long>(kBudgetFactor) * cleared_iterations_);
    if (follow < b) b = static_cast<int>(follow);
  }
  return b > 0 ? b : 1;
}

void KeptOverlaps::save_state(double *out) const
{
  out[0] = skip_;
  out[1] = backoff_;
  out[2] = cleared_iterations_;
}

void KeptOverlaps::load_state(const double *in)
{
  // doubles from a file: clamped (and NaN read as the fresh state) rather than trusted
  const auto within = [](double v, int lo, int hi, int fresh) {
    return v >= lo && v <= hi ? static_cast<int>(v) : fresh;
  };
  skip_ = within(in[0], 0, kMaxBackoff, 0);
  backoff_ = within(in[1], 1, kMaxBackoff, 1);
  cleared_iterations_ = within(in[2], -1, std::numeric_limits<int>::max(), -1);
}

double KeptOverlaps::memory_usage() const { return bytes_of(rows_, by_); }

}    // namespace hardcontact
