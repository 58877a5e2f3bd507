// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The rear's own Campbell stiffness (DamageMaterial::mHasRearStiffness): a hit from behind takes it, a
// frontal one keeps the front's, the sides' take precedence across the body, two cars split a rear-end hit by
// it, and a recording keeps it with the body's forward axis.
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

// The mid-size front, and a rear a third weaker at onset and half as stiff (G = A^2 / 2B): made-up values
// that only need to differ from the front's.
DamageMaterial SoftRear()
{
    DamageMaterial material;
    material.mHasRearStiffness = true;
    material.mRearCrushA = 2.0 / 3.0 * material.mCrushA;
    material.mRearCrushB = 0.5 * material.mCrushB;
    material.mRearCrushG = material.mRearCrushA * material.mRearCrushA / (2.0 * material.mRearCrushB);
    return material;
}

DamageMaterial RearOnly(const DamageMaterial& inMaterial)
{
    DamageMaterial rear = inMaterial;
    rear.mCrushA = inMaterial.mRearCrushA;
    rear.mCrushB = inMaterial.mRearCrushB;
    rear.mCrushG = inMaterial.mRearCrushG;
    return rear;
}

} // namespace

TEST_CASE("CrushMaterialAlong gives the rear's stiffness to a crush pushing the body forward", "[plugin]")
{
    const DamageMaterial material = SoftRear();
    BodyLength length;
    length.mAxis = Vec3::UnitX();
    const Vec3 up = Vec3::UnitZ();
    // A crush direction points into the body: +x into a car facing +x is a hit from behind.
    for (const Vec3& from_behind : {Vec3(1.0, 0.0, 0.0), Vec3(0.8, 0.6, 0.0), Vec3(0.8, -0.6, 0.0)})
    {
        INFO("direction " << from_behind.transpose());
        CHECK(CrushMaterialAlong(material, from_behind, length, up).mCrushB == material.mRearCrushB);
        CHECK(CrushMaterialAlong(material, from_behind, length, up).mCrushA == material.mRearCrushA);
        CHECK(CrushMaterialAlong(material, from_behind, length, up).mCrushG == material.mRearCrushG);
        // A car modelled facing -x has its rear at +x: the same crush is frontal there.
        CHECK(CrushMaterialAlong(material, from_behind, length, up, -Vec3::UnitX()).mCrushB ==
              material.mCrushB);
    }
    for (const Vec3& other :
         {Vec3(-1.0, 0.0, 0.0), Vec3(-0.8, 0.6, 0.0), Vec3(0.0, 1.0, 0.0), Vec3(0.0, 0.0, -1.0)})
    {
        INFO("direction " << other.transpose());
        CHECK(CrushMaterialAlong(material, other, length, up).mCrushB == material.mCrushB);
    }
    // Across the body the sides' stiffness takes precedence; along it the rear's still applies.
    DamageMaterial both = material;
    both.mHasSideStiffness = true;
    both.mSideCrushA = 0.1 * material.mCrushA;
    both.mSideCrushB = 0.1 * material.mCrushB;
    both.mSideCrushG = 1.0;
    CHECK(CrushMaterialAlong(both, Vec3(0.6, 0.8, 0.0), length, up).mCrushB == both.mSideCrushB);
    CHECK(CrushMaterialAlong(both, Vec3(0.8, 0.6, 0.0), length, up).mCrushB == both.mRearCrushB);
    // Out-of-range rear values are refused only when they are used.
    DamageMaterial bad = material;
    bad.mRearCrushG = -1.0;
    CHECK(ValidateDamageMaterial(bad).GetError().mMessage.find("mRearCrushG") != std::string::npos);
    bad.mHasRearStiffness = false;
    CHECK(ValidateDamageMaterial(bad).IsValid());
}

TEST_CASE("A hit from behind crushes Campbell's depth with the rear's stiffness, a frontal one is unchanged "
          "bit for bit",
          "[plugin]")
{
    const DamageMaterial soft = SoftRear();
    DamageMaterial plain = soft;
    plain.mHasRearStiffness = false;
    const DeformableObject soft_car = common::MakeCrushBoxCar(cHalf, soft);
    const DeformableObject plain_car = common::MakeCrushBoxCar(cHalf, plain);
    const double energy = 60000.0; // J: about a 1,575 kg car at 31 km/h

    const Collision rear = common::FaceCrushCollision(cHalf, -Vec3::UnitX(), energy);
    const std::optional<CrushPlan> soft_plan =
        PlanCampbellCrush(rear, ECollisionSide::B, energy, soft, Vec3::UnitZ(), soft_car.GetDeformer(),
                          &soft_car.GetCrushBody());
    const std::optional<CrushPlan> plain_plan =
        PlanCampbellCrush(rear, ECollisionSide::B, energy, plain, Vec3::UnitZ(), plain_car.GetDeformer(),
                          &plain_car.GetCrushBody());
    REQUIRE(soft_plan);
    REQUIRE(plain_plan);
    INFO("rear crush " << soft_plan->mDepth << " m with the rear's stiffness, " << plain_plan->mDepth
                       << " m with the front's");
    CHECK(soft_plan->mDirection.x() > 0.99); // into the body from behind
    // A flat face struck square: each plan's depth is the closed form over its width.
    CHECK(soft_plan->mDepth ==
          Approx(CampbellCrushDepth(RearOnly(soft), soft_plan->mWidth, energy)).epsilon(1.0e-9));
    CHECK(plain_plan->mDepth ==
          Approx(CampbellCrushDepth(plain, plain_plan->mWidth, energy)).epsilon(1.0e-9));
    CHECK(soft_plan->mDepth > 1.2 * plain_plan->mDepth);

    // The car modelled facing -x: the same face is its front, and crushes with the front's stiffness.
    const DeformableObject backwards_car = common::MakeCrushBoxCar(cHalf, soft, -Vec3::UnitX());
    const std::optional<CrushPlan> backwards =
        PlanCampbellCrush(rear, ECollisionSide::B, energy, soft, Vec3::UnitZ(), backwards_car.GetDeformer(),
                          &backwards_car.GetCrushBody());
    REQUIRE(backwards);
    CHECK(backwards->mDepth == plain_plan->mDepth);

    // Through the object: the front the same bit for bit, the rear deeper.
    const Collision front = common::FaceCrushCollision(cHalf, Vec3::UnitX(), energy);
    DeformableObject soft_front = soft_car, plain_front = plain_car;
    REQUIRE(soft_front.ApplyCollision(front, ECollisionSide::B).IsValid());
    REQUIRE(plain_front.ApplyCollision(front, ECollisionSide::B).IsValid());
    CHECK(soft_front.GetDeformer().GetPositions() == plain_front.GetDeformer().GetPositions());
    DeformableObject soft_rear = soft_car, plain_rear = plain_car;
    REQUIRE(soft_rear.ApplyCollision(rear, ECollisionSide::B).IsValid());
    REQUIRE(plain_rear.ApplyCollision(rear, ECollisionSide::B).IsValid());
    auto deepest_rear = [](const DeformableObject& inCar)
    {
        double deepest = 0.0;
        for (std::size_t v = 0; v < inCar.GetDeformer().GetPositions().size(); ++v)
            deepest = std::max(deepest, inCar.GetDeformer().GetPositions()[v].x() -
                                            inCar.GetDeformer().GetRestMesh().mPositions[v].x());
        return deepest;
    };
    CHECK(deepest_rear(soft_rear) > 1.2 * deepest_rear(plain_rear));
}

TEST_CASE("A rear-end hit's energy is shared by the struck rear's stiffness", "[plugin]")
{
    // Car A struck from behind by car B's front, the same footprint: with a rear half as stiff (B), A takes
    // 1 / (1 + 1/2) of the energy; with the front's stiffness at both ends, half.
    const DamageMaterial soft = SoftRear();
    DamageMaterial plain = soft;
    plain.mHasRearStiffness = false;
    Collision collision;
    collision.mBodyA = BodyId{0};
    collision.mBodyB = BodyId{1};
    for (double s : {-0.6, 0.6})
    {
        CollisionContact contact;
        contact.mImpulse = 1000.0;
        contact.mAbsorbedEnergy = 6000.0;
        contact.mLocalPointOnA = Vec3(-cHalf.x(), s, 0.0);
        contact.mLocalNormalOnA = Vec3::UnitX(); // into A is +x: A's rear struck
        contact.mLocalPointOnB = Vec3(cHalf.x(), s, 0.0);
        contact.mLocalNormalOnB = Vec3::UnitX(); // into B is -x: B's front struck
        collision.mContacts.push_back(contact);
    }
    BodyLength length;
    length.mAxis = Vec3::UnitX();
    ShareCrushEnergy(collision, {&soft, Vec3::UnitZ(), &length, Vec3::UnitX()},
                     {&plain, Vec3::UnitZ(), &length, Vec3::UnitX()});
    CHECK(collision.mCrushEnergyA == Approx(8000.0));
    CHECK(collision.mCrushEnergyA + collision.mCrushEnergyB == Approx(12000.0));
    ShareCrushEnergy(collision, {&plain, Vec3::UnitZ(), &length, Vec3::UnitX()},
                     {&plain, Vec3::UnitZ(), &length, Vec3::UnitX()});
    CHECK(collision.mCrushEnergyA == Approx(6000.0));
}

TEST_CASE("A body's forward axis is checked when its material has the rear's stiffness", "[plugin]")
{
    DeformableObjectSettings settings;
    settings.mMesh = common::MakeBoxMesh(cHalf, common::BoxSegmentsForTriangles(cHalf, 2000));
    settings.mMaterial = SoftRear();
    for (const Vec3& forward : {Vec3(0.0, 0.0, 1.0), Vec3(2.0, 0.0, 0.0), Vec3(std::nan(""), 0.0, 0.0)})
    {
        INFO("forward " << forward.transpose());
        settings.mForwardAxis = forward;
        const Result<DeformableObject> refused = DeformableObject::Create(settings);
        REQUIRE_FALSE(refused);
        CHECK(refused.GetError().mMessage.find("mForwardAxis") != std::string::npos);
    }
    settings.mForwardAxis = Vec3::UnitY();
    CHECK(DeformableObject::Create(settings));
    // A material without the rear's stiffness never reads it.
    settings.mMaterial.mHasRearStiffness = false;
    settings.mForwardAxis = Vec3::Zero();
    CHECK(DeformableObject::Create(settings));
}

TEST_CASE("A world crushes a rear with its stiffness and the recording replays it bit for bit", "[plugin]")
{
    // The car modelled facing -x (its rear at +x), moving along +x tail first into a wall at x = 0.
    std::unique_ptr<DamageWorld> world = std::move(DamageWorld::Create().Get());
    const BodyId wall = world->CreateBody(common::StaticGround()).Get();
    const BodyState car_state = common::BoxCarBeforeWall(1575.0, cHalf, 30.0 / 3.6);
    const BodyId car = world->CreateBody(car_state).Get();
    DeformableObjectSettings settings;
    settings.mMesh = common::MakeBoxMesh(cHalf, common::BoxSegmentsForTriangles(cHalf, 12000));
    settings.mMaterial = SoftRear();
    settings.mFittedMaxTotalDeformation = 1.5;
    settings.mForwardAxis = -Vec3::UnitX();
    const ObjectId object = world->CreateDeformableObject(car, settings).Get();
    const std::filesystem::path path = common::ScratchDirectory() / "rear_stiffness.crumple";
    Result<std::unique_ptr<DamageRecorder>> recorder = DamageRecorder::Create(path, *world);
    REQUIRE(recorder);
    std::vector<ContactEvent> contacts;
    for (double y : {-0.6, 0.6})
        for (double z : {-0.3, 0.3})
        {
            ContactEvent contact;
            contact.mBodyA = car;
            contact.mBodyB = wall;
            contact.mPointOnA = contact.mPointOnB = Vec3(0.0, y, z);
            contact.mNormal = -Vec3::UnitX(); // from the wall (B) to the car (A)
            contacts.push_back(contact);
        }
    REQUIRE(world->SubmitContacts(contacts, 1.0 / 120.0));
    world->Flush();
    REQUIRE(recorder.Get()->Close());

    // The same hit on a car whose rear is the front's: the rear's stiffness crushed deeper.
    const ffd::FfdDeformer& live = world->GetObject(object)->GetDeformer();
    auto deepest = [](const ffd::FfdDeformer& inDeformer)
    {
        double depth = 0.0;
        for (std::size_t v = 0; v < inDeformer.GetPositions().size(); ++v)
            depth = std::max(depth,
                             inDeformer.GetRestMesh().mPositions[v].x() - inDeformer.GetPositions()[v].x());
        return depth;
    };
    CHECK(deepest(live) > 0.1);

    Result<Replay> replay = DecodeReplay(ReadFileBytes(path).Get());
    REQUIRE(replay);
    const DeformableObjectSettings& read = replay.Get().mObjects[0].mSettings;
    CHECK(read.mMaterial.mHasRearStiffness);
    CHECK(read.mMaterial.mRearCrushA == settings.mMaterial.mRearCrushA);
    CHECK(read.mMaterial.mRearCrushB == settings.mMaterial.mRearCrushB);
    CHECK(read.mMaterial.mRearCrushG == settings.mMaterial.mRearCrushG);
    CHECK(read.mForwardAxis == settings.mForwardAxis);
    Result<std::vector<ReplayedObject>> replayed = ReplayDamage(replay.Get());
    REQUIRE(replayed);
    const std::vector<Vec3>& again = replayed.Get()[0].mDeformable.GetDeformer().GetPositions();
    REQUIRE(again.size() == live.GetPositions().size());
    CHECK(std::memcmp(again.data(), live.GetPositions().data(), again.size() * sizeof(Vec3)) == 0);
}
