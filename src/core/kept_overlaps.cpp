#include "kept_overlaps.h"

#include <algorithm>
#include <limits>

namespace hardcontact {

bool KeptOverlaps::begin_step()
{
  raised_ = 0;
  active_ = skip_ == 0;
  if (skip_ > 0) --skip_;
  return active_;
}

void KeptOverlaps::undo()
{
  raised_ = 0;
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

}    // namespace hardcontact
