// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "BoxMesh.h"
#include "ImpulseBodies.h"
#include "ScratchDirectory.h"

#include <crumple/base/FileBytes.h>
#include <crumple/plugin/CampbellCrush.h>
#include <crumple/plugin/DamageRecorder.h>
#include <crumple/plugin/DamageWorld.h>
#include <crumple/plugin/ReplayDamage.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <optional>
#include <vector>

using namespace crumple;
using namespace crumple::plugin;

namespace
{

constexpr double cMass = 1575.0; // the oracle's mid-size car (DamageMaterial's default A, B, G)

// A static impactor's shape box in its own frame (the world frame: the impactor sits at the origin).
struct ShapeBounds
{
    Vec3 mMin, mMax;
};

// The wall ahead of the car: 2 m thick behind the plane x = 0, 10 m wide, 6 m tall.
const ShapeBounds cWall{Vec3(0.0, -5.0, -3.0), Vec3(2.0, 5.0, 3.0)};

// A 4.4 m x 1.65 m x 1.4 m Campbell box car whose front face is at x = 0, before a static impactor whose
// shape the world is told (or not, as a body without BodyState::mHasShapeBounds).
struct FaceCar
{
    explicit FaceCar(const std::optional<ShapeBounds>& inImpactor)
        : mWorldOwner(std::move(DamageWorld::Create().Get())), mWorld(*mWorldOwner)
    {
        BodyState impactor;
        impactor.mMotionType = EMotionType::Static;
        if (inImpactor)
        {
            impactor.mHasShapeBounds = true;
            impactor.mShapeMin = inImpactor->mMin;
            impactor.mShapeMax = inImpactor->mMax;
        }
        mImpactor = mWorld.CreateBody(impactor).Get();
        mCar = mWorld.CreateBody(State(0.0)).Get();
        DeformableObjectSettings car;
        car.mMesh = common::MakeBoxMesh(mHalf, common::BoxSegmentsForTriangles(mHalf, 20000));
        car.mMaterial.mModel = ECrushModel::Campbell;
        car.mMaterial.mMaxInstantDeformation = 1.5;
        car.mFittedMaxTotalDeformation = 1.5;
        mObject = mWorld.CreateDeformableObject(mCar, car).Get();
    }

    BodyState State(double inSpeed) const
    {
        BodyState car = common::BoxCarBeforeWall(cMass, mHalf, inSpeed);
        // The car's own shape: the box (what an adapter states for a box collision shape).
        car.mHasShapeBounds = true;
        car.mShapeMin = -mHalf;
        car.mShapeMax = mHalf;
        return car;
    }

    // Hits the impactor at inSpeed (m/s, along +x) with contacts on the front face at y = inYs, z = +-0.6.
    void Hit(double inSpeed, const std::vector<double>& inYs)
    {
        REQUIRE(mWorld.SetBodyState(mCar, State(inSpeed)));
        std::vector<ContactEvent> contacts;
        for (double y : inYs)
            for (double z : {-0.6, 0.6})
            {
                ContactEvent contact;
                contact.mBodyA = mImpactor;
                contact.mBodyB = mCar;
                contact.mPointOnA = Vec3(0.0, y, z);
                contact.mPointOnB = Vec3(0.0, y, z);
                contact.mNormal = Vec3::UnitX(); // from the car (B) to the impactor (A)
                contacts.push_back(contact);
            }
        REQUIRE(mWorld.SubmitContacts(contacts, 1.0 / 120.0));
        mWorld.Flush();
    }

    const ffd::FfdDeformer& Deformer() const { return mWorld.GetObject(mObject)->GetDeformer(); }
    const DamageMaterial& Material() const { return mWorld.GetObject(mObject)->GetMaterial(); }

    // Deepest and shallowest backward move of the front face's vertices (rest x = 2.2) with rest y in
    // [inLow, inHigh] (m).
    std::pair<double, double> FrontCrush(double inLow = -10.0, double inHigh = 10.0) const
    {
        double deepest = 0.0, shallowest = 1.0e9;
        for (std::size_t v = 0; v < Deformer().GetPositions().size(); ++v)
        {
            const Vec3& rest = Deformer().GetRestMesh().mPositions[v];
            if (rest.x() > mHalf.x() - 1.0e-9 && rest.y() >= inLow && rest.y() <= inHigh)
            {
                const double crush = rest.x() - Deformer().GetPositions()[v].x();
                deepest = std::max(deepest, crush);
                shallowest = std::min(shallowest, crush);
            }
        }
        return {deepest, shallowest};
    }

    // The kinetic energy a hit at inSpeed gives the crush: (1 - e^2) of it with the world's restitution e.
    double Absorbed(double inSpeed) const
    {
        const double e = mWorld.GetSettings().mRestitution;
        return (1.0 - e * e) * 0.5 * cMass * inSpeed * inSpeed;
    }

    Vec3 mHalf{2.2, 0.825, 0.7};
    std::unique_ptr<DamageWorld> mWorldOwner; // on the heap: the world never moves
    DamageWorld& mWorld;
    BodyId mImpactor, mCar;
    ObjectId mObject;
};

} // namespace

TEST_CASE("A wall's face reaches past its contacts: one contact column crushes the whole front by Campbell's depth", "[plugin]")
{
    // An engine that reports the wall's contact at one place of a flat front (a hull's tip, a manifold of
    // one) gives the crush the same width as one that reports the face's corners, once the wall's shape is
    // known: the wall meets the whole front as it advances.
    const double v = 40.0 / 3.6;
    FaceCar point(cWall), corners(cWall), unknown(std::nullopt);
    point.Hit(v, {0.0});
    corners.Hit(v, {-0.825, 0.825});
    unknown.Hit(v, {0.0});
    const double expected = CampbellCrushDepth(point.Material(), 2.0 * point.mHalf.y(), point.Absorbed(v));
    const auto [deepest, shallowest] = point.FrontCrush();
    INFO("one column: " << deepest << " to " << shallowest << " m; the corners " << corners.FrontCrush().first
                        << " m; shape unknown " << unknown.FrontCrush().first << " m; Campbell " << expected << " m");
    CHECK(deepest == Approx(expected).epsilon(0.05));
    CHECK(deepest == Approx(corners.FrontCrush().first).epsilon(1.0e-6));
    // Flat: every vertex of the front face, out to its edges, crushed by 90 % of the deepest at least.
    CHECK(shallowest >= 0.9 * deepest);
    // Without the wall's shape the one column is all the crush knows: a pole's pocket, deeper.
    CHECK(unknown.FrontCrush().first > 1.3 * deepest);
}

TEST_CASE("An offset wall crushes its own share of the front, and a pole's shape keeps its pocket narrow", "[plugin]")
{
    const double v = 30.0 / 3.6;
    SECTION("40 % offset")
    {
        // The wall covers y >= 0.165, 40 % of the 1.65 m front; the engine's contacts lie at its edge.
        FaceCar car(ShapeBounds{Vec3(0.0, 0.165, -3.0), Vec3(2.0, 10.0, 3.0)});
        car.Hit(v, {0.165});
        const double share = car.mHalf.y() - 0.165;
        const double expected = CampbellCrushDepth(car.Material(), share, car.Absorbed(v));
        const auto [deepest, shallowest] = car.FrontCrush(0.165 + car.Deformer().GetMinSpacing(), 10.0);
        INFO("struck share " << deepest << " to " << shallowest << " m, Campbell for " << share << " m: " << expected << " m");
        CHECK(deepest == Approx(expected).epsilon(0.05));
        CHECK(shallowest >= 0.9 * deepest);
        // The far side, beyond the pocket wall's fade (C / (2 sqrt(kappa)) and the spline's two spacings),
        // does not move.
        const double fade = deepest / (2.0 * std::sqrt(car.Material().mCrushedLengthFraction)) + 3.0 * car.Deformer().GetMinSpacing();
        CHECK(car.FrontCrush(-10.0, 0.165 - fade).first == 0.0);
    }
    SECTION("pole")
    {
        // A 0.3 m pole, narrower than the material's minimum crush width: its shape changes nothing across.
        FaceCar known(ShapeBounds{Vec3(0.0, -0.15, -3.0), Vec3(0.3, 0.15, 3.0)}), unknown(std::nullopt);
        known.Hit(v, {0.0});
        unknown.Hit(v, {0.0});
        INFO("pole known " << known.FrontCrush().first << " m, unknown " << unknown.FrontCrush().first << " m");
        CHECK(known.FrontCrush().first == Approx(unknown.FrontCrush().first).epsilon(0.02));
        const double reach = 0.5 * known.Material().mMinCrushWidth +
                             std::max(2.0 * known.Deformer().GetMinSpacing(), known.FrontCrush().first) +
                             3.0 * known.Deformer().GetMinSpacing();
        CHECK(known.FrontCrush(reach, 10.0).first == 0.0);
        CHECK(known.FrontCrush(-10.0, -reach).first == 0.0);
    }
}

TEST_CASE("A collision's shape boxes are recorded and replay the crush bit for bit", "[plugin]")
{
    FaceCar car(cWall);
    const std::filesystem::path path = common::ScratchDirectory() / "impactor_face.crumple";
    Result<std::unique_ptr<DamageRecorder>> recorder = DamageRecorder::Create(path, car.mWorld);
    REQUIRE(recorder);
    car.Hit(12.0, {0.3});
    REQUIRE(recorder.Get()->Close());
    Result<Replay> replay = DecodeReplay(ReadFileBytes(path).Get());
    REQUIRE(replay);
    REQUIRE(replay.Get().mCollisions.size() == 1);
    const Collision& collision = replay.Get().mCollisions[0];
    // A is the wall (created first): B's box on A is the car's, A's box on B the wall's in the car's frame.
    REQUIRE(collision.mShapeOfAOnB.mKnown);
    REQUIRE(collision.mShapeOfBOnA.mKnown);
    CHECK(collision.mShapeOfAOnB.ExtentAlong(Vec3::UnitY())[0] == Approx(-5.0));
    CHECK(collision.mShapeOfAOnB.ExtentAlong(Vec3::UnitX())[0] == Approx(car.mHalf.x()));
    CHECK(collision.mShapeOfBOnA.ExtentAlong(Vec3::UnitX())[1] == Approx(0.0).margin(1.0e-12));
    Result<std::vector<ReplayedObject>> replayed = ReplayDamage(replay.Get());
    REQUIRE(replayed);
    const std::vector<Vec3>& live = car.Deformer().GetPositions();
    const std::vector<Vec3>& again = replayed.Get()[0].mDeformable.GetDeformer().GetPositions();
    REQUIRE(live.size() == again.size());
    CHECK(std::memcmp(live.data(), again.data(), live.size() * sizeof(Vec3)) == 0);
    CHECK(car.FrontCrush().first > 0.1);
}

TEST_CASE("A body state's shape bounds are checked, and a refused one changes nothing", "[plugin]")
{
    FaceCar car(cWall);
    const BodyState before = *car.mWorld.GetBodyState(car.mCar);
    const auto refused = [&](const BodyState& inState, const char* inField) {
        const Status status = car.mWorld.SetBodyState(car.mCar, inState);
        REQUIRE_FALSE(status);
        CHECK(status.GetError().mMessage.find(inField) != std::string::npos);
        CHECK(car.mWorld.GetBodyState(car.mCar)->mShapeMax == before.mShapeMax);
    };
    BodyState state = car.State(0.0);
    state.mShapeMin.x() = std::nan("");
    refused(state, "mShapeMin");
    state = car.State(0.0);
    state.mShapeMax.y() = std::numeric_limits<double>::infinity();
    refused(state, "mShapeMax");
    state = car.State(0.0);
    state.mShapeMax.z() = 2.0e9;
    refused(state, "1e9");
    state = car.State(0.0);
    state.mShapeMin.x() = 3.0; // above mShapeMax.x() = 2.2
    refused(state, "above mShapeMax");
    // Without mHasShapeBounds the fields are not read.
    state = car.State(0.0);
    state.mHasShapeBounds = false;
    state.mShapeMin.x() = std::nan("");
    CHECK(car.mWorld.SetBodyState(car.mCar, state));
}
