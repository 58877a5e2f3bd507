// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The crush model over the shipped car meshes and the box car, in both engines: frontal, 40 % offset, pole
// and 30-degree wall at 20-64 km/h with the default material (Campbell's law, mid-size class).
#include <crumple/crash/CrashRun.h>
#include <crumple/crash/ShippedCars.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <string>
#include <vector>

using namespace crumple;
using namespace crumple::crash;

namespace
{

std::vector<std::pair<std::string, TargetSpec>> Targets()
{
    TargetSpec wall, offset, pole, angled;
    offset.mType = ETarget::OffsetWall;
    pole.mType = ETarget::Pole;
    angled.mAngleDegrees = 30.0;
    return {{"full wall", wall}, {"40 % offset", offset}, {"pole", pole}, {"30-degree wall", angled}};
}

constexpr std::array<double, 4> cSpeedsKmh{20.0, 40.0, 56.0, 64.0};

struct Run
{
    CrashOutcome mOutcome;
    double mFront = 0.0;
};

// Every body x target x speed x engine, run once for all the checks below.
const std::map<std::string, Run>& Runs()
{
    static const std::map<std::string, Run> runs = [] {
        std::map<std::string, Run> all;
        for (const NamedVehicle& body : ShippedCars())
            for (const auto& [target_name, target] : Targets())
                for (double km_h : cSpeedsKmh)
                    for (EEngine engine : {EEngine::Bullet, EEngine::Ode})
                    {
                        CrashScenario scenario;
                        scenario.mName = body.mName;
                        scenario.mEngine = engine;
                        scenario.mDuration = 0.3;
                        scenario.mVehicle = body.mVehicle;
                        scenario.mTarget = target;
                        scenario.mImpact.mSpeed = km_h / 3.6;
                        scenario.mPictures = false;
                        Result<CrashOutcome> outcome = RunCrash(scenario, {});
                        REQUIRE(outcome);
                        const std::string key = body.mName + ", " + target_name + ", " + std::to_string(static_cast<int>(km_h)) +
                                                " km/h, " + ToString(engine);
                        Run run{outcome.Get(), outcome.Get().mResidualCrush[static_cast<int>(EZone::Front)]};
                        all.emplace(key, std::move(run));
                    }
        return all;
    }();
    return runs;
}

const Run& Find(const std::string& inBody, const std::string& inTarget, double inKmh, EEngine inEngine)
{
    return Runs().at(inBody + ", " + inTarget + ", " + std::to_string(static_cast<int>(inKmh)) + " km/h, " +
                     ToString(inEngine));
}

} // namespace

// One test case per verdict, its checks as sections: the 128 crashes run once per process (about a minute
// on this project's machine with the re-cut meshes), not once per check.
TEST_CASE("Crush model: engines agree, crush grows with speed and width, the roof, the rear and the outside stay, nothing turns over, Campbell's band", "[crash][slow]")
{
    SECTION("the same crash crushes the same in Bullet and ODE, within 5 %")
    {
        for (const NamedVehicle& body : ShippedCars())
            for (const auto& [target, spec] : Targets())
                for (double km_h : cSpeedsKmh)
                {
                    const double bullet = Find(body.mName, target, km_h, EEngine::Bullet).mFront;
                    const double ode = Find(body.mName, target, km_h, EEngine::Ode).mFront;
                    INFO(body.mName << ", " << target << ", " << km_h << " km/h: Bullet " << bullet << " m, ODE " << ode << " m");
                    CHECK(std::abs(bullet - ode) <= 0.05 * std::max(bullet, ode));
                }
    }

    SECTION("front crush grows with speed in both engines")
    {
        for (const NamedVehicle& body : ShippedCars())
            for (const auto& [target, spec] : Targets())
                for (EEngine engine : {EEngine::Bullet, EEngine::Ode})
                    for (std::size_t i = 1; i < cSpeedsKmh.size(); ++i)
                    {
                        const double slower = Find(body.mName, target, cSpeedsKmh[i - 1], engine).mFront;
                        const double faster = Find(body.mName, target, cSpeedsKmh[i], engine).mFront;
                        INFO(body.mName << ", " << target << ", " << ToString(engine) << ": " << cSpeedsKmh[i - 1] << " km/h "
                                        << slower << " m, " << cSpeedsKmh[i] << " km/h " << faster << " m");
                        CHECK(faster > slower);
                    }
    }

    SECTION("a pole crushes deeper than a full wall at the same speed")
    {
        // By more than a fifth while the pole's crush has room; once it stacks up against the occupant cell
        // (DamageMaterial::mCrushZoneFraction) both crushes approach the same bound, the zone's, and the
        // pole's stays the deeper.
        for (const NamedVehicle& body : ShippedCars())
            for (double km_h : cSpeedsKmh)
                for (EEngine engine : {EEngine::Bullet, EEngine::Ode})
                {
                    const double wall = Find(body.mName, "full wall", km_h, engine).mFront;
                    const Run& pole = Find(body.mName, "pole", km_h, engine);
                    const bool stacked = pole.mOutcome.mStackedUpDents > 0;
                    INFO(body.mName << ", " << km_h << " km/h, " << ToString(engine) << ": wall " << wall << " m, pole "
                                    << pole.mFront << " m" << (stacked ? ", stacked up" : ""));
                    CHECK(pole.mFront > (stacked ? 1.0 : 1.2) * wall);
                }
    }

    SECTION("the roof moves less than 2 % of the front crush")
    {
        // The roof zone (the top fifth between the front and rear quarters) is the occupant cell's top: a
        // crush that would compact into it stacks up instead. Before the cell, every crush deeper than about
        // 0.7 m moved it, by up to 0.5 m on the box car at 64 km/h.
        for (const auto& [name, run] : Runs())
        {
            INFO(name << ": roof " << run.mOutcome.mResidualCrush[static_cast<int>(EZone::Roof)] << " m, front " << run.mFront << " m");
            CHECK(run.mOutcome.mResidualCrush[static_cast<int>(EZone::Roof)] <= 0.02 * run.mFront);
        }
    }

    SECTION("the rear never moves and no vertex moves out against the crush by more than 1 cm")
    {
        for (const auto& [name, run] : Runs())
        {
            INFO(name << ": rear " << run.mOutcome.mResidualCrush[static_cast<int>(EZone::Rear)] << " m, outward "
                      << run.mOutcome.mOutwardDisplacement << " m, front " << run.mFront << " m");
            CHECK(run.mOutcome.mResidualCrush[static_cast<int>(EZone::Rear)] <= 0.02 * run.mFront);
            CHECK(run.mOutcome.mOutwardDisplacement <= 0.01);
        }
    }

    SECTION("no triangle and no vertex normal turns over")
    {
        // Hundreds turned on the Toy Car before ffd::FlipNearlyFlatEdges took the flat caps out, and 10-23 after
        // it: caps on the front lip's creases, which no flip may remove, until ffd::SplitCaps split them (the
        // re-cut, crash::RecutCarMesh).
        for (const auto& [name, run] : Runs())
        {
            INFO(name << ": " << run.mOutcome.mFoldedTriangles << " triangles and " << run.mOutcome.mFoldedVertices
                      << " vertex normals turned over");
            CHECK(run.mOutcome.mFoldedTriangles == 0);
            CHECK(run.mOutcome.mFoldedVertices == 0);
        }
    }

    SECTION("every wall hit reports its wall gap, and the box car's flat front ends flat against a full or "
            "an offset wall")
    {
        // MeasureWallGap: a flat wall should leave a flat front. The box car's front is flat, so it must end
        // on the wall's plane to the lattice's resolution (bound 5 mm); the meshes' rounded fronts and the
        // 30-degree wall's slanted one end with gaps of centimetres (README), reported here, not bound.
        for (const NamedVehicle& body : ShippedCars())
            for (const auto& [target, spec] : Targets())
                for (double km_h : cSpeedsKmh)
                    for (EEngine engine : {EEngine::Bullet, EEngine::Ode})
                    {
                        const Run& run = Find(body.mName, target, km_h, engine);
                        const bool wall = spec.mType == ETarget::RigidWall || spec.mType == ETarget::OffsetWall;
                        REQUIRE(run.mOutcome.mWallGap.has_value() == wall);
                        if (!wall)
                            continue;
                        const WallGap& gap = *run.mOutcome.mWallGap;
                        INFO(body.mName << ", " << target << ", " << km_h << " km/h, " << ToString(engine)
                                        << ": wall gap mean " << gap.mMean << " m, largest " << gap.mLargest
                                        << " m over " << gap.mSquares << " squares");
                        CHECK(gap.mSquares > 0);
                        CHECK(std::isfinite(gap.mMean));
                        // The box car's flat front square to the wall (not the 30-degree one)
                        if (body.mName == "box car" && spec.mAngleDegrees == 0.0)
                            CHECK(gap.mLargest < 0.005);
                    }
    }

    SECTION("a 56 km/h full-width hit crushes inside Campbell's band")
    {
        // shared/data/crash/campbell_oracle.csv: 0.369-0.742 m at 56 km/h for every class (the default
        // material is the mid-size class; the bodies' masses and widths differ from it).
        for (const NamedVehicle& body : ShippedCars())
            for (EEngine engine : {EEngine::Bullet, EEngine::Ode})
            {
                const Run& run = Find(body.mName, "full wall", 56.0, engine);
                INFO(body.mName << ", " << ToString(engine) << ": front " << run.mFront
                                << " m, CRASH3 average " << run.mOutcome.mCrushProfile.Average() << " m");
                CHECK(run.mFront >= 0.369);
                CHECK(run.mFront <= 0.742);
            }
    }
}
