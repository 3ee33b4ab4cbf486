#include "families/p2os/protocol/robot_params.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace playerkit::hardware::p2os {
namespace robot_params_test {

TEST(RobotParams, TwentyThreeRowsInTheReferencesOrder) {
  const auto table = robot_params_table();
  ASSERT_EQ(table.size(), 23u);
  const char* expected[] = {"amigo", "p2at", "p2at8+", "p2at8", "p2ce", "p2d8+", "p2d8",
                            "p2de", "p2df", "p2dx", "p2it", "p2pb", "p2pp", "p3at", "p3dx",
                            "perfpb+", "perfpb", "pion1m", "pion1x", "pionat", "powerbot",
                            "psos1m", "psos1x"};
  for (std::size_t i = 0; i < table.size(); ++i) {
    EXPECT_EQ(table[i].index, static_cast<int>(i));
    EXPECT_EQ(table[i].subclass, expected[i]);
    EXPECT_EQ(table[i].robot_class, "Pioneer");
  }
}

TEST(RobotParams, SpotChecksOfTheMainTable) {
  const RobotParams& p3dx = *find_robot_params("Pioneer", "p3dx");
  EXPECT_EQ(p3dx.index, 14);
  EXPECT_DOUBLE_EQ(p3dx.angle_conv_factor, 0.001534);
  EXPECT_DOUBLE_EQ(p3dx.diff_conv_factor, 0.0056);
  EXPECT_DOUBLE_EQ(p3dx.dist_conv_factor, 0.485);
  EXPECT_DOUBLE_EQ(p3dx.range_conv_factor, 1.0);
  EXPECT_DOUBLE_EQ(p3dx.vel_conv_factor, 1.0);
  EXPECT_EQ(p3dx.vel2_divisor, 20);
  EXPECT_EQ(p3dx.sonar_count, 16);
  EXPECT_EQ(p3dx.max_velocity, 2200);
  EXPECT_EQ(p3dx.max_rot_velocity, 500);
  EXPECT_EQ(p3dx.radius, 250);
  EXPECT_NEAR(p3dx.wheelbase(), 357.1, 0.1);
  EXPECT_EQ(p3dx.heading_units_per_turn(), 4096);

  const RobotParams& pion1x = *find_robot_params("Pioneer", "pion1x");
  EXPECT_DOUBLE_EQ(pion1x.angle_conv_factor, 0.006136);
  EXPECT_DOUBLE_EQ(pion1x.diff_conv_factor, 0.003333);
  EXPECT_DOUBLE_EQ(pion1x.dist_conv_factor, 0.05066);
  EXPECT_DOUBLE_EQ(pion1x.range_conv_factor, 0.1734);
  EXPECT_DOUBLE_EQ(pion1x.vel_conv_factor, 0.07979);
  EXPECT_EQ(pion1x.vel2_divisor, 4);
  EXPECT_EQ(pion1x.sonar_count, 7);
  EXPECT_EQ(pion1x.heading_units_per_turn(), 1024);

  const RobotParams& amigo = robot_params_table()[0];
  EXPECT_DOUBLE_EQ(amigo.vel_conv_factor, 0.6154);
  EXPECT_NEAR(amigo.wheelbase(), 181.8, 0.1);
  const RobotParams& powerbot = *find_robot_params("Pioneer", "powerbot");
  EXPECT_DOUBLE_EQ(powerbot.diff_conv_factor, 0.00373);
  EXPECT_DOUBLE_EQ(powerbot.dist_conv_factor, 0.5813);
  EXPECT_EQ(powerbot.sonar_count, 31);
  EXPECT_EQ(powerbot.max_rot_velocity, 360);
  EXPECT_EQ(powerbot.radius, 550);
}

TEST(RobotParams, EveryRowIsUsable) {
  for (const RobotParams& row : robot_params_table()) {
    EXPECT_GT(row.angle_conv_factor, 0.0) << row.subclass;
    EXPECT_GT(row.diff_conv_factor, 0.0) << row.subclass;
    EXPECT_GT(row.dist_conv_factor, 0.0) << row.subclass;
    EXPECT_GT(row.range_conv_factor, 0.0) << row.subclass;
    EXPECT_GT(row.vel_conv_factor, 0.0) << row.subclass;
    EXPECT_GT(row.vel2_divisor, 0) << row.subclass;
    EXPECT_GT(row.max_velocity, 0) << row.subclass;
    EXPECT_TRUE(row.sonar_poses.empty() ||
                static_cast<int>(row.sonar_poses.size()) == row.sonar_count)
        << row.subclass;
  }
}

TEST(RobotParams, LookupIgnoresCaseAndFallsBackToRowZero) {
  EXPECT_EQ(find_robot_params("PIONEER", "P3DX")->index, 14);
  EXPECT_EQ(find_robot_params("pioneer", "P2AT8+")->index, 2);
  EXPECT_EQ(find_robot_params("Pioneer", "p3dx-sh"), nullptr);
  EXPECT_EQ(find_robot_params("Amigo", "p3dx"), nullptr);  // class must match too
  EXPECT_EQ(select_robot_params("Pioneer", "p3dx-sh").subclass, "amigo");
  EXPECT_EQ(select_robot_params("Pioneer", "peoplebot-3").index, 0);
  EXPECT_EQ(select_robot_params("Pioneer", "p2df").index, 8);
  // Exact match only: "p2at8" is not taken for "p2at8+" nor the reverse.
  EXPECT_EQ(find_robot_params("Pioneer", "p2at8")->index, 3);
  EXPECT_EQ(find_robot_params("Pioneer", "p2at"), &robot_params_table()[1]);
}

TEST(RobotParams, SonarPosesOfSection4_3) {
  const auto p3dx = find_robot_params("Pioneer", "p3dx")->sonar_poses;
  ASSERT_EQ(p3dx.size(), 16u);
  EXPECT_EQ(p3dx[0], (SonarPose{115, 130, 90}));
  EXPECT_EQ(p3dx[3], (SonarPose{210, 25, 10}));
  EXPECT_EQ(p3dx[11], (SonarPose{-210, -25, -170}));
  EXPECT_EQ(p3dx[15], (SonarPose{-115, 130, 90}));
  for (const char* same : {"p2dx", "p2de", "p2d8", "p2d8+"}) {
    const auto poses = find_robot_params("Pioneer", same)->sonar_poses;
    EXPECT_TRUE(std::equal(poses.begin(), poses.end(), p3dx.begin(), p3dx.end())) << same;
  }
  const auto p3at = find_robot_params("Pioneer", "p3at")->sonar_poses;
  ASSERT_EQ(p3at.size(), 16u);
  EXPECT_EQ(p3at[3], (SonarPose{240, 25, 10}));
  EXPECT_EQ(p3at[9], (SonarPose{-185, -115, -130}));

  const auto amigo = find_robot_params("Pioneer", "amigo")->sonar_poses;
  ASSERT_EQ(amigo.size(), 8u);
  EXPECT_EQ(amigo[6], (SonarPose{-146, -60, -145}));

  const auto p2pb = find_robot_params("Pioneer", "p2pb")->sonar_poses;
  ASSERT_EQ(p2pb.size(), 24u);
  EXPECT_EQ(p2pb[7], p3dx[7]);
  EXPECT_EQ(p2pb[8], (SonarPose{50, 130, 90}));
  EXPECT_EQ(p2pb[15], (SonarPose{50, -130, -90}));
  EXPECT_EQ(p2pb[16], p3dx[8]);
  EXPECT_EQ(p2pb[23], p3dx[15]);

  const auto perfpb = find_robot_params("Pioneer", "perfpb+")->sonar_poses;
  ASSERT_EQ(perfpb.size(), 32u);
  EXPECT_TRUE(std::equal(p2pb.begin(), p2pb.end(), perfpb.begin()));
  EXPECT_EQ(perfpb[24], (SonarPose{-195, -130, -90}));
  EXPECT_EQ(perfpb[28], (SonarPose{-290, 25, 170}));

  // The sheet gives none for these rows.
  for (const char* none : {"p2ce", "p2df", "p2it", "p2pp", "pion1m", "pion1x", "pionat",
                           "powerbot", "psos1m", "psos1x"}) {
    EXPECT_TRUE(find_robot_params("Pioneer", none)->sonar_poses.empty()) << none;
  }
}

TEST(RobotParams, RemainingFieldsWhereTheSheetGivesThem) {
  std::set<std::string> with_extra;
  for (const RobotParams& row : robot_params_table()) {
    if (row.extra) with_extra.insert(std::string(row.subclass));
  }
  EXPECT_EQ(with_extra, (std::set<std::string>{"amigo", "p2dx", "p2de", "p2at", "p3dx", "p3at",
                                                "p2pb", "perfpb"}));
  const RobotExtraParams& p3dx = *find_robot_params("Pioneer", "p3dx")->extra;
  EXPECT_EQ(p3dx.num_front_bumpers, 5);
  EXPECT_DOUBLE_EQ(p3dx.gyro_scaler, 1.626);
  EXPECT_EQ(p3dx.laser_x, 18);
  EXPECT_EQ(p3dx.laser_y, 0);
  EXPECT_EQ(p3dx.robot_length, 500);
  EXPECT_EQ(p3dx.robot_width, 400);
  EXPECT_TRUE(p3dx.settable_vel_maxes);
  EXPECT_EQ(p3dx.switch_to_baud_rate, 38400);
  EXPECT_EQ(p3dx.laser_port, "COM3");
  EXPECT_TRUE(p3dx.holonomic);

  const RobotExtraParams& amigo = *find_robot_params("Pioneer", "amigo")->extra;
  EXPECT_EQ(amigo.num_front_bumpers, 0);
  EXPECT_EQ(amigo.laser_x, 0);
  EXPECT_EQ(amigo.robot_diagonal, 120);

  const RobotExtraParams& p2pb = *find_robot_params("Pioneer", "p2pb")->extra;
  EXPECT_TRUE(p2pb.front_bumpers);
  EXPECT_TRUE(p2pb.rear_bumpers);
  EXPECT_EQ(p2pb.laser_x, 17);
  EXPECT_EQ(p2pb.laser_y, 8);

  const RobotExtraParams& perfpb = *find_robot_params("Pioneer", "perfpb")->extra;
  EXPECT_TRUE(perfpb.table_sensing_ir);
  EXPECT_TRUE(perfpb.new_table_sensing_ir);
  EXPECT_FALSE(perfpb.request_encoder_packets);
  EXPECT_TRUE(perfpb.request_io_packets);
  EXPECT_EQ(perfpb.laser_x, 21);

  const RobotExtraParams& p3at = *find_robot_params("Pioneer", "p3at")->extra;
  EXPECT_EQ(p3at.laser_x, 160);
  EXPECT_EQ(p3at.laser_y, 7);
  EXPECT_EQ(p3at.trans_vel_max, 0);
}

}  // namespace robot_params_test
}  // namespace playerkit::hardware::p2os
