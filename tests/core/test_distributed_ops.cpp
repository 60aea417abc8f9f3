// The reduction step that sum_max_all is built on (core/distributed_ops.h): the sums are added,
// the maxima compared, the leading count kept; and the serial host leaves values as they are.
#include "distributed_ops.h"

#include <gtest/gtest.h>

#include <vector>

namespace hardcontact {
namespace {

TEST(CombineSumMax, AddsTheSumsAndKeepsTheLargerMaxima)
{
  // two sums, then two maxima (one larger on each side)
  const std::vector<double> in = {2.0, 1.5, -4.0, 3.0, -1.0};
  std::vector<double> inout = {2.0, 0.25, 1.0, 7.0, -2.0};
  combine_sum_max(in.data(), inout.data(), 5);
  EXPECT_EQ(inout, (std::vector<double>{2.0, 1.75, -3.0, 7.0, -1.0}));
}

TEST(CombineSumMax, OnlySumsOrOnlyMaxima)
{
  std::vector<double> sums = {3.0, 1.0, 2.0, 3.0};
  combine_sum_max(std::vector<double>{3.0, 10.0, 20.0, 30.0}.data(), sums.data(), 4);
  EXPECT_EQ(sums, (std::vector<double>{3.0, 11.0, 22.0, 33.0}));
  std::vector<double> maxima = {0.0, 5.0, 0.0};
  combine_sum_max(std::vector<double>{0.0, 4.0, 1e-300}.data(), maxima.data(), 3);
  EXPECT_EQ(maxima, (std::vector<double>{0.0, 5.0, 1e-300}));
}

TEST(CombineSumMax, IsCommutative)
{
  // every process must end with the same bits whichever order the host combines in
  const std::vector<double> a = {1.0, 0.1, 0.7, 2.5}, b = {1.0, 0.2, -3.0, 2.5000001};
  std::vector<double> ab = b, ba = a;
  combine_sum_max(a.data(), ab.data(), 4);
  combine_sum_max(b.data(), ba.data(), 4);
  EXPECT_EQ(ab, ba);
}

TEST(SerialOps, SumMaxAllLeavesValues)
{
  SerialOps ops;
  double v[3] = {1.0, -2.0, 3.0};
  ops.sum_max_all(v, 2, 1);
  EXPECT_EQ(v[0], 1.0);
  EXPECT_EQ(v[1], -2.0);
  EXPECT_EQ(v[2], 3.0);
}

}    // namespace
}    // namespace hardcontact
