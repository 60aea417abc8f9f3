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
  for (int c = 0; c < nc; ++c) {
    const double *v = find(p.body_i[c], partner_key(p, tag, c));
    if (!v) continue;
    double *m = &mu[static_cast<size_t>(block_) * c];
    if (block_ == 1) {
      m[0] = v[0];
      continue;
    }
    // body i kept the force (and rolling force) on itself: the row's are on j
    for (int vec = 0; 2 * vec + 1 < block_; ++vec) {
      const Vec3 on_j = -Vec3(v[3 * vec], v[3 * vec + 1], v[3 * vec + 2]);
      if (vec == 0) m[0] = on_j.dot(p.normal[c]);
      m[2 * vec + 1] = on_j.dot(p.tangent1[c]);
      m[2 * vec + 2] = on_j.dot(p.tangent2[c]);
    }
  }
}

void ContactHistory::store(const ContactProblem &p, const LAMMPS_NS::tagint *tag,
                           const std::vector<double> &mu)
{
  for (int i = 0; i < p.n_owned; ++i) clear(i);
  const int nc = p.n_contacts();
  double on[2][6];    // the values kept by atom i (on i) and by atom j (on j)
  for (int c = 0; c < nc; ++c) {
    const double *v = &mu[static_cast<size_t>(block_) * c];
    if (v[0] <= 0.0) continue;    // an open contact starts the next step from 0
    const int i = p.body_i[c], j = p.body_j[c];
    if (block_ == 1) {
      on[0][0] = on[1][0] = v[0];
    } else {
      for (int vec = 0; 2 * vec + 1 < block_; ++vec) {
        Vec3 f = v[2 * vec + 1] * p.tangent1[c] + v[2 * vec + 2] * p.tangent2[c];
        if (vec == 0) f += v[0] * p.normal[c];
        for (int d = 0; d < 3; ++d) {
          on[0][3 * vec + d] = -f[d];
          on[1][3 * vec + d] = f[d];
        }
      }
    }
    if (i < p.n_owned) add(i, partner_key(p, tag, c), on[0]);
    if (!is_wall(j) && j < p.n_owned) add(j, static_cast<double>(tag[i]), on[1]);
  }
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
