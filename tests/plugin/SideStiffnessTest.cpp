// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The sides' own Campbell stiffness (DamageMaterial::mHasSideStiffness): a crush across the body takes it,
// one along the body keeps the ends' stiffness, the energy split between two cars follows it, and a
// recording keeps it.
#include "BoxMesh.h"
#include "FaceCrushCollision.h"
#include "ImpulseBodies.h"
#include "ScratchDirectory.h"

#include <crumple/base/FileBytes.h>
#include <crumple/plugin/CampbellCrush.h>
#include <crumple/plugin/DamageRecorder.h>
#include <crumple/plugin/DamageWorld.h>
#include <crumple/plugin/ReplayDamage.h>

#include <catch2/catch.hpp>

#include <cstring>

using namespace crumple;
using namespace crumple::plugin;

namespace
{

const Vec3 cHalf(2.2, 0.825, 0.7); // a 4.4 m x 1.65 m x 1.4 m box car

// The mid-size defaults at the ends, and sides half as strong at onset and a quarter as stiff (CRASH3's G =
// A^2 / 2B): made-up values that only need to differ from the ends'.
DamageMaterial SoftSides()
{
    DamageMaterial material;
    material.mHasSideStiffness = true;
    material.mSideCrushA = 0.5 * material.mCrushA;
    material.mSideCrushB = 0.25 * material.mCrushB;
    material.mSideCrushG = material.mSideCrushA * material.mSideCrushA / (2.0 * material.mSideCrushB);
    return material;
}

DeformableObject MakeCar(const DamageMaterial& inMaterial)
{
    return common::MakeCrushBoxCar(cHalf, inMaterial);
}

Collision FaceCollision(const Vec3& inOutward, double inEnergy)
{
    return common::FaceCrushCollision(cHalf, inOutward, inEnergy);
}

} // namespace

TEST_CASE("CrushMaterialAlong gives the sides' stiffness to a crush nearer the width than the length",
          "[plugin]")
{
    const DamageMaterial material = SoftSides();
    BodyLength length;
    length.mAxis = Vec3::UnitX();
    const Vec3 up = Vec3::UnitZ();
    for (const Vec3& across :
         {Vec3(0.0, 1.0, 0.0), Vec3(0.0, -1.0, 0.0), Vec3(0.6, 0.8, 0.0), Vec3(-0.6, -0.8, 0.0)})
    {
        INFO("direction " << across.transpose());
        const DamageMaterial side = CrushMaterialAlong(material, across, length, up);
        CHECK(side.mCrushA == material.mSideCrushA);
        CHECK(side.mCrushB == material.mSideCrushB);
        CHECK(side.mCrushG == material.mSideCrushG);
    }
    for (const Vec3& along :
         {Vec3(1.0, 0.0, 0.0), Vec3(-1.0, 0.0, 0.0), Vec3(0.8, 0.6, 0.0), Vec3(0.0, 0.0, -1.0)})
    {
        INFO("direction " << along.transpose());
        const DamageMaterial end = CrushMaterialAlong(material, along, length, up);
        CHECK(end.mCrushA == material.mCrushA);
        CHECK(end.mCrushB == material.mCrushB);
        CHECK(end.mCrushG == material.mCrushG);
    }
    // Without the sides' stiffness every direction keeps the ends'.
    DamageMaterial plain = material;
    plain.mHasSideStiffness = false;
    CHECK(CrushMaterialAlong(plain, Vec3::UnitY(), length, up).mCrushB == plain.mCrushB);
    // Out-of-range side values are refused only when they are used.
    DamageMaterial bad = material;
    bad.mSideCrushB = 0.0;
    CHECK(ValidateDamageMaterial(bad).GetError().mMessage.find("mSideCrushB") != std::string::npos);
    bad.mHasSideStiffness = false;
    CHECK(ValidateDamageMaterial(bad).IsValid());
}

TEST_CASE(
    "A side crush is Campbell's depth with the sides' stiffness, a frontal one is unchanged bit for bit",
    "[plugin]")
{
    const DamageMaterial soft = SoftSides();
    DamageMaterial plain = soft;
    plain.mHasSideStiffness = false;
    const DeformableObject soft_car = MakeCar(soft), plain_car = MakeCar(plain);
    const double energy = 60000.0; // J: about a 1,575 kg car at 31 km/h

    const Collision side = FaceCollision(Vec3::UnitY(), energy);
    const std::optional<CrushPlan> soft_plan =
        PlanCampbellCrush(side, ECollisionSide::B, energy, soft, Vec3::UnitZ(), soft_car.GetDeformer(),
                          &soft_car.GetCrushBody());
    const std::optional<CrushPlan> plain_plan =
        PlanCampbellCrush(side, ECollisionSide::B, energy, plain, Vec3::UnitZ(), plain_car.GetDeformer(),
                          &plain_car.GetCrushBody());
    REQUIRE(soft_plan);
    REQUIRE(plain_plan);
    DamageMaterial sides_only = soft;
    sides_only.mCrushA = soft.mSideCrushA;
    sides_only.mCrushB = soft.mSideCrushB;
    sides_only.mCrushG = soft.mSideCrushG;
    INFO("side crush " << soft_plan->mDepth << " m with the sides' stiffness, " << plain_plan->mDepth
                       << " m with the ends'");
    // A flat face struck square: each plan's depth is the closed form over its width.
    CHECK(soft_plan->mDepth ==
          Approx(CampbellCrushDepth(sides_only, soft_plan->mWidth, energy)).epsilon(1.0e-9));
    CHECK(plain_plan->mDepth ==
          Approx(CampbellCrushDepth(plain, plain_plan->mWidth, energy)).epsilon(1.0e-9));
    CHECK(soft_plan->mDepth > 1.5 * plain_plan->mDepth);

    const Collision front = FaceCollision(Vec3::UnitX(), energy);
    const std::optional<CrushPlan> soft_front =
        PlanCampbellCrush(front, ECollisionSide::B, energy, soft, Vec3::UnitZ(), soft_car.GetDeformer(),
                          &soft_car.GetCrushBody());
    const std::optional<CrushPlan> plain_front =
        PlanCampbellCrush(front, ECollisionSide::B, energy, plain, Vec3::UnitZ(), plain_car.GetDeformer(),
                          &plain_car.GetCrushBody());
    REQUIRE(soft_front);
    REQUIRE(plain_front);
    CHECK(soft_front->mDepth == plain_front->mDepth);
    CHECK(soft_front->mWidth == plain_front->mWidth);

    // Through the object: the soft side's vertices move deeper, its front the same bit for bit.
    DeformableObject soft_hit = soft_car, plain_hit = plain_car;
    REQUIRE(soft_hit.ApplyCollision(side, ECollisionSide::B).IsValid());
    REQUIRE(plain_hit.ApplyCollision(side, ECollisionSide::B).IsValid());
    auto deepest_side = [](const DeformableObject& inCar)
    {
        double deepest = 0.0;
        for (std::size_t v = 0; v < inCar.GetDeformer().GetPositions().size(); ++v)
            deepest = std::max(deepest, inCar.GetDeformer().GetRestMesh().mPositions[v].y() -
                                            inCar.GetDeformer().GetPositions()[v].y());
        return deepest;
    };
    CHECK(deepest_side(soft_hit) > 1.5 * deepest_side(plain_hit));
    DeformableObject soft_front_hit = soft_car, plain_front_hit = plain_car;
    REQUIRE(soft_front_hit.ApplyCollision(front, ECollisionSide::B).IsValid());
    REQUIRE(plain_front_hit.ApplyCollision(front, ECollisionSide::B).IsValid());
    CHECK(soft_front_hit.GetDeformer().GetPositions() == plain_front_hit.GetDeformer().GetPositions());
}

TEST_CASE("Two cars share a side hit's energy by the struck side's stiffness", "[plugin]")
{
    // Car A struck in its side, car B in its front, the same footprint: with sides a quarter as stiff (B),
    // A takes 1 / (1 + 1/4) = 80 % of the energy; told nothing of A's length, half.
    const DamageMaterial soft = SoftSides();
    DamageMaterial plain = soft;
    plain.mHasSideStiffness = false;
    Collision collision;
    collision.mBodyA = BodyId{0};
    collision.mBodyB = BodyId{1};
    for (double s : {-0.8, 0.8})
    {
        CollisionContact contact;
        contact.mImpulse = 1000.0;
        contact.mAbsorbedEnergy = 5000.0;
        contact.mLocalPointOnA = Vec3(s, cHalf.y(), 0.0);
        contact.mLocalNormalOnA = -Vec3::UnitY(); // into A is +n: A's left side struck
        contact.mLocalPointOnB = Vec3(cHalf.x(), s, 0.0);
        contact.mLocalNormalOnB = Vec3::UnitX(); // B's front struck
        collision.mContacts.push_back(contact);
    }
    BodyLength length;
    length.mAxis = Vec3::UnitX();
    ShareCrushEnergy(collision, {&soft, Vec3::UnitZ(), &length}, {&plain, Vec3::UnitZ(), &length});
    CHECK(collision.mCrushEnergyA == Approx(8000.0));
    CHECK(collision.mCrushEnergyA + collision.mCrushEnergyB == Approx(10000.0));
    ShareCrushEnergy(collision, {&soft, Vec3::UnitZ()}, {&plain, Vec3::UnitZ()});
    CHECK(collision.mCrushEnergyA == Approx(5000.0));
}

TEST_CASE("A world crushes a side with its stiffness and the recording replays it bit for bit", "[plugin]")
{
    std::unique_ptr<DamageWorld> world = std::move(DamageWorld::Create().Get());
    const BodyId wall = world->CreateBody(common::StaticGround()).Get();
    // The car's left side (+y) on the plane y = 0, moving along +y into a wall there.
    BodyState car_state = common::BoxCarBeforeWall(1575.0, cHalf, 0.0);
    car_state.mTransform.mTranslation = car_state.mCenterOfMass = Vec3(0.0, -cHalf.y(), 0.0);
    car_state.mLinearVelocity = Vec3(0.0, 30.0 / 3.6, 0.0);
    const BodyId car = world->CreateBody(car_state).Get();
    DeformableObjectSettings settings;
    settings.mMesh = common::MakeBoxMesh(cHalf, common::BoxSegmentsForTriangles(cHalf, 12000));
    settings.mMaterial = SoftSides();
    settings.mFittedMaxTotalDeformation = 1.5;
    const ObjectId object = world->CreateDeformableObject(car, settings).Get();
    const std::filesystem::path path = common::ScratchDirectory() / "side_stiffness.crumple";
    Result<std::unique_ptr<DamageRecorder>> recorder = DamageRecorder::Create(path, *world);
    REQUIRE(recorder);
    std::vector<ContactEvent> contacts;
    for (double x : {-0.6, 0.6})
        for (double z : {-0.3, 0.3})
        {
            ContactEvent contact;
            contact.mBodyA = car;
            contact.mBodyB = wall;
            contact.mPointOnA = contact.mPointOnB = Vec3(x, 0.0, z);
            contact.mNormal = -Vec3::UnitY(); // from the wall (B) to the car (A)
            contacts.push_back(contact);
        }
    REQUIRE(world->SubmitContacts(contacts, 1.0 / 120.0));
    world->Flush();
    REQUIRE(recorder.Get()->Close());

    const ffd::FfdDeformer& live = world->GetObject(object)->GetDeformer();
    double deepest = 0.0;
    for (std::size_t v = 0; v < live.GetPositions().size(); ++v)
        deepest = std::max(deepest, live.GetRestMesh().mPositions[v].y() - live.GetPositions()[v].y());
    CHECK(deepest > 0.1);

    Result<Replay> replay = DecodeReplay(ReadFileBytes(path).Get());
    REQUIRE(replay);
    const DamageMaterial& read = replay.Get().mObjects[0].mSettings.mMaterial;
    CHECK(read.mHasSideStiffness);
    CHECK(read.mSideCrushA == settings.mMaterial.mSideCrushA);
    CHECK(read.mSideCrushB == settings.mMaterial.mSideCrushB);
    CHECK(read.mSideCrushG == settings.mMaterial.mSideCrushG);
    Result<std::vector<ReplayedObject>> replayed = ReplayDamage(replay.Get());
    REQUIRE(replayed);
    const std::vector<Vec3>& again = replayed.Get()[0].mDeformable.GetDeformer().GetPositions();
    REQUIRE(again.size() == live.GetPositions().size());
    CHECK(std::memcmp(again.data(), live.GetPositions().data(), again.size() * sizeof(Vec3)) == 0);
}
