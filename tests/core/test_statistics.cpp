// Order statistics of unsorted figures: the k-th smallest, and the median as the middle value or
// the mean of the two middle ones; the value given for an empty sample.
#include <gtest/gtest.h>

#include <cmath>

#include "core/statistics.h"

namespace demoplan {
namespace {

TEST(Statistics, MedianIsTheMiddleOrTheMeanOfTheTwoMiddleValues) {
  EXPECT_DOUBLE_EQ(median({7, 1, 5}), 5);
  EXPECT_DOUBLE_EQ(median({7, 1, 5, 2}), 3.5);
  EXPECT_DOUBLE_EQ(median({4}), 4);
  EXPECT_DOUBLE_EQ(median({2, 2, 9, 2}), 2);
  EXPECT_DOUBLE_EQ(median({}), 0);
  EXPECT_TRUE(std::isnan(median({}, std::nan(""))));
}

TEST(Statistics, OrderStatisticIsTheKthSmallestClampedToTheLargest) {
  const std::vector<double> v{9, 3, 7, 1, 5};
  EXPECT_DOUBLE_EQ(order_statistic(v, 0), 1);
  EXPECT_DOUBLE_EQ(order_statistic(v, 1), 3);
  EXPECT_DOUBLE_EQ(order_statistic(v, 4), 9);
  EXPECT_DOUBLE_EQ(order_statistic(v, 40), 9);
  EXPECT_DOUBLE_EQ(order_statistic({}, 0, -1), -1);
}

}  // namespace
}  // namespace demoplan
