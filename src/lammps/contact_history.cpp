#include "contact_history.h"

#include "sources/contact_source.h"

#include "memory.h"

#include <algorithm>

namespace hardcontact {
namespace {

// The key under which an atom stores row c: the other atom's ID, or the wall code j < 0.
double partner_key(const ContactProblem &p, const LAMMPS_NS::tagint *tag, int c)
{
  const int j = p.body_j[c];
  return is_wall(j) ? static_cast<double>(j) : static_cast<double>(tag[j]);
}

}    // namespace

ContactHistory::~ContactHistory()
{
  memory_->destroy(data_);
}

void ContactHistory::load(const ContactProblem &p, const LAMMPS_NS::tagint *tag,
                          std::vector<double> &mu) const
{
  const int nc = p.n_contacts();
  mu.assign(static_cast<size_t>(block_) * nc, 0.0);
  with_law(law_, [&](auto rows_law) {
    using Law = decltype(rows_law);
    for (int c = 0; c < nc; ++c) {
      // body i kept the values on itself (laws: history_values)
      const double *v = find(p.body_i[c], partner_key(p, tag, c));
      if (v) Law::from_history(p, c, v, &mu[static_cast<size_t>(block_) * c]);
    }
  });
}

void ContactHistory::store(const ContactProblem &p, const LAMMPS_NS::tagint *tag,
                           const std::vector<double> &mu)
{
  for (int i = 0; i < p.n_owned; ++i) clear(i);
  const int nc = p.n_contacts();
  with_law(law_, [&](auto rows_law) {
    using Law = decltype(rows_law);
    double on_i[Law::history], on_j[Law::history];    // the values atom i and atom j keep
    for (int c = 0; c < nc; ++c) {
      const double *m = &mu[static_cast<size_t>(block_) * c];
      if (m[0] <= 0.0) continue;    // an open contact starts the next step from 0
      const int i = p.body_i[c], j = p.body_j[c];
      Law::history_values(p, c, m, on_i, on_j);
      if (i < p.n_owned) add(i, partner_key(p, tag, c), on_i);
      if (!is_wall(j) && j < p.n_owned) add(j, static_cast<double>(tag[i]), on_j);
    }
  });
}

void ContactHistory::grow(int nmax)
{
  if (capacity_ == 0) capacity_ = 8;    // a disc in a hexagonal packing has 6 contacts
  memory_->grow(data_, nmax, max_packed_size(), "hardcontact:contact_history");
  for (int i = nmax_; i < nmax; ++i) data_[i][0] = 0.0;
  nmax_ = nmax;
}

// More columns for every row: only when some atom has more contacts than ever before.
void ContactHistory::reserve(int capacity)
{
  if (capacity <= capacity_) return;
  capacity = std::max(capacity, 2 * capacity_);
  double **bigger = nullptr;
  memory_->create(bigger, std::max(nmax_, 1), 1 + stride() * capacity,
                  "hardcontact:contact_history");
  for (int i = 0; i < nmax_; ++i) std::copy(data_[i], data_[i] + packed_size(i), bigger[i]);
  memory_->destroy(data_);
  data_ = bigger;
  capacity_ = capacity;
}

void ContactHistory::copy(int from, int to)
{
  std::copy(data_[from], data_[from] + packed_size(from), data_[to]);
}

void ContactHistory::add(int i, double partner, const double *values)
{
  const int n = count(i);
  reserve(n + 1);
  double *entry = data_[i] + 1 + stride() * n;
  entry[0] = partner;
  std::copy(values, values + k_, entry + 1);
  data_[i][0] = n + 1;
}

const double *ContactHistory::find(int i, double partner) const
{
  const int n = count(i);
  for (int e = 0; e < n; ++e) {
    const double *entry = data_[i] + 1 + stride() * e;
    if (entry[0] == partner) return entry + 1;
  }
  return nullptr;
}

int ContactHistory::pack(int i, double *buf) const
{
  const int m = packed_size(i);
  std::copy(data_[i], data_[i] + m, buf);
  return m;
}

int ContactHistory::unpack(int i, const double *buf)
{
  const int n = static_cast<int>(buf[0]);
  reserve(n);
  std::copy(buf, buf + 1 + stride() * n, data_[i]);
  return 1 + stride() * n;
}

}    // namespace hardcontact
