// Video reading: frame count, fps, exact seeking, the cache, and clear errors for broken files.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <opencv2/imgproc.hpp>

#include "core/error.h"
#include "perception/video/frame_cache.h"
#include "perception/video/video_reader.h"
#include "perception/video/video_writer.h"

namespace fs = std::filesystem;
using namespace demoplan;
using namespace demoplan::perception;

namespace {

// Frame i shows a white bar at column 5 i (robust to compression).
cv::Mat numbered_frame(int i) {
  cv::Mat m(120, 160, CV_8UC3, cv::Scalar::all(30));
  cv::rectangle(m, cv::Rect(5 * i, 0, 5, 120), cv::Scalar::all(230), cv::FILLED);
  return m;
}
int number_of(const cv::Mat& frame) {
  cv::Mat col;
  cv::reduce(frame, col, 0, cv::REDUCE_AVG, CV_32F);
  int best = 0;
  for (int x = 0; x < col.cols; ++x)
    if (col.at<cv::Vec3f>(0, x)[0] > col.at<cv::Vec3f>(0, best)[0]) best = x;
  return best / 5;
}

std::string write_video(const fs::path& dir, const std::string& name, const std::string& fourcc, int frames) {
  const std::string path = (dir / name).string();
  VideoWriter w(path, 30.0, {160, 120}, fourcc);
  for (int i = 0; i < frames; ++i) w.write(numbered_frame(i));
  w.finish();
  return path;
}

class VideoTest : public ::testing::Test {
protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("demoplan_video_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_F(VideoTest, ReadsCountFpsAndSeeksExactly) {
  for (const auto& [name, fourcc] : {std::pair{"a.mp4", "mp4v"}, std::pair{"b.avi", "MJPG"}, std::pair{"c.mkv", "FFV1"}}) {
    const std::string path = write_video(dir_, name, fourcc, 25);
    VideoReader v(path, 4);
    EXPECT_EQ(v.frame_count(), 25) << name;
    EXPECT_DOUBLE_EQ(v.fps(), 30.0) << name;
    EXPECT_EQ(v.size(), cv::Size(160, 120));
    EXPECT_NEAR(v.timestamp(15), 0.5, 1e-9);
    for (int i : {0, 1, 2, 20, 7, 24, 3, 3, 12, 0})  // forward, backward, repeated (cached)
      EXPECT_EQ(number_of(v.frame(i)), i) << name << " frame " << i;
    EXPECT_NE(error_of([&] { v.frame(25); }).find("frame 25"), std::string::npos);
  }
}

TEST_F(VideoTest, WriterLeavesNoFileWhenAbandoned) {
  const std::string path = (dir_ / "x.mp4").string();
  {
    VideoWriter w(path, 30.0, {160, 120});
    w.write(numbered_frame(0));
  }
  EXPECT_FALSE(fs::exists(path));
  EXPECT_TRUE(fs::is_empty(dir_));
}

TEST_F(VideoTest, TruncatedVideoNamesTheFrame) {
  // AVI keeps decoding up to where the data ends: the error names the first missing frame.
  const std::string avi = write_video(dir_, "t.avi", "MJPG", 30);
  fs::resize_file(avi, fs::file_size(avi) / 2);
  const std::string msg = error_of([&] {
    VideoReader v(avi);
    for (int i = 0; i < v.frame_count(); ++i) v.frame(i);
  });
  EXPECT_NE(msg.find(avi), std::string::npos) << msg;
  EXPECT_NE(msg.find("frame "), std::string::npos) << msg;
  EXPECT_NE(msg.find("truncated or corrupt"), std::string::npos) << msg;
  // MP4 keeps its index at the end: a truncated one does not open; the error says frame 0.
  const std::string mp4 = write_video(dir_, "t.mp4", "mp4v", 30);
  fs::resize_file(mp4, fs::file_size(mp4) / 2);
  const std::string msg2 = error_of([&] { VideoReader v(mp4); });
  EXPECT_NE(msg2.find("frame 0"), std::string::npos) << msg2;
}

TEST_F(VideoTest, NotAVideo) {
  const std::string text = (dir_ / "notes.mp4").string();
  std::ofstream(text) << "this is not a video\n";
  EXPECT_NE(error_of([&] { VideoReader v(text); }).find("frame 0"), std::string::npos);
  const std::string empty = (dir_ / "empty.mkv").string();
  std::ofstream{empty};
  EXPECT_NE(error_of([&] { VideoReader v(empty); }).find("empty"), std::string::npos);
  EXPECT_NE(error_of([&] { VideoReader v((dir_ / "missing.mp4").string()); }).find("not found"), std::string::npos);
}

TEST(FrameCache, KeepsTheMostRecent) {
  FrameCache c(2);
  c.put(1, numbered_frame(1));
  c.put(2, numbered_frame(2));
  EXPECT_TRUE(c.get(1));  // 1 is now the most recent
  c.put(3, numbered_frame(3));
  EXPECT_TRUE(c.get(1));
  EXPECT_FALSE(c.get(2));
  EXPECT_EQ(number_of(*c.get(3)), 3);
  EXPECT_EQ(c.size(), 2u);
}
