#include "past_corrections.h"

#include <unordered_map>

namespace hardcontact {

void PastCorrections::follow(const ContactProblem &p, DistributedOps &ops)
{
  if (ops.max_all(p.renumbered ? 1.0 : 0.0) > 0.0) clear();
  if (w_.empty()) return;
  if (p.body_i == bodies_i_ && p.body_j == bodies_j_) return;    // the common case at rest
  // a pair's row is (i, j) or (j, i) as its neighbour list had it; walls are j < 0
  const auto key = [](int i, int j) {
    return (static_cast<unsigned long long>(static_cast<unsigned>(i)) << 32) |
           static_cast<unsigned>(j);
  };
  std::unordered_map<unsigned long long, int> old;
  old.reserve(bodies_i_.size());
  for (size_t c = 0; c < bodies_i_.size(); ++c)
    old.emplace(key(bodies_i_[c], bodies_j_[c]), static_cast<int>(c));
  const int nc = p.n_contacts();
  std::vector<int> from(nc, -1);
  for (int c = 0; c < nc; ++c) {
    const auto it = old.find(key(p.body_i[c], p.body_j[c]));
    if (it != old.end()) from[c] = it->second;
  }
  const size_t B = static_cast<size_t>(block_);
  for (auto *list : {&w_, &aw_})
    for (std::vector<double> &w : *list) {
      std::vector<double> moved(B * nc, 0.0);
      for (int c = 0; c < nc; ++c)
        if (from[c] >= 0)
          for (size_t k = 0; k < B; ++k) moved[B * c + k] = w[B * from[c] + k];
      w.swap(moved);
    }
  bodies_i_ = p.body_i;
  bodies_j_ = p.body_j;
}

void PastCorrections::record(std::vector<double> d, std::vector<double> ad,
                             const ContactProblem &p, int keep)
{
  if (static_cast<int>(w_.size()) >= keep) {
    w_.pop_back();
    aw_.pop_back();
  }
  w_.insert(w_.begin(), std::move(d));
  aw_.insert(aw_.begin(), std::move(ad));
  bodies_i_ = p.body_i;
  bodies_j_ = p.body_j;
}

// E = W^T A W (k x k, symmetrised: the carried products are of different steps' A) and W^T g
// in one reduction; c = -E^+ W^T g over the eigenvalues above kCut x the largest (dependent
// corrections: the same slow mode again).
bool PastCorrections::coefficients(const ContactProblem &p, const std::vector<int> &rows,
                                   const std::vector<double> &g, DistributedOps &ops,
                                   Eigen::VectorXd &c) const
{
  const int k = static_cast<int>(w_.size());
  const size_t B = static_cast<size_t>(block_);
  c.resize(0);
  std::vector<double> sums(static_cast<size_t>(k) * k + k, 0.0);
  for (const int r : rows) {
    if (!p.counted[r]) continue;
    for (size_t q = 0; q < B; ++q) {
      const size_t at = B * r + q;
      for (int a = 0; a < k; ++a) {
        const double wa = w_[a][at];
        if (wa == 0.0) continue;
        for (int b = 0; b < k; ++b) sums[static_cast<size_t>(a) * k + b] += wa * aw_[b][at];
        sums[static_cast<size_t>(k) * k + a] += wa * g[at];
      }
    }
  }
  ops.sum_all(sums.data(), static_cast<int>(sums.size()));
  Eigen::MatrixXd E(k, k);
  Eigen::VectorXd wg(k);
  for (int a = 0; a < k; ++a) {
    for (int b = 0; b < k; ++b)
      E(a, b) = 0.5 * (sums[static_cast<size_t>(a) * k + b] + sums[static_cast<size_t>(b) * k + a]);
    wg(a) = sums[static_cast<size_t>(k) * k + a];
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(E);
  const double top = eig.eigenvalues().maxCoeff();
  if (!(top > 0.0)) return false;
  Eigen::VectorXd proj = eig.eigenvectors().transpose() * wg;
  for (int a = 0; a < k; ++a) {
    const double l = eig.eigenvalues()(a);
    proj(a) = l > kCut * top ? -proj(a) / l : 0.0;
  }
  c = eig.eigenvectors() * proj;
  return true;
}

}    // namespace hardcontact
