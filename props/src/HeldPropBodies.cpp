// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/props/HeldPropBodies.h>

#include <algorithm>
#include <cmath>

namespace crumple::props
{

Result<HeldPropBodies> HeldPropBodies::Create(PropWorld& ioProps, HeldPropEngine inEngine, const HeldPropSettings& inSettings)
{
    if (!inEngine.mCreatePieceBody || !inEngine.mSetPropPieces)
        return MakeError(EError::InvalidArgument, "HeldPropBodies::Create: the engine's mCreatePieceBody and mSetPropPieces are required");
    if (inEngine.mSetHeldMass && !ioProps.GetSettings().mContactMass)
        return MakeError(EError::InvalidArgument,
                         "HeldPropBodies::Create: mSetHeldMass needs the prop world's contact masses "
                         "(PropWorldSettings::mContactMass)");
    if (!std::isfinite(inSettings.mShapeCellSize) || !(inSettings.mShapeCellSize > 0.0))
        return MakeError(EError::InvalidArgument, "HeldPropBodies::Create: mShapeCellSize must be finite and > 0 m");
    if (!std::isfinite(inSettings.mShapeTolerance) || !(inSettings.mShapeTolerance >= 0.0))
        return MakeError(EError::InvalidArgument, "HeldPropBodies::Create: mShapeTolerance must be finite and >= 0 m");
    if (!std::isfinite(inSettings.mMinPieceMass) || !(inSettings.mMinPieceMass >= 0.0))
        return MakeError(EError::InvalidArgument, "HeldPropBodies::Create: mMinPieceMass must be finite and >= 0 kg");
    return HeldPropBodies(ioProps, std::move(inEngine), inSettings);
}

Status HeldPropBodies::Update(const PropStepReport& inStepped, HeldPropUpdate& outUpdate)
{
    outUpdate = HeldPropUpdate();
    Status first_failure = Status::Ok();
    const auto keep = [&](const Status& inStatus) {
        if (!inStatus && first_failure)
            first_failure = inStatus;
        return inStatus.IsValid();
    };
    const auto prop_count = static_cast<std::size_t>(mProps->GetPropCount());
    mGivenVelocity.resize(prop_count, Vec3::Zero());
    mGivenMass.resize(prop_count, 0.0);
    mGivenBody.resize(prop_count);
    const bool new_props = mPropsSeen < prop_count;

    // 1. The struck members' velocity and mass. The velocity after a step in which props moved, to every held
    // body (the adapter also forgets the body's remembered impact: its velocity is set here, not by the
    // contact solve); while all sleep, only where it changed (a prop that fell asleep gives zero once), so a
    // scene at rest makes no engine call. The mass only where it changed.
    // intent: a body the engine holds for a prop: still in the world, and held (not free or static)
    const auto engine_holds = [&](plugin::BodyId inBody)
    {
        return mProps->GetWorld().GetBodyState(inBody) != nullptr &&
               (!mEngine.mIsHeld || mEngine.mIsHeld(inBody));
    };
    for (std::size_t index = 0; index < prop_count; ++index)
    {
        if (!mEngine.mSetHeldVelocity && !mEngine.mSetHeldMass)
            break;
        const PropId prop{static_cast<std::uint32_t>(index)};
        const plugin::BodyId body = mProps->GetBody(prop);
        if (!body.IsValid())
        {
            // intent: a removed prop's held body, if the game keeps it, is left as made (at rest, its own
            // mass), not moving with the last struck members for ever, nor weighing what they weighed
            const plugin::BodyId kept = mGivenBody[index];
            const bool keeps = kept.IsValid() && engine_holds(kept);
            if (keeps && mEngine.mSetHeldVelocity && mGivenVelocity[index] != Vec3::Zero())
            {
                keep(mEngine.mSetHeldVelocity(kept, Vec3::Zero()));
                ++outUpdate.mVelocitiesGiven;
            }
            if (keeps && mEngine.mSetHeldMass && mGivenMass[index] != 0.0)
            {
                keep(mEngine.mSetHeldMass(kept, 0.0));
                ++outUpdate.mMassesGiven;
            }
            mGivenBody[index] = plugin::BodyId();
            mGivenVelocity[index] = Vec3::Zero();
            mGivenMass[index] = 0.0;
            continue;
        }
        const Vec3 velocity = mProps->GetContactVelocity(prop);
        const double mass = mProps->GetContactMass(prop);
        const bool give_velocity =
            mEngine.mSetHeldVelocity && (inStepped.mStepped > 0 || velocity != mGivenVelocity[index]);
        const bool give_mass = mEngine.mSetHeldMass && mass != mGivenMass[index];
        if (!give_velocity && !give_mass)
            continue;
        if (!engine_holds(body))
            continue; // its body left the world, or is free or static: the engine moves it
        mGivenBody[index] = body;
        if (give_mass)
        {
            if (keep(mEngine.mSetHeldMass(body, mass)))
                mGivenMass[index] = mass;
            ++outUpdate.mMassesGiven;
        }
        if (give_velocity)
        {
            if (keep(mEngine.mSetHeldVelocity(body, velocity)))
                mGivenVelocity[index] = velocity;
            ++outUpdate.mVelocitiesGiven;
        }
    }
    const bool pending = std::find(mShapePending.begin(), mShapePending.end(), std::uint8_t{1}) != mShapePending.end();
    mShapePending.resize(prop_count, 0);
    if (inStepped.mStepped == 0 && !new_props && !pending)
        return first_failure;

    // 2. Loose pieces become bodies. TakeLooseFragments refuses only a bad minimum mass, checked by Create.
    Result<std::vector<LooseFragment>> loose = mProps->TakeLooseFragments(mSettings.mMinPieceMass);
    if (!loose)
        return loose.GetError();
    for (LooseFragment& piece : loose.Get())
    {
        HeldPiece held{std::move(piece), plugin::BodyId()};
        if (!held.mPiece.mDropped)
            if (Result<plugin::BodyId> body = mEngine.mCreatePieceBody(held.mPiece.mRigidBody.mBody); keep(body.IsValid() ? Status::Ok() : Status(body.GetError())))
            {
                held.mBody = body.Get();
                // intent: refused only for a body the engine did not add to the damage world
                if (mSettings.mQuietPieces)
                    keep(mProps->GetWorld().SetQuiet(held.mBody, true));
            }
        outUpdate.mPieces.push_back(std::move(held));
    }

    // 3. New shapes: every prop's first, then those that changed.
    for (std::size_t index = 0; index < prop_count; ++index)
    {
        const PropId prop{static_cast<std::uint32_t>(index)};
        if (mProps->GetWorld().GetBodyState(mProps->GetBody(prop)) == nullptr)
        {
            // its body left the world, or the prop was removed: no shape to give again
            mShapePending[index] = 0;
            continue;
        }
        Result<std::optional<std::vector<std::vector<Vec3>>>> shape = mProps->TakeChangedShape(prop, mSettings.mShapeCellSize, mSettings.mShapeTolerance);
        if (!shape)
            return shape.GetError();
        if (!shape.Get() && mShapePending[index] != 0)
        {
            // The engine refused the last shape: the prop's shape now, again (TakeChangedShape has moved on).
            Result<std::vector<std::vector<Vec3>>> again = mProps->GetCollisionPieces(prop, mSettings.mShapeCellSize);
            if (!again)
                return again.GetError();
            shape.Get().emplace(std::move(again).Get());
        }
        if (!shape.Get())
            continue;
        mShapePending[index] = keep(mEngine.mSetPropPieces(mProps->GetBody(prop), *shape.Get())) ? 0 : 1;
        ++outUpdate.mShapesGiven;
    }
    mPropsSeen = prop_count;
    return first_failure;
}

} // namespace crumple::props
