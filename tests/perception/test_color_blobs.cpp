// Where a part's colours show (color_blobs.h): a red part's model finds the red regions of a
// grey frame as large as a part, not a speck of red, not where another part is tracked.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "perception/tracking/color_blobs.h"

using namespace demoplan::perception;

namespace {

const cv::Vec3b kRed(40, 40, 200), kGrey(128, 128, 128), kBlue(200, 60, 30);

// A model that has seen the part red against grey.
ColorHistograms red_part() {
  ColorHistograms colors;
  for (int i = 0; i < 500; ++i) colors.add_foreground(kRed), colors.add_background(kGrey);
  colors.update();
  return colors;
}

cv::Mat grey_frame() { return cv::Mat(480, 640, CV_8UC3, cv::Scalar(kGrey[0], kGrey[1], kGrey[2])); }

void fill(cv::Mat& image, const cv::Rect& r, const cv::Vec3b& c) { image(r).setTo(cv::Scalar(c[0], c[1], c[2])); }

}  // namespace

TEST(ColorBlobs, FindsTheRegionsInThePartsColoursLargestFirst) {
  cv::Mat image = grey_frame();
  fill(image, {100, 80, 60, 40}, kRed);   // centre (129.5, 99.5), 2400 px
  fill(image, {400, 300, 40, 40}, kRed);  // centre (419.5, 319.5), 1600 px
  fill(image, {300, 50, 60, 60}, kBlue);  // not its colour
  const std::vector<ColorBlob> blobs = color_blobs(image, red_part(), OcclusionMap(), 0, 500.0);
  ASSERT_EQ(blobs.size(), 2u);
  EXPECT_NEAR(blobs[0].centre.x(), 129.5, 2.0);
  EXPECT_NEAR(blobs[0].centre.y(), 99.5, 2.0);
  EXPECT_NEAR(blobs[0].area, 2400.0, 0.15 * 2400);
  EXPECT_GT(blobs[0].probability, 0.9);
  EXPECT_NEAR(blobs[1].centre.x(), 419.5, 2.0);
  EXPECT_NEAR(blobs[1].centre.y(), 319.5, 2.0);
  EXPECT_NEAR(blobs[1].area, 1600.0, 0.15 * 1600);
}

TEST(ColorBlobs, ASpeckOrARegionSmallerThanAskedIsNoBlob) {
  cv::Mat image = grey_frame();
  fill(image, {200, 200, 3, 3}, kRed);   // a speck: gone with the opening
  fill(image, {500, 100, 20, 20}, kRed);  // 400 px, below the 500 asked
  EXPECT_TRUE(color_blobs(image, red_part(), OcclusionMap(), 0, 500.0).empty());
  EXPECT_EQ(color_blobs(image, red_part(), OcclusionMap(), 0, 200.0).size(), 1u);
}

TEST(ColorBlobs, WhereAnotherPartIsTrackedIsNoBlobOfThisOne) {
  cv::Mat image = grey_frame();
  fill(image, {100, 80, 60, 40}, kRed);
  OcclusionMap map;
  map.labels = cv::Mat::zeros(241, 321, CV_8U);
  map.depth = cv::Mat(241, 321, CV_32F, cv::Scalar(10.f));
  map.labels(cv::Rect(45, 35, 40, 30)).setTo(2);  // part 1 over the red region (scale 0.5)
  EXPECT_TRUE(color_blobs(image, red_part(), map, 0, 500.0).empty());
  // Its own label, or the furniture behind it, takes nothing away.
  EXPECT_EQ(color_blobs(image, red_part(), map, 1, 500.0).size(), 1u);
  map.labels(cv::Rect(45, 35, 40, 30)).setTo(OcclusionMap::kFurniture);
  EXPECT_EQ(color_blobs(image, red_part(), map, 0, 500.0).size(), 1u);
}

TEST(ColorBlobs, NoModelYetOrNoImageGivesNone) {
  cv::Mat image = grey_frame();
  fill(image, {100, 80, 60, 40}, kRed);
  EXPECT_TRUE(color_blobs(image, ColorHistograms(), OcclusionMap(), 0, 500.0).empty());
  EXPECT_TRUE(color_blobs(cv::Mat(), red_part(), OcclusionMap(), 0, 500.0).empty());
}
