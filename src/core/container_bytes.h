// What the memory_usage() of the core's objects count (LAMMPS's per-rank memory line).
#pragma once

namespace hardcontact {

// Bytes the containers hold (their capacity, not their size: what stays allocated).
template <class... V>
double bytes_of(const V &...v)
{
  return (0.0 + ... + static_cast<double>(v.capacity() * sizeof(typename V::value_type)));
}

}    // namespace hardcontact
