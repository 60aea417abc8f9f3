#include "warm_start_store.h"

#include "memory.h"

#include <algorithm>

namespace hardcontact {

WarmStartStore::~WarmStartStore()
{
  memory_->destroy(data_);
}

void WarmStartStore::grow(int nmax)
{
  if (capacity_ == 0) capacity_ = 8;    // a disc in a hexagonal packing has 6 contacts
  memory_->grow(data_, nmax, 1 + 2 * capacity_, "hardcontact:warm_start");
  for (int i = nmax_; i < nmax; ++i) data_[i][0] = 0.0;
  nmax_ = nmax;
}

// More columns for every row: only when some atom has more contacts than ever before.
void WarmStartStore::reserve(int capacity)
{
  if (capacity <= capacity_) return;
  capacity = std::max(capacity, 2 * capacity_);
  double **bigger = nullptr;
  memory_->create(bigger, std::max(nmax_, 1), 1 + 2 * capacity, "hardcontact:warm_start");
  for (int i = 0; i < nmax_; ++i) std::copy(data_[i], data_[i] + 1 + 2 * count(i), bigger[i]);
  memory_->destroy(data_);
  data_ = bigger;
  capacity_ = capacity;
}

void WarmStartStore::copy(int from, int to)
{
  std::copy(data_[from], data_[from] + 1 + 2 * count(from), data_[to]);
}

void WarmStartStore::add(int i, double partner, double mu)
{
  const int n = count(i);
  reserve(n + 1);
  data_[i][1 + 2 * n] = partner;
  data_[i][2 + 2 * n] = mu;
  data_[i][0] = n + 1;
}

double WarmStartStore::find(int i, double partner) const
{
  const int n = count(i);
  for (int k = 0; k < n; ++k)
    if (data_[i][1 + 2 * k] == partner) return data_[i][2 + 2 * k];
  return 0.0;
}

int WarmStartStore::pack(int i, double *buf) const
{
  const int m = packed_size(i);
  std::copy(data_[i], data_[i] + m, buf);
  return m;
}

int WarmStartStore::unpack(int i, const double *buf)
{
  const int n = static_cast<int>(buf[0]);
  reserve(n);
  std::copy(buf, buf + 1 + 2 * n, data_[i]);
  return 1 + 2 * n;
}

}    // namespace hardcontact
