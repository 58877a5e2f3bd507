// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/ode/OdeAdapter.h>
#include <crumple/ode/OdeBodyState.h>

#include <ode/ode.h>

namespace crumple::ode
{

using namespace crumple::plugin;

Result<std::unique_ptr<OdeAdapter>> OdeAdapter::Create(DamageWorld& inDamage)
{
    BodyState environment;
    environment.mMotionType = EMotionType::Static;
    Result<BodyId> body = inDamage.CreateBody(environment);
    if (!body)
        return body.GetError();
    return std::unique_ptr<OdeAdapter>(new OdeAdapter(inDamage, body.Get()));
}

Result<BodyId> OdeAdapter::AddBody(dBodyID inBody)
{
    if (inBody == nullptr)
        return MakeError(EError::InvalidArgument, "AddBody: null dBodyID");
    if (mBodies.contains(inBody))
        return MakeError(EError::InvalidArgument, "AddBody: this ODE body is already registered");
    Result<BodyId> body = mDamage.CreateBody(OdeBodyState(inBody));
    if (body)
        mBodies.emplace(inBody, body.Get());
    return body;
}

Result<BodyId> OdeAdapter::AddStaticGeom(dGeomID inGeom)
{
    if (inGeom == nullptr || dGeomGetBody(inGeom) != nullptr)
        return MakeError(EError::InvalidArgument, "AddStaticGeom: the geom must exist and have no body");
    if (mStaticGeoms.contains(inGeom))
        return MakeError(EError::InvalidArgument, "AddStaticGeom: this geom is already registered");
    Result<BodyId> body = mDamage.CreateBody(OdeStaticGeomState(inGeom));
    if (body)
        mStaticGeoms.emplace(inGeom, body.Get());
    return body;
}

OdeAdapter::~OdeAdapter()
{
    // intent: the bodies this adapter made leave the damage world and ODE
    for (const OwnedBody& owned : mOwned)
    {
        (void)mDamage.RemoveBody(owned.mBody);
        dGeomDestroy(owned.mGeom);
        dBodyDestroy(owned.mOdeBody);
    }
}

Result<BodyId> OdeAdapter::CreateConvexBody(dWorldID inWorld, dSpaceID inSpace, const ConvexBodySettings& inSettings)
{
    if (inWorld == nullptr || inSpace == nullptr)
        return MakeError(EError::InvalidArgument, "CreateConvexBody: null dWorldID or dSpaceID");
    if (Status valid = ValidateConvexBodySettings(inSettings); !valid)
        return valid.GetError();
    OwnedBody owned;
    owned.mOdeBody = dBodyCreate(inWorld);
    dMass mass;
    const Vec3& inertia = inSettings.mPrincipalInertia;
    dMassSetParameters(&mass, inSettings.mMass, 0.0, 0.0, 0.0, inertia.x(), inertia.y(), inertia.z(), 0.0, 0.0, 0.0);
    dBodySetMass(owned.mOdeBody, &mass);
    const Vec3& x = inSettings.mPosition;
    dBodySetPosition(owned.mOdeBody, x.x(), x.y(), x.z());
    dMatrix3 rotation;
    for (int i = 0; i < 3; ++i)
    {
        for (int j = 0; j < 3; ++j)
            rotation[4 * i + j] = inSettings.mOrientation(i, j);
        rotation[4 * i + 3] = 0.0;
    }
    dBodySetRotation(owned.mOdeBody, rotation);
    const Vec3& v = inSettings.mLinearVelocity;
    const Vec3& w = inSettings.mAngularVelocity;
    dBodySetLinearVel(owned.mOdeBody, v.x(), v.y(), v.z());
    dBodySetAngularVel(owned.mOdeBody, w.x(), w.y(), w.z());
    // intent: the hull's bounding box along the body (principal) axes, centred where the points are
    Vec3 low = inSettings.mHullPoints[0], high = low;
    for (const Vec3& p : inSettings.mHullPoints)
    {
        low = low.cwiseMin(p);
        high = high.cwiseMax(p);
    }
    const Vec3 size = high - low, centre = 0.5 * (low + high);
    owned.mGeom = dCreateBox(inSpace, size.x(), size.y(), size.z());
    dGeomSetBody(owned.mGeom, owned.mOdeBody);
    dGeomSetOffsetPosition(owned.mGeom, centre.x(), centre.y(), centre.z());

    Result<BodyId> body = AddBody(owned.mOdeBody);
    if (!body)
    {
        dGeomDestroy(owned.mGeom);
        dBodyDestroy(owned.mOdeBody);
        return body;
    }
    owned.mBody = body.Get();
    mOwned.push_back(owned);
    return body;
}

dBodyID OdeAdapter::GetConvexBody(BodyId inBody) const
{
    for (const OwnedBody& owned : mOwned)
        if (owned.mBody == inBody)
            return owned.mOdeBody;
    return nullptr;
}

Status OdeAdapter::RemoveBody(dBodyID inBody)
{
    const auto found = mBodies.find(inBody);
    if (found == mBodies.end())
        return MakeError(EError::OutOfRange, "RemoveBody: this ODE body is not registered");
    const BodyId body = found->second;
    if (Status removed = mDamage.RemoveBody(body); !removed)
        return removed;
    mBodies.erase(found);
    // Contacts buffered this step with the body would make the damage world refuse the whole step.
    std::erase_if(mEvents, [&](const ContactEvent& e) { return e.mBodyA == body || e.mBodyB == body; });
    // A body made later this step may reuse the slot: it must be snapshotted for itself.
    if (body.mValue < mSnapshotted.size())
        mSnapshotted[body.mValue] = 0;
    std::erase(mSnapshottedList, body);
    // intent: a body this adapter made is destroyed with its geom (inBody dies here)
    for (auto owned = mOwned.begin(); owned != mOwned.end(); ++owned)
        if (owned->mBody == body)
        {
            dGeomDestroy(owned->mGeom);
            dBodyDestroy(owned->mOdeBody);
            mOwned.erase(owned);
            break;
        }
    return Status::Ok();
}

BodyId OdeAdapter::FindBody(dBodyID inBody) const
{
    const auto found = mBodies.find(inBody);
    return found == mBodies.end() ? BodyId{} : found->second;
}

BodyId OdeAdapter::BodyOfGeom(dGeomID inGeom)
{
    dBodyID body = dGeomGetBody(inGeom);
    if (body == nullptr)
    {
        const auto found = mStaticGeoms.find(inGeom);
        return found == mStaticGeoms.end() ? mEnvironment : found->second;
    }
    const auto found = mBodies.find(body);
    if (found == mBodies.end())
        return BodyId{};
    // Pre-solve snapshot, once per step, only for bodies that are in contact.
    const BodyId id = found->second;
    if (mSnapshotted.size() <= id.mValue)
        mSnapshotted.resize(id.mValue + 1, 0);
    if (mSnapshotted[id.mValue] == 0)
    {
        mSnapshotted[id.mValue] = 1;
        mSnapshottedList.push_back(id);
        if (mDamage.SetBodyState(id, OdeBodyState(body)))
            ++mCurrent.mBodiesSnapshotted;
    }
    return id;
}

void OdeAdapter::OnCollide(dGeomID inGeom1, dGeomID inGeom2, std::span<const dContactGeom> inContacts)
{
    if (inContacts.empty())
        return;
    const BodyId a = BodyOfGeom(inGeom1);
    const BodyId b = BodyOfGeom(inGeom2);
    if (!a.IsValid() || !b.IsValid() || a == b)
        return;
    for (const dContactGeom& contact : inContacts)
    {
        ContactEvent event;
        event.mBodyA = a;
        event.mBodyB = b;
        // ODE gives one point in the overlap: Crumple splits it onto the surfaces by the depth.
        event.mPointOnA = event.mPointOnB = Vec3(contact.pos[0], contact.pos[1], contact.pos[2]);
        event.mNormal = Vec3(contact.normal[0], contact.normal[1], contact.normal[2]);
        event.mPenetrationDepth = static_cast<double>(contact.depth);
        mEvents.push_back(event);
    }
}

void OdeAdapter::AfterStep(double inTimeStep)
{
    mTime += inTimeStep;
    for (ContactEvent& event : mEvents)
        event.mTime = mTime;
    mCurrent.mContactsReported = static_cast<int>(mEvents.size());
    // ODE's output is finite unless the game's simulation already diverged; then the step is skipped.
    if (!mEvents.empty() && !mDamage.SubmitContacts(mEvents, inTimeStep))
        mCurrent.mContactsRefused = static_cast<int>(mEvents.size());
    mCurrent.mUpdate = mDamage.Update(mTime);

    // Ready for the next step.
    mLastStats = mCurrent;
    mCurrent = {};
    mEvents.clear();
    for (BodyId id : mSnapshottedList)
        mSnapshotted[id.mValue] = 0;
    mSnapshottedList.clear();
}

} // namespace crumple::ode
