#include "kept_overlaps.h"

#include "container_bytes.h"

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

double KeptOverlaps::memory_usage() const { return bytes_of(rows_, by_); }

}    // namespace hardcontact
