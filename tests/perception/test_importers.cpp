// BOP results CSV and 100DOH hand detections: reading, writing, clear errors, and fusion.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "perception/events/hand_fusion.h"
#include "perception/importers/bop_csv.h"
#include "perception/importers/hand_detections.h"
#include "perception/tracking/bop_fusion.h"

namespace fs = std::filesystem;
using namespace demoplan;
using namespace demoplan::perception;

namespace {

class ImportTest : public ::testing::Test {
protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("demoplan_import_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string file(const std::string& name, const std::string& text) {
    const std::string p = (dir_ / name).string();
    std::ofstream(p) << text;
    return p;
  }
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

TEST_F(ImportTest, BopCsvReadsWhatCosyPoseWrites) {
  const std::string p = file("r.csv",
                             "scene_id,im_id,obj_id,score,R,t,time\n"
                             "48,0,2,0.93,1 0 0 0 0 -1 0 1 0,10.5 -20 800,0.12\n"
                             "48,1,5,0.5,1 0 0 0 1 0 0 0 1,0 0 1000,-1\n");
  const auto d = load_bop_csv(p);
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0].object_id, 2);
  EXPECT_EQ(d[0].image_id, 0);
  EXPECT_NEAR(d[0].camera_T_object.translation().z(), 0.8, 1e-12);
  EXPECT_NEAR(d[0].camera_T_object.linear()(1, 2), -1.0, 1e-12);
  EXPECT_EQ(d[1].line, 3);
  const std::string out = (dir_ / "w.csv").string();
  save_bop_csv(out, d);
  const auto back = load_bop_csv(out);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_TRUE(back[0].camera_T_object.isApprox(d[0].camera_T_object, 1e-6));
  EXPECT_EQ(bop_object_id("YCBV_12"), 12);
  EXPECT_EQ(bop_object_id("CUBOID_0.1_0.2_0.8"), -1);
}

TEST_F(ImportTest, MalformedBopLinesAreNamed) {
  const std::string head = "scene_id,im_id,obj_id,score,R,t,time\n48,0,2,0.9,1 0 0 0 1 0 0 0 1,0 0 500,-1\n";
  EXPECT_NE(error_of([&] { load_bop_csv(file("a.csv", head + "48,1,2,0.9,1 0 0 0 1 0 0 0,0 0 500,-1\n")); })
                .find("line 3: R must hold 9 numbers"),
            std::string::npos);
  EXPECT_NE(error_of([&] { load_bop_csv(file("b.csv", head + "48,1,2,0.9,2 0 0 0 1 0 0 0 1,0 0 500,-1\n")); })
                .find("line 3: R is not a rotation"),
            std::string::npos);
  EXPECT_NE(error_of([&] { load_bop_csv(file("c.csv", head + "48,x,2,0.9,1 0 0 0 1 0 0 0 1,0 0 500,-1\n")); })
                .find("line 3: im_id"),
            std::string::npos);
  EXPECT_NE(error_of([&] { load_bop_csv(file("d.csv", head + "48,1,2,0.9\n")); }).find("line 3: expected 7"),
            std::string::npos);
  // A frame beyond the video is reported when the estimates are fused.
  PoseTracks t;
  t.object_ids = {"YCBV_02"};
  t.planning = {true};
  t.resize(10);
  const auto d = load_bop_csv(file("e.csv", "scene_id,im_id,obj_id,score,R,t,time\n0,12,2,0.9,1 0 0 0 1 0 0 0 1,0 0 500,-1\n"));
  EXPECT_NE(error_of([&] { fuse_bop_detections(t, d, Pose::Identity(), "e.csv"); }).find("e.csv: line 2: im_id 12"),
            std::string::npos);
}

TEST_F(ImportTest, BopEstimatesFillTheTracks) {
  PoseTracks t;
  t.object_ids = {"YCBV_02", "YCBV_05"};
  t.planning = {true, true};
  t.resize(3);
  t.samples[0][1].valid = true;  // a marker pose: kept
  t.samples[0][1].markers = 2;
  const auto d = load_bop_csv(file("f.csv",
                                   "scene_id,im_id,obj_id,score,R,t,time\n"
                                   "0,1,2,0.9,1 0 0 0 1 0 0 0 1,0 0 500,-1\n"
                                   "0,2,2,0.8,1 0 0 0 1 0 0 0 1,0 0 600,-1\n"
                                   "0,2,2,0.4,1 0 0 0 1 0 0 0 1,0 0 900,-1\n"
                                   "0,0,9,0.8,1 0 0 0 1 0 0 0 1,0 0 600,-1\n"));
  std::vector<std::string> warnings;
  Pose world_T_camera = Pose::Identity();
  world_T_camera.translation() << 0, 0, 2;
  EXPECT_EQ(fuse_bop_detections(t, d, world_T_camera, "f.csv", 0.5, &warnings), 1);
  EXPECT_NEAR(t.samples[0][2].pose.translation().z(), 2.6, 1e-9);  // the best score wins
  EXPECT_NEAR(t.samples[0][2].confidence, 0.4, 1e-9);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("obj_id 9"), std::string::npos);
}

TEST_F(ImportTest, HandDetections) {
  const std::string p = file("h.json", R"({"format":"demoplan-hand-detections","version":1,"frames":[
     {"frame":4,"hand_dets":[[100,100,150,160,0.99,3,0.003,1.0,0.0,1]],
      "obj_dets":[[300,100,360,160,0.9],[170,100,210,160,0.8]]},
     {"frame":2,"hand_dets":[[10,10,20,20,0.9,0,0,0,0,0]],"obj_dets":[]}]})");
  const auto h = load_hand_detections(p);
  ASSERT_EQ(h.size(), 2u);
  EXPECT_EQ(h[0].frame, 2);  // sorted
  EXPECT_EQ(h[1].hands[0].contact, HandContact::Portable);
  EXPECT_TRUE(h[1].hands[0].right);
  // Hand centre (125, 130) + 0.003 * 10000 * (1, 0) = (155, 130): nearest object box is the second.
  EXPECT_EQ(contact_object(h[1], 0), 1);
  EXPECT_EQ(contact_object(h[0], 0), -1);
  const std::string out = (dir_ / "h2.json").string();
  save_hand_detections(out, h);
  EXPECT_EQ(load_hand_detections(out).size(), 2u);
  const std::string bad = file("bad.json", R"({"format":"demoplan-hand-detections","version":1,"frames":[
     {"frame":0,"hand_dets":[[1,2,3,4,0.9,7,0,0,0,1]]}]})");
  EXPECT_NE(error_of([&] { load_hand_detections(bad); }).find("frames[0].hand_dets[0][5]: contact state must be 0..4"),
            std::string::npos);
  const std::string short_row = file("short.json", R"({"format":"demoplan-hand-detections","version":1,"frames":[
     {"frame":3,"hand_dets":[[1,2,3,4,0.9]]}]})");
  EXPECT_NE(error_of([&] { load_hand_detections(short_row); }).find("frames[0].hand_dets[0]"), std::string::npos);
}

TEST(HandFusion, RunsSetAndSplitCarries) {
  PoseTracks t;
  t.object_ids = {"A"};
  t.planning = {true};
  t.resize(100);
  for (int f = 0; f < 100; ++f)
    if (f < 30 || f > 70) t.samples[0][f].valid = true;
  ContactAnalysis a;
  a.carries.push_back({0, 20, 80, 0.9, 0.9, 0.5});
  fuse_hand_contacts(a, {{0, 21, 40}, {0, 50, 78}}, t);
  ASSERT_EQ(a.carries.size(), 2u);
  EXPECT_EQ(a.carries[0].start, 21);
  EXPECT_EQ(a.carries[0].end, 41);
  EXPECT_EQ(a.carries[1].start, 50);
  EXPECT_EQ(a.carries[1].end, 79);
}
