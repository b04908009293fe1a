// URDF loading: the benchmark robots against the facts recorded in robots.json, and small inline
// URDFs for each geometry type, joint kind, mesh path form and option of the loader.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/model/kinematics.h"
#include "core/model/mesh.h"
#include "core/model/robot_model.h"

namespace {

namespace fs = std::filesystem;
using demoplan::JointType;
using demoplan::Pose;
using demoplan::RobotModel;
using demoplan::UrdfOptions;
constexpr double kPi = std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();

const std::string kData = DEMOPLAN_DATA_DIR;

nlohmann::json robots_json() {
  std::ifstream in(kData + "/robots/robots.json");
  EXPECT_TRUE(in.good());
  return nlohmann::json::parse(in)["robots"];
}

RobotModel load_robot(const nlohmann::json& robot, const UrdfOptions& options = {}) {
  return demoplan::load_urdf(kData + "/" + robot["urdf"].get<std::string>(), options);
}

std::string type_name(JointType t) {
  switch (t) {
    case JointType::Fixed: return "fixed";
    case JointType::Revolute: return "revolute";
    case JointType::Continuous: return "continuous";
    case JointType::Prismatic: return "prismatic";
  }
  return "?";
}

template <class T>
const T& shape_as(const demoplan::Geometry& g) {
  EXPECT_TRUE(std::holds_alternative<T>(g.shape));
  return std::get<T>(g.shape);
}

// Binary STL stores its triangle count at byte 80; the loader must keep every triangle.
std::uint32_t stl_triangle_count(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char header[84];
  in.read(header, 84);
  EXPECT_TRUE(in.good()) << path;
  std::uint32_t n = 0;
  for (int i = 3; i >= 0; --i) n = (n << 8) | static_cast<unsigned char>(header[80 + i]);
  EXPECT_EQ(fs::file_size(path), 84u + 50u * n) << path << " is not a binary STL";
  return n;
}

// A fresh directory under the system temp dir, removed with everything in it.
struct TempDir {
  fs::path path;
  TempDir() {
    std::random_device rd;
    path = fs::temp_directory_path() / ("demoplan_test_urdf_" + std::to_string(rd()) + "_" +
                                        std::to_string(rd()));
    fs::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

const std::string kPandaLink0Stl = kData + "/robots/franka_panda/meshes/collision/link0.stl";

// ---------------------------------------------------------------------------------------------
// (a) Every benchmark robot: configuration joints as robots.json records them.

TEST(Urdf, RobotsMatchRobotsJson) {
  const nlohmann::json robots = robots_json();
  ASSERT_EQ(robots.size(), 4u);
  for (const char* name : {"panda", "ur5", "kuka_iiwa", "kmr_iiwa"}) {
    SCOPED_TRACE(name);
    ASSERT_TRUE(robots.contains(name));
    const nlohmann::json& r = robots[name];
    const RobotModel model = load_robot(r);
    EXPECT_EQ(model.links[0].name, r["root_link"].get<std::string>());
    ASSERT_EQ(model.nq, r["nq"].get<int>());
    const auto joints = model.configuration_joints();
    const nlohmann::json& expected = r["configuration_joints"];
    ASSERT_EQ(joints.size(), expected.size());
    for (size_t i = 0; i < joints.size(); ++i) {
      const nlohmann::json& e = expected[i];
      SCOPED_TRACE(e["name"].get<std::string>());
      ASSERT_NE(joints[i], nullptr);
      const demoplan::Joint& j = *joints[i];
      EXPECT_EQ(j.name, e["name"].get<std::string>());
      EXPECT_EQ(j.q_index, static_cast<int>(i));
      EXPECT_EQ(type_name(j.type), e["type"].get<std::string>());
      EXPECT_EQ(model.links[j.parent_link].name, e["parent_link"].get<std::string>());
      EXPECT_EQ(model.links[j.child_link].name, e["child_link"].get<std::string>());
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(j.axis[k], e["axis"][k].get<double>(), 1e-12);
      EXPECT_DOUBLE_EQ(j.limits.lower, e["lower"].get<double>());
      EXPECT_DOUBLE_EQ(j.limits.upper, e["upper"].get<double>());
      EXPECT_DOUBLE_EQ(j.limits.velocity, e["velocity"].get<double>());
      EXPECT_DOUBLE_EQ(j.limits.effort, e["effort"].get<double>());
      if (e["urdf_mimic_of"].is_null()) {
        EXPECT_FALSE(j.mimic.has_value());
      } else {
        ASSERT_TRUE(j.mimic.has_value());
        EXPECT_EQ(model.joints[j.mimic->joint].name, e["urdf_mimic_of"].get<std::string>());
      }
    }
    // The limit vectors follow the same order, and the benchmark's start is within them.
    const std::vector<double> init = r["initial_configuration"].get<std::vector<double>>();
    ASSERT_EQ(init.size(), static_cast<size_t>(model.nq));
    const Eigen::VectorXd q0 = Eigen::Map<const Eigen::VectorXd>(init.data(), model.nq);
    EXPECT_TRUE(model.within_limits(q0, 1e-9));
    for (int i = 0; i < model.nq; ++i) {
      EXPECT_DOUBLE_EQ(model.lower_limits()[i], expected[i]["lower"].get<double>());
      EXPECT_DOUBLE_EQ(model.upper_limits()[i], expected[i]["upper"].get<double>());
    }
    // Structural invariants the kinematics relies on: parents precede children.
    for (const auto& j : model.joints) EXPECT_LT(j.parent_link, j.child_link) << j.name;
  }
}

// ---------------------------------------------------------------------------------------------
// (b) KMR mobile base: x, y prismatic and theta revolute, in the robot-pose frame.

TEST(Urdf, KmrBaseJointsMoveKmrLink) {
  const nlohmann::json r = robots_json()["kmr_iiwa"];
  const RobotModel model = load_robot(r);
  const auto joints = model.configuration_joints();
  ASSERT_EQ(model.nq, 12);
  EXPECT_EQ(joints[0]->type, JointType::Prismatic);
  EXPECT_TRUE(joints[0]->axis.isApprox(Eigen::Vector3d::UnitX()));
  EXPECT_EQ(joints[1]->type, JointType::Prismatic);
  EXPECT_TRUE(joints[1]->axis.isApprox(Eigen::Vector3d::UnitY()));
  EXPECT_EQ(joints[2]->type, JointType::Revolute);
  EXPECT_TRUE(joints[2]->axis.isApprox(Eigen::Vector3d::UnitZ()));
  EXPECT_DOUBLE_EQ(joints[0]->limits.lower, -3.0);
  EXPECT_DOUBLE_EQ(joints[1]->limits.upper, 3.0);
  EXPECT_DOUBLE_EQ(joints[2]->limits.upper, 5.0);

  const int kmr = model.link_index("kmr_link");
  const int iiwa0 = model.link_index("iiwa_link_0");
  ASSERT_GE(kmr, 0);
  ASSERT_GE(iiwa0, 0);
  // The arm sits on the platform through the fixed joint kmr_to_iiwa (xyz 0.366 0.15 0.701,
  // rpy 0 0 3.14 in the URDF), so it must follow the base rigidly.
  const Pose kmr_to_iiwa = Pose(Eigen::Translation3d(0.366, 0.15, 0.701)) *
                           Pose(Eigen::AngleAxisd(3.14, Eigen::Vector3d::UnitZ()));
  const Pose base = Pose(Eigen::Translation3d(1.0, -2.0, 0.0)) *
                    Pose(Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()));

  const double samples[][3] = {{0, 0, 0}, {0.2, 2.2, -kPi}, {-1.5, 0.4, 2.5}, {3.0, -3.0, 5.0}};
  demoplan::PoseVector poses;
  for (const auto& s : samples) {
    SCOPED_TRACE("x=" + std::to_string(s[0]) + " y=" + std::to_string(s[1]) +
                 " theta=" + std::to_string(s[2]));
    Eigen::VectorXd q = Eigen::VectorXd::Zero(model.nq);
    q.head<3>() << s[0], s[1], s[2];
    q.segment<7>(3) << 0.1, -0.7, 0.2, -1.4, 0.3, 1.2, 0.5;  // the arm must not move the base
    const Pose expected = Pose(Eigen::Translation3d(s[0], s[1], 0.0)) *
                          Pose(Eigen::AngleAxisd(s[2], Eigen::Vector3d::UnitZ()));
    demoplan::forward_kinematics(model, q, Pose::Identity(), poses);
    EXPECT_TRUE(poses[kmr].isApprox(expected, 1e-12));
    EXPECT_TRUE(poses[iiwa0].isApprox(expected * kmr_to_iiwa, 1e-12));
    demoplan::forward_kinematics(model, q, base, poses);
    EXPECT_TRUE(poses[kmr].isApprox(base * expected, 1e-12));
  }
}

// ---------------------------------------------------------------------------------------------
// (c) Mimic: the second Panda finger follows the first.

TEST(Urdf, PandaFingerMimic) {
  const RobotModel model = load_robot(robots_json()["panda"]);
  const int f1 = model.joint_index("panda_finger_joint1");
  const int f2 = model.joint_index("panda_finger_joint2");
  ASSERT_GE(f1, 0);
  ASSERT_GE(f2, 0);
  EXPECT_FALSE(model.joints[f1].mimic.has_value());
  ASSERT_TRUE(model.joints[f2].mimic.has_value());
  EXPECT_EQ(model.joints[f2].mimic->joint, f1);
  EXPECT_EQ(model.joints[f2].mimic->multiplier, 1.0);
  EXPECT_EQ(model.joints[f2].mimic->offset, 0.0);
  // Both fingers keep their own configuration slot (benchmark convention).
  EXPECT_EQ(model.joints[f1].q_index, 7);
  EXPECT_EQ(model.joints[f2].q_index, 8);

  Eigen::VectorXd q(9);
  q << 0.1, -0.2, 0.3, -1.5, 0.4, 1.6, 0.5, 0.03, 0.0;
  const Eigen::VectorXd before = q;
  model.enforce_mimic(q);
  EXPECT_EQ(q[8], 0.03);
  EXPECT_EQ(q.head<8>(), before.head<8>());  // nothing else is touched

  // With the slots equal the fingers open symmetrically: 2 x 0.03 apart along the hand's y.
  demoplan::PoseVector poses;
  demoplan::forward_kinematics(model, q, Pose::Identity(), poses);
  const Pose& hand = poses[model.link_index("panda_hand")];
  const Eigen::Vector3d left = hand.inverse() * poses[model.link_index("panda_leftfinger")].translation();
  const Eigen::Vector3d right = hand.inverse() * poses[model.link_index("panda_rightfinger")].translation();
  EXPECT_TRUE(left.isApprox(Eigen::Vector3d(0, 0.03, 0.0584), 1e-12));
  EXPECT_TRUE(right.isApprox(Eigen::Vector3d(0, -0.03, 0.0584), 1e-12));
}

TEST(Urdf, MimicMultiplierAndOffset) {
  // q[follower] = multiplier * q[leader] + offset, whatever the slot order.
  const std::string xml = R"(
    <robot name="m">
      <link name="base"/> <link name="l1"/> <link name="l2"/>
      <joint name="b_follower" type="revolute">
        <parent link="base"/> <child link="l2"/> <axis xyz="0 0 1"/>
        <limit lower="-5" upper="5" effort="1" velocity="1"/>
        <mimic joint="a_leader" multiplier="-2" offset="0.25"/>
      </joint>
      <joint name="a_leader" type="revolute">
        <parent link="base"/> <child link="l1"/> <axis xyz="0 0 1"/>
        <limit lower="-1" upper="1" effort="1" velocity="1"/>
      </joint>
    </robot>)";
  const RobotModel model = demoplan::parse_urdf(xml, "mimic.urdf");
  ASSERT_EQ(model.nq, 2);
  const int leader = model.joint_index("a_leader"), follower = model.joint_index("b_follower");
  ASSERT_TRUE(model.joints[follower].mimic.has_value());
  EXPECT_EQ(model.joints[follower].mimic->joint, leader);
  EXPECT_DOUBLE_EQ(model.joints[follower].mimic->multiplier, -2.0);
  EXPECT_DOUBLE_EQ(model.joints[follower].mimic->offset, 0.25);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(2);
  q[model.joints[leader].q_index] = 0.5;
  model.enforce_mimic(q);
  EXPECT_DOUBLE_EQ(q[model.joints[follower].q_index], -0.75);
  EXPECT_DOUBLE_EQ(q[model.joints[leader].q_index], 0.5);
}

// ---------------------------------------------------------------------------------------------
// (d) Geometry and joints from inline URDFs.

TEST(Urdf, PrimitiveShapesOriginsAndColours) {
  const std::string xml = R"(
    <robot name="shapes">
      <material name="blue"><color rgba="0 0 1 0.5"/></material>
      <link name="base">
        <visual>
          <origin xyz="1 2 3" rpy="0 0 1.5707963267948966"/>
          <geometry><box size="0.1 0.2 0.3"/></geometry>
          <material name="red"><color rgba="1 0 0 1"/></material>
        </visual>
        <visual>
          <geometry><sphere radius="0.25"/></geometry>
          <material name="blue"/>
        </visual>
        <collision>
          <origin xyz="0 0 0.2" rpy="1.5707963267948966 0 0"/>
          <geometry><cylinder radius="0.05" length="0.4"/></geometry>
        </collision>
        <collision><geometry><sphere radius="0.07"/></geometry></collision>
        <collision><geometry><box size="1 2 3"/></geometry></collision>
      </link>
    </robot>)";
  const RobotModel model = demoplan::parse_urdf(xml, "/nowhere/shapes.urdf");
  EXPECT_EQ(model.name, "shapes");
  EXPECT_EQ(model.urdf_path, "/nowhere/shapes.urdf");
  ASSERT_EQ(model.links.size(), 1u);
  EXPECT_EQ(model.nq, 0);
  const demoplan::Link& base = model.links[0];
  ASSERT_EQ(base.visuals.size(), 2u);
  ASSERT_EQ(base.collisions.size(), 3u);

  EXPECT_EQ(shape_as<demoplan::BoxShape>(base.visuals[0]).size, Eigen::Vector3d(0.1, 0.2, 0.3));
  EXPECT_TRUE(base.visuals[0].origin.translation().isApprox(Eigen::Vector3d(1, 2, 3)));
  // rpy (0, 0, pi/2): x -> y, y -> -x.
  const Eigen::Matrix3d Rz90 = (Eigen::Matrix3d() << 0, -1, 0, 1, 0, 0, 0, 0, 1).finished();
  EXPECT_TRUE(base.visuals[0].origin.linear().isApprox(Rz90, 1e-12));
  EXPECT_EQ(base.visuals[0].color, Eigen::Vector4d(1, 0, 0, 1));
  EXPECT_DOUBLE_EQ(shape_as<demoplan::SphereShape>(base.visuals[1]).radius, 0.25);
  EXPECT_EQ(base.visuals[1].color, Eigen::Vector4d(0, 0, 1, 0.5));  // named global material

  const auto& cyl = shape_as<demoplan::CylinderShape>(base.collisions[0]);
  EXPECT_DOUBLE_EQ(cyl.radius, 0.05);
  EXPECT_DOUBLE_EQ(cyl.length, 0.4);
  // roll pi/2: the cylinder's z axis becomes -y.
  EXPECT_TRUE((base.collisions[0].origin.linear() * Eigen::Vector3d::UnitZ())
                  .isApprox(-Eigen::Vector3d::UnitY(), 1e-12));
  EXPECT_TRUE(base.collisions[0].origin.translation().isApprox(Eigen::Vector3d(0, 0, 0.2)));
  EXPECT_DOUBLE_EQ(shape_as<demoplan::SphereShape>(base.collisions[1]).radius, 0.07);
  EXPECT_EQ(shape_as<demoplan::BoxShape>(base.collisions[2]).size, Eigen::Vector3d(1, 2, 3));
}

TEST(Urdf, MeshPathsAbsoluteRelativeAndScale) {
  const std::string abs_mesh = kPandaLink0Stl;
  const std::string xml = R"(
    <robot name="meshes">
      <link name="base">
        <collision><geometry>
          <mesh filename=")" + abs_mesh + R"(" scale="0.001 0.002 0.003"/>
        </geometry></collision>
        <collision><geometry><mesh filename="meshes/collision/link1.stl"/></geometry></collision>
        <collision><geometry><mesh filename="../ur5/meshes/collision/base.stl"/></geometry></collision>
        <collision><geometry><mesh filename="file://)" + abs_mesh + R"("/></geometry></collision>
      </link>
    </robot>)";
  // The source path anchors relative mesh paths; the file itself need not exist.
  const std::string source = kData + "/robots/franka_panda/inline_meshes.urdf";
  const RobotModel model = demoplan::parse_urdf(xml, source);
  const auto& c = model.links[0].collisions;
  ASSERT_EQ(c.size(), 4u);

  const auto& m0 = shape_as<demoplan::MeshShape>(c[0]);
  EXPECT_TRUE(fs::equivalent(m0.path, abs_mesh));
  EXPECT_EQ(m0.scale, Eigen::Vector3d(0.001, 0.002, 0.003));
  ASSERT_NE(m0.mesh, nullptr);
  EXPECT_EQ(m0.mesh->triangles.size(), stl_triangle_count(abs_mesh));
  // The scale is recorded, not baked into the vertices (meshes are in file units).
  const Eigen::Vector3f extent = m0.mesh->bounds().sizes();
  EXPECT_GT(extent.minCoeff(), 0.05f);  // Panda link0 is ~0.1-0.2 m across in the file

  const auto& m1 = shape_as<demoplan::MeshShape>(c[1]);
  EXPECT_EQ(m1.path, fs::path(kData + "/robots/franka_panda/meshes/collision/link1.stl")
                         .lexically_normal()
                         .string());
  EXPECT_EQ(m1.scale, Eigen::Vector3d::Ones());
  ASSERT_NE(m1.mesh, nullptr);
  EXPECT_EQ(m1.mesh->triangles.size(), stl_triangle_count(m1.path));

  const auto& m2 = shape_as<demoplan::MeshShape>(c[2]);  // ".." is normalised away
  EXPECT_EQ(m2.path,
            fs::path(kData + "/robots/ur5/meshes/collision/base.stl").lexically_normal().string());
  ASSERT_NE(m2.mesh, nullptr);
  EXPECT_EQ(m2.mesh->triangles.size(), stl_triangle_count(m2.path));

  const auto& m3 = shape_as<demoplan::MeshShape>(c[3]);  // file:// URI
  EXPECT_TRUE(fs::equivalent(m3.path, abs_mesh));

  // A missing mesh is an input error naming the URDF.
  const std::string bad = R"(<robot name="b"><link name="l"><collision><geometry>
      <mesh filename="meshes/collision/no_such_mesh.stl"/></geometry></collision></link></robot>)";
  try {
    demoplan::parse_urdf(bad, source);
    FAIL() << "missing mesh accepted";
  } catch (const demoplan::InputError& e) {
    EXPECT_EQ(e.file(), source);
    EXPECT_NE(std::string(e.what()).find("no_such_mesh.stl"), std::string::npos) << e.what();
  }
}

TEST(Urdf, PackageUriResolvedThroughPackagePaths) {
  // Layout: <tmp>/empty/ (searched first, has no package) and <tmp>/share/my_pkg/meshes/part.stl.
  TempDir tmp;
  fs::create_directories(tmp.path / "empty");
  const fs::path mesh = tmp.path / "share" / "my_pkg" / "meshes" / "part.stl";
  fs::create_directories(mesh.parent_path());
  fs::copy_file(kPandaLink0Stl, mesh);

  const std::string xml = R"(<robot name="p"><link name="l">
      <visual><geometry><mesh filename="package://my_pkg/meshes/part.stl"/></geometry></visual>
      <collision><geometry><mesh filename="package://my_pkg/meshes/part.stl"/></geometry></collision>
    </link></robot>)";
  UrdfOptions options;
  options.package_paths = {(tmp.path / "empty").string(), (tmp.path / "share").string()};
  const RobotModel model = demoplan::parse_urdf(xml, "/elsewhere/p.urdf", options);
  const auto& col = shape_as<demoplan::MeshShape>(model.links[0].collisions.at(0));
  EXPECT_EQ(col.path, mesh.lexically_normal().string());
  ASSERT_NE(col.mesh, nullptr);
  EXPECT_EQ(col.mesh->triangles.size(), stl_triangle_count(kPandaLink0Stl));
  const auto& vis = shape_as<demoplan::MeshShape>(model.links[0].visuals.at(0));
  EXPECT_EQ(vis.path, mesh.lexically_normal().string());  // resolved even when not loaded
  EXPECT_EQ(vis.mesh, nullptr);

  // Without a package path that holds my_pkg, loading fails with an InputError.
  options.package_paths = {(tmp.path / "empty").string()};
  EXPECT_THROW(demoplan::parse_urdf(xml, "/elsewhere/p.urdf", options), demoplan::InputError);
  EXPECT_THROW(demoplan::parse_urdf(xml, "/elsewhere/p.urdf"), demoplan::InputError);
}

TEST(Urdf, JointKindsLimitsAndConfigurationOrder) {
  // Children of one link are ordered by joint name (urdfdom), not by file order; the
  // configuration follows the depth-first joint order with fixed joints skipped.
  const std::string xml = R"(
    <robot name="j">
      <link name="base"/> <link name="wheel"/> <link name="slider"/> <link name="tip"/>
      <joint name="z_wheel" type="continuous">
        <parent link="base"/> <child link="wheel"/> <axis xyz="0 0 2"/>
        <origin xyz="0 0.5 0" rpy="0 0 0"/>
        <limit effort="3" velocity="4"/>
      </joint>
      <joint name="a_slider" type="prismatic">
        <parent link="base"/> <child link="slider"/> <axis xyz="1 0 0"/>
        <limit lower="-0.1" upper="0.2" effort="5" velocity="0.5"/>
      </joint>
      <joint name="b_tip" type="fixed">
        <parent link="slider"/> <child link="tip"/> <origin xyz="0 0 1"/>
      </joint>
    </robot>)";
  const RobotModel model = demoplan::parse_urdf(xml, "j.urdf");
  ASSERT_EQ(model.nq, 2);
  const auto cj = model.configuration_joints();
  EXPECT_EQ(cj[0]->name, "a_slider");
  EXPECT_EQ(cj[1]->name, "z_wheel");
  EXPECT_EQ(model.joints[model.joint_index("b_tip")].q_index, -1);
  EXPECT_EQ(model.links[0].name, "base");

  const demoplan::Joint& wheel = *cj[1];
  EXPECT_EQ(wheel.type, JointType::Continuous);
  EXPECT_EQ(wheel.limits.lower, -kInf);
  EXPECT_EQ(wheel.limits.upper, kInf);
  EXPECT_DOUBLE_EQ(wheel.limits.velocity, 4.0);
  EXPECT_DOUBLE_EQ(wheel.limits.effort, 3.0);
  EXPECT_EQ(wheel.axis, Eigen::Vector3d::UnitZ());  // normalised from (0 0 2)
  EXPECT_EQ(cj[0]->type, JointType::Prismatic);
  EXPECT_DOUBLE_EQ(cj[0]->limits.lower, -0.1);
  EXPECT_DOUBLE_EQ(cj[0]->limits.upper, 0.2);

  // A continuous joint accepts any angle; a prismatic one is bounded.
  Eigen::VectorXd q(2);
  q << 0.0, 100.0;
  EXPECT_TRUE(model.within_limits(q));
  q << 0.3, 0.0;
  EXPECT_FALSE(model.within_limits(q));

  // Motion: the wheel turns about its (normalised) axis at y = 0.5; the slider moves along x
  // and carries the tip 1 m above it.
  q << 0.15, kPi / 2;
  demoplan::PoseVector poses;
  demoplan::forward_kinematics(model, q, Pose::Identity(), poses);
  const Pose& w = poses[model.link_index("wheel")];
  EXPECT_TRUE(w.translation().isApprox(Eigen::Vector3d(0, 0.5, 0)));
  EXPECT_TRUE((w.linear() * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d::UnitY(), 1e-12));
  EXPECT_TRUE(poses[model.link_index("tip")].translation().isApprox(Eigen::Vector3d(0.15, 0, 1)));
}

TEST(Urdf, FixedJointsGroupRigidBodies) {
  // base -fixed-> plate -revolute-> arm -fixed-> tool -fixed-> tip, and base -fixed-> side.
  const std::string xml = R"(
    <robot name="r">
      <link name="base"/> <link name="plate"/> <link name="arm"/> <link name="tool"/>
      <link name="tip"/> <link name="side"/>
      <joint name="j_plate" type="fixed"><parent link="base"/><child link="plate"/></joint>
      <joint name="j_side" type="fixed"><parent link="base"/><child link="side"/></joint>
      <joint name="j_arm" type="revolute"><parent link="plate"/><child link="arm"/>
        <axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
      <joint name="j_tool" type="fixed"><parent link="arm"/><child link="tool"/></joint>
      <joint name="j_tip" type="fixed"><parent link="tool"/><child link="tip"/></joint>
    </robot>)";
  const RobotModel model = demoplan::parse_urdf(xml, "r.urdf");
  const std::vector<int> body = model.rigid_bodies();
  ASSERT_EQ(body.size(), model.links.size());
  auto body_of = [&](const char* link) { return body[model.link_index(link)]; };
  const int base = model.link_index("base"), arm = model.link_index("arm");
  EXPECT_EQ(body_of("base"), base);
  EXPECT_EQ(body_of("plate"), base);
  EXPECT_EQ(body_of("side"), base);
  EXPECT_EQ(body_of("arm"), arm);
  EXPECT_EQ(body_of("tool"), arm);
  EXPECT_EQ(body_of("tip"), arm);

  // On the Panda, link7 -> link8 -> hand are welded; each finger is its own body.
  const RobotModel panda = load_robot(robots_json()["panda"]);
  const std::vector<int> pb = panda.rigid_bodies();
  const int link7 = panda.link_index("panda_link7");
  EXPECT_EQ(pb[panda.link_index("panda_link8")], link7);
  EXPECT_EQ(pb[panda.link_index("panda_hand")], link7);
  EXPECT_EQ(pb[panda.link_index("panda_leftfinger")], panda.link_index("panda_leftfinger"));
  EXPECT_EQ(pb[panda.link_index("panda_link6")], panda.link_index("panda_link6"));
}

// ---------------------------------------------------------------------------------------------
// (e) Mesh loading on the benchmark robots: collision always, visual only on request.

TEST(Urdf, CollisionMeshesLoadedVisualMeshesOnRequest) {
  const nlohmann::json robots = robots_json();
  demoplan::MeshCache cache;  // keeps the visual pass affordable across the four robots
  for (const auto& [name, r] : robots.items()) {
    SCOPED_TRACE(name);
    const RobotModel plain = load_robot(r);
    int n_collision = 0, n_visual = 0;
    for (const auto& link : plain.links) {
      for (const auto& g : link.collisions) {
        if (!std::holds_alternative<demoplan::MeshShape>(g.shape)) continue;
        const auto& m = std::get<demoplan::MeshShape>(g.shape);
        SCOPED_TRACE(link.name + " collision " + m.path);
        ++n_collision;
        EXPECT_TRUE(fs::path(m.path).is_absolute());
        ASSERT_NE(m.mesh, nullptr);
        EXPECT_GT(m.mesh->triangles.size(), 0u);
        if (fs::path(m.path).extension() == ".stl") {
          EXPECT_EQ(m.mesh->triangles.size(), stl_triangle_count(m.path));
        }
      }
      for (const auto& g : link.visuals) {
        if (!std::holds_alternative<demoplan::MeshShape>(g.shape)) continue;
        ++n_visual;
        const auto& m = std::get<demoplan::MeshShape>(g.shape);
        EXPECT_EQ(m.mesh, nullptr) << link.name << " visual loaded by default";
        EXPECT_TRUE(fs::exists(m.path)) << m.path;  // still resolved
      }
    }
    EXPECT_GE(n_collision, 1);
    EXPECT_GE(n_visual, 1);

    UrdfOptions options;
    options.load_visual_meshes = true;
    options.mesh_cache = &cache;
    const RobotModel full = load_robot(r, options);
    int loaded = 0;
    for (const auto& link : full.links)
      for (const auto& g : link.visuals)
        if (const auto* m = std::get_if<demoplan::MeshShape>(&g.shape)) {
          ASSERT_NE(m->mesh, nullptr) << link.name << " " << m->path;
          EXPECT_GT(m->mesh->triangles.size(), 0u);
          ++loaded;
        }
    EXPECT_EQ(loaded, n_visual);
  }
}

TEST(Urdf, MeshScaleKeptSeparateFromMillimetreMesh) {
  // kmr.stl is in millimetres with scale 0.001 in the URDF (README section 1). Scaled, its
  // footprint must match the KMR collision box (1.122 x 0.631 m) to within a few cm.
  UrdfOptions options;
  options.load_visual_meshes = true;
  const RobotModel model = load_robot(robots_json()["kmr_iiwa"], options);
  const demoplan::Link& kmr = model.links.at(model.link_index("kmr_link"));
  ASSERT_EQ(kmr.visuals.size(), 1u);
  const auto& m = shape_as<demoplan::MeshShape>(kmr.visuals[0]);
  EXPECT_EQ(m.scale, Eigen::Vector3d::Constant(0.001));
  ASSERT_NE(m.mesh, nullptr);
  EXPECT_EQ(m.mesh->triangles.size(), stl_triangle_count(m.path));
  const Eigen::Vector3d size = m.mesh->bounds().sizes().cast<double>().cwiseProduct(m.scale);
  EXPECT_NEAR(size.x(), 1.122, 0.05);
  EXPECT_NEAR(size.y(), 0.631, 0.05);
  ASSERT_EQ(kmr.collisions.size(), 1u);
  EXPECT_EQ(shape_as<demoplan::BoxShape>(kmr.collisions[0]).size, Eigen::Vector3d(1.122, 0.631, 0.701));
}

TEST(Urdf, MeshCacheSharesMeshesAcrossModels) {
  // The UR5 carries the Panda hand: with one cache both models hold the same mesh object.
  demoplan::MeshCache cache;
  UrdfOptions options;
  options.mesh_cache = &cache;
  const nlohmann::json robots = robots_json();
  const RobotModel panda = load_robot(robots["panda"], options);
  const RobotModel ur5 = load_robot(robots["ur5"], options);
  auto hand_mesh = [](const RobotModel& m) {
    return std::get<demoplan::MeshShape>(m.links.at(m.link_index("panda_hand")).collisions.at(0).shape)
        .mesh;
  };
  ASSERT_NE(hand_mesh(panda), nullptr);
  EXPECT_EQ(hand_mesh(panda), hand_mesh(ur5));
  // Without a cache each load reads its own copy.
  EXPECT_NE(hand_mesh(load_robot(robots["panda"])), hand_mesh(load_robot(robots["ur5"])));
}

// Mesh paths must not depend on the working directory at load time: a visual mesh that was
// not loaded is opened later, for drawing.
TEST(Urdf, RelativeSourcePathStillGivesAbsoluteMeshPath) {
  // MeshShape::path is documented as "resolved, absolute". A URDF named by a relative path
  // (e.g. a command-line argument) must not leave cwd-relative mesh paths behind.
  TempDir tmp;
  fs::copy_file(kPandaLink0Stl, tmp.path / "part.stl");
  const fs::path old_cwd = fs::current_path();
  fs::current_path(tmp.path);
  std::string path;
  try {
    const std::string xml = R"(<robot name="r"><link name="l"><collision><geometry>
        <mesh filename="part.stl"/></geometry></collision></link></robot>)";
    const RobotModel model = demoplan::parse_urdf(xml, "r.urdf");
    path = std::get<demoplan::MeshShape>(model.links[0].collisions.at(0).shape).path;
  } catch (...) {
    fs::current_path(old_cwd);
    throw;
  }
  fs::current_path(old_cwd);
  EXPECT_TRUE(fs::path(path).is_absolute()) << "got '" << path << "'";
  EXPECT_TRUE(fs::exists(path) && fs::equivalent(path, tmp.path / "part.stl")) << path;
}

}  // namespace
