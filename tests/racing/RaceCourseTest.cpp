// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The racing course's driver and its brick wall: the steering that brings a knocked car back to the course
// line, and a wall whose every brick above its footing can come loose.
#include <RaceSession.h>

#include <crumple/fem/TetGrid.h>

#include <catch2/catch.hpp>

#include <cmath>

using namespace crumple;
using namespace crumple::samples;

namespace
{

// A car at (x, y) on the ground heading inYaw (rad, from +x towards +y).
Transform CarAt(double inX, double inY, double inYaw)
{
    return {Eigen::AngleAxisd(inYaw, Vec3::UnitZ()).toRotationMatrix(), Vec3(inX, inY, 0.8)};
}

} // namespace

TEST_CASE("The racing driver steers back to the course line, no further than the steering allows", "[racing]")
{
    constexpr double cWheelBase = 2.8;
    // On the line and along it: straight ahead.
    CHECK(RaceCourse::SteeringAngle(CarAt(10.0, 0.0, 0.0), cWheelBase) == 0.0);
    // Left of the line (y > 0): to the right (negative), and as far to the left from the right, mirrored.
    const double left = RaceCourse::SteeringAngle(CarAt(10.0, 0.8, 0.0), cWheelBase);
    CHECK(left < 0.0);
    CHECK(RaceCourse::SteeringAngle(CarAt(10.0, -0.8, 0.0), cWheelBase) == Approx(-left).epsilon(1.0e-12));
    // Further off, more; heading back towards the line, less; heading away, more.
    CHECK(RaceCourse::SteeringAngle(CarAt(10.0, 1.6, 0.0), cWheelBase) < left);
    CHECK(RaceCourse::SteeringAngle(CarAt(10.0, 0.8, -0.05), cWheelBase) > left);
    CHECK(RaceCourse::SteeringAngle(CarAt(10.0, 0.8, 0.05), cWheelBase) < left);
    // On the line but turned 30 degrees to the left: back to the right.
    CHECK(RaceCourse::SteeringAngle(CarAt(10.0, 0.0, 0.52), cWheelBase) < 0.0);
    // Where the car is does not matter along the line.
    CHECK(RaceCourse::SteeringAngle(CarAt(55.0, 0.8, 0.0), cWheelBase) == left);
    // Far off or turned round: at the steering's limit, never past it.
    CHECK(RaceCourse::SteeringAngle(CarAt(10.0, 40.0, 0.0), cWheelBase) == -RaceCourse::cMaxSteering);
    CHECK(RaceCourse::SteeringAngle(CarAt(10.0, -40.0, 0.0), cWheelBase) == RaceCourse::cMaxSteering);
    for (double yaw = -3.1; yaw < 3.15; yaw += 0.1)
        CHECK(std::abs(RaceCourse::SteeringAngle(CarAt(10.0, 2.0, yaw), cWheelBase)) <=
              RaceCourse::cMaxSteering);
    // A small offset: the arc of pure pursuit, 2 sin(bearing) / look-ahead of curvature, through the wheel
    // base.
    const double bearing = std::atan2(-0.8, 12.0);
    CHECK(left == Approx(std::atan(2.0 * cWheelBase * std::sin(bearing) / 12.0)).epsilon(1.0e-12));
}

TEST_CASE(
    "The racing course's brick wall stands on a footing in the ground, the rest of it free to break loose",
    "[racing]")
{
    const fem::TetGridSettings grid = RaceCourse::BrickWallSettings();
    const Transform pose = RaceCourse::BrickWall();
    const double cell_height = grid.mSize.z() / grid.mCellCount[2];
    // The footing course lies in the ground (below z = 0), every course above it on or above the ground.
    CHECK(pose.mTranslation.z() + cell_height == Approx(0.0).margin(1.0e-12));
    CHECK(pose.mTranslation.z() < 0.0);
    // Across the road's left edge: the car on the course line (1.8 m wide) meets part of it, not all.
    CHECK(pose.mTranslation.y() < 0.9);
    CHECK(pose.mTranslation.y() + grid.mSize.y() > 0.9);
    // Bricks: one grid cell each, the brick's proportions (longer along the wall than thick or high).
    CHECK(grid.mSize.y() / grid.mCellCount[1] > grid.mSize.x() / grid.mCellCount[0]);
    CHECK(grid.mSize.y() / grid.mCellCount[1] > cell_height);
    REQUIRE(fem::TetGrid(grid).IsValid());
}
