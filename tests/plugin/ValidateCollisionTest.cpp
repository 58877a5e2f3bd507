// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// A collision made by hand (or read from a file) is checked before it dents: ValidateCollision's codes, and
// DeformableObject::ApplyCollision and ApplyReplayedCollisions refusing it whole, changing no vertex or
// control.
#include "BoxMesh.h"

#include <crumple/plugin/DeformableObject.h>
#include <crumple/plugin/ReplayDamage.h>

#include <catch2/catch.hpp>

#include <functional>
#include <limits>
#include <string>

using namespace crumple;
using namespace crumple::plugin;

namespace
{

constexpr double cNan = std::numeric_limits<double>::quiet_NaN();
constexpr double cInf = std::numeric_limits<double>::infinity();

DeformableObject MakeCar(ECrushModel inModel)
{
    DeformableObjectSettings settings;
    settings.mFittedControlCount = {8, 6, 6};
    settings.mMesh = common::MakeBoxMesh(Vec3(2.1, 0.9, 0.7), {12, 6, 6});
    settings.mMaterial.mModel = inModel;
    return DeformableObject::Create(settings).Get();
}

// Two contacts on the car's front (the car is body B; the normal from B to A is +x), with a friction impulse
// inside its cone and a crush energy for each side: a collision that dents in either crush model.
Collision FrontCollision()
{
    Collision collision;
    collision.mBodyA = BodyId{0};
    collision.mBodyB = BodyId{1};
    collision.mEndTime = 0.05;
    collision.mCrushEnergyA = 1.0e4;
    collision.mCrushEnergyB = 1.0e5;
    for (double y : {-0.4, 0.4})
    {
        CollisionContact contact;
        contact.mPointOnB = contact.mLocalPointOnB = Vec3(2.1, y, 0.0);
        contact.mPointOnA = contact.mLocalPointOnA = Vec3(2.1, y, 0.0);
        contact.mNormal = contact.mLocalNormalOnB = Vec3::UnitX();
        contact.mLocalNormalOnA = -Vec3::UnitX();
        contact.mImpulse = 8000.0;
        contact.mFriction = 0.5;
        contact.mFrictionImpulse = contact.mLocalFrictionOnA = Vec3(0.0, 100.0, 0.0);
        contact.mLocalFrictionOnB = Vec3(0.0, -100.0, 0.0);
        contact.mApproachSpeed = 15.0;
        contact.mAbsorbedEnergy = 5.0e4;
        collision.mContacts.push_back(contact);
    }
    return collision;
}

struct Spoil
{
    const char* mName;
    EError mCode;
    std::function<void(Collision&)> mApply;
};

const std::vector<Spoil>& Spoils()
{
    static const std::vector<Spoil> spoils{
        {"a NaN point", EError::NonFinite, [](Collision& c) { c.mContacts[1].mLocalPointOnB.y() = cNan; }},
        {"an infinite impulse", EError::NonFinite, [](Collision& c) { c.mContacts[0].mImpulse = cInf; }},
        {"a NaN friction coefficient", EError::NonFinite,
         [](Collision& c) { c.mContacts[0].mFriction = cNan; }},
        {"a NaN start time", EError::NonFinite, [](Collision& c) { c.mStartTime = cNan; }},
        {"a NaN crush energy", EError::NonFinite, [](Collision& c) { c.mCrushEnergyB = cNan; }},
        {"an infinite shape box", EError::NonFinite,
         [](Collision& c) { c.mShapeOfBOnA.mCenter.x() = -cInf; }},
        {"a negative impulse", EError::InvalidArgument, [](Collision& c) { c.mContacts[1].mImpulse = -1.0; }},
        {"a negative crush energy", EError::InvalidArgument, [](Collision& c) { c.mCrushEnergyA = -1.0; }},
        {"a normal that is not unit", EError::InvalidArgument,
         [](Collision& c) { c.mContacts[0].mLocalNormalOnB *= 2.0; }},
        {"friction outside its cone", EError::InvalidArgument,
         [](Collision& c) { c.mContacts[0].mFrictionImpulse = Vec3(0.0, 5000.0, 0.0); }},
        {"an impulse past 1e30 N s", EError::OutOfRange,
         [](Collision& c) { c.mContacts[0].mImpulse = 1.0e31; }},
        {"an energy past 1e50 J", EError::OutOfRange,
         [](Collision& c) { c.mContacts[1].mAbsorbedEnergy = 1.0e51; }},
        {"a shape box past 1e10 m", EError::OutOfRange,
         [](Collision& c) { c.mShapeOfAOnB.mHalfAxes(2, 2) = 1.0e11; }},
    };
    return spoils;
}

} // namespace

TEST_CASE("ValidateCollision passes a sound collision and names what is wrong with a spoiled one", "[plugin]")
{
    CHECK(ValidateCollision(FrontCollision()).IsValid());
    CHECK(ValidateCollision(Collision{}).IsValid()); // no contacts: nothing to dent, nothing wrong
    Collision sticky = FrontCollision();
    sticky.mContacts[0].mFriction = cInf; // a surface that never slides
    CHECK(ValidateCollision(sticky).IsValid());
    for (const Spoil& spoil : Spoils())
    {
        INFO(spoil.mName);
        Collision spoiled = FrontCollision();
        spoil.mApply(spoiled);
        const Status status = ValidateCollision(spoiled);
        REQUIRE(status.HasError());
        CHECK(status.GetError().mCode == spoil.mCode);
        CHECK_FALSE(status.GetError().mMessage.empty());
    }
}

TEST_CASE("ApplyCollision refuses a spoiled collision whole in both crush models, denting nothing",
          "[plugin]")
{
    for (ECrushModel model : {ECrushModel::ImpulseFactor, ECrushModel::Campbell})
    {
        INFO("crush model " << static_cast<int>(model));
        const DeformableObject pristine = MakeCar(model);
        // The sound collision dents: the refusals below are not a dent that would have moved nothing.
        DeformableObject dented = pristine;
        const Result<ffd::DentReport> dent = dented.ApplyCollision(FrontCollision(), ECollisionSide::B);
        REQUIRE(dent.IsValid());
        REQUIRE(dent.Get().mVerticesMoved > 0);
        for (const Spoil& spoil : Spoils())
        {
            INFO(spoil.mName);
            Collision spoiled = FrontCollision();
            spoil.mApply(spoiled);
            DeformableObject object = pristine;
            const Result<ffd::DentReport> refused = object.ApplyCollision(spoiled, ECollisionSide::B);
            REQUIRE(refused.HasError());
            CHECK(refused.GetError().mCode == spoil.mCode);
            CHECK(object.GetDeformer().GetPositions() == pristine.GetDeformer().GetPositions());
            CHECK(object.GetDeformer().GetNormals() == pristine.GetDeformer().GetNormals());
            CHECK(object.GetDeformer().GetZones()[0].GetControlDisplacements() ==
                  pristine.GetDeformer().GetZones()[0].GetControlDisplacements());
        }
        DeformableObject object = pristine;
        CHECK(object.ApplyCollision(FrontCollision(), static_cast<ECollisionSide>(7)).GetError().mCode ==
              EError::InvalidArgument);
        CHECK(object.GetDeformer().GetPositions() == pristine.GetDeformer().GetPositions());
    }
}

TEST_CASE("A hand-made replay with a spoiled collision is refused before any collision is applied",
          "[plugin]")
{
    const DeformableObject pristine = MakeCar(ECrushModel::Campbell);
    Replay replay;
    replay.mCollisions = {FrontCollision(), FrontCollision()};
    replay.mCollisions[1].mContacts[0].mLocalPointOnB.z() =
        cNan; // the second one: the first must not land either
    std::vector<ReplayedObject> objects{{ObjectId{0}, BodyId{1}, 0, pristine}};
    const Status status = ApplyReplayedCollisions(replay, objects);
    REQUIRE(status.HasError());
    CHECK(status.GetError().mCode == EError::NonFinite);
    CHECK(status.GetError().mMessage.find("collision 1") != std::string::npos);
    CHECK(objects[0].mDeformable.GetDeformer().GetPositions() == pristine.GetDeformer().GetPositions());

    replay.mCollisions.pop_back();
    REQUIRE(ApplyReplayedCollisions(replay, objects).IsValid());
    CHECK(objects[0].mDeformable.GetDeformer().GetPositions() != pristine.GetDeformer().GetPositions());
}
