// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/ode/OdeAdapter.h>
#include <crumple/ode/OdeBodyState.h>
#include <crumple/base/ThreadCpuClock.h>

#include <ode/ode.h>

#include <algorithm>
#include <string>

namespace crumple::ode
{

using namespace crumple::plugin;

Result<std::unique_ptr<OdeAdapter>> OdeAdapter::Create(DamageWorld& inDamage, const OdeAdapterSettings& inSettings)
{
    BodyState environment;
    environment.mMotionType = EMotionType::Static;
    Result<BodyId> body = inDamage.CreateBody(environment);
    if (!body)
        return body.GetError();
    return std::unique_ptr<OdeAdapter>(new OdeAdapter(inDamage, body.Get(), inSettings));
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

namespace
{

void SetPose(dBodyID ioBody, const Vec3& inPosition, const Mat3& inOrientation)
{
    dBodySetPosition(ioBody, inPosition.x(), inPosition.y(), inPosition.z());
    dMatrix3 rotation;
    for (int i = 0; i < 3; ++i)
    {
        for (int j = 0; j < 3; ++j)
            rotation[4 * i + j] = inOrientation(i, j);
        rotation[4 * i + 3] = 0.0;
    }
    dBodySetRotation(ioBody, rotation);
}

// A dBody with its centre of mass at its origin (as ODE requires), principal inertia along its axes.
dBodyID MakeBody(dWorldID inWorld, double inMass, const Vec3& inInertia, const Vec3& inPosition, const Mat3& inOrientation)
{
    dBodyID body = dBodyCreate(inWorld);
    dMass mass;
    dMassSetParameters(&mass, inMass, 0.0, 0.0, 0.0, inInertia.x(), inInertia.y(), inInertia.z(), 0.0, 0.0, 0.0);
    dBodySetMass(body, &mass);
    SetPose(body, inPosition, inOrientation);
    return body;
}

// The box that bounds inPoints along the body axes, centred where they are, on inBody.
dGeomID MakeBoundingBox(dSpaceID inSpace, dBodyID inBody, const std::vector<Vec3>& inPoints)
{
    Vec3 low = inPoints[0], high = low;
    for (const Vec3& p : inPoints)
    {
        low = low.cwiseMin(p);
        high = high.cwiseMax(p);
    }
    const Vec3 size = high - low, centre = 0.5 * (low + high);
    dGeomID geom = dCreateBox(inSpace, size.x(), size.y(), size.z());
    dGeomSetBody(geom, inBody);
    dGeomSetOffsetPosition(geom, centre.x(), centre.y(), centre.z());
    return geom;
}

} // namespace

OdeAdapter::~OdeAdapter()
{
    // intent: the bodies this adapter made leave the damage world and ODE
    for (const OwnedBody& owned : mOwned)
    {
        (void)mDamage.RemoveBody(owned.mBody);
        for (dGeomID geom : owned.mGeoms)
            dGeomDestroy(geom);
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
    owned.mOdeBody = MakeBody(inWorld, inSettings.mMass, inSettings.mPrincipalInertia, inSettings.mPosition, inSettings.mOrientation);
    const Vec3& v = inSettings.mLinearVelocity;
    const Vec3& w = inSettings.mAngularVelocity;
    dBodySetLinearVel(owned.mOdeBody, v.x(), v.y(), v.z());
    dBodySetAngularVel(owned.mOdeBody, w.x(), w.y(), w.z());
    owned.mSpace = inSpace;
    owned.mGeoms.push_back(MakeBoundingBox(inSpace, owned.mOdeBody, inSettings.mHullPoints));
    return Own(std::move(owned));
}

Result<BodyId> OdeAdapter::CreatePropBody(dWorldID inWorld, dSpaceID inSpace, const plugin::PropBodySettings& inSettings)
{
    if (inWorld == nullptr || inSpace == nullptr)
        return MakeError(EError::InvalidArgument, "CreatePropBody: null dWorldID or dSpaceID");
    if (Status valid = plugin::ValidatePropBodySettings(inSettings); !valid)
        return valid.GetError();
    OwnedBody owned;
    owned.mOdeBody = MakeBody(inWorld, inSettings.mMass, inSettings.mPrincipalInertia, inSettings.mPosition, inSettings.mOrientation);
    owned.mSpace = inSpace;
    owned.mProp = true;
    owned.mHeld = inSettings.mHeld;
    owned.mOwnMass = inSettings.mMass;
    owned.mOwnInertia = inSettings.mPrincipalInertia;
    owned.mHomePosition = inSettings.mPosition;
    owned.mHomeOrientation = inSettings.mOrientation;
    if (owned.mHeld)
        dBodySetGravityMode(owned.mOdeBody, 0); // the ground holds it, not a contact with the ground
    for (const std::vector<Vec3>& piece : inSettings.mPieces)
        owned.mGeoms.push_back(MakeBoundingBox(inSpace, owned.mOdeBody, piece));
    return Own(std::move(owned));
}

Result<BodyId> OdeAdapter::Own(OwnedBody&& ioOwned)
{
    Result<BodyId> body = AddBody(ioOwned.mOdeBody);
    if (!body)
    {
        for (dGeomID geom : ioOwned.mGeoms)
            dGeomDestroy(geom);
        dBodyDestroy(ioOwned.mOdeBody);
        return body;
    }
    ioOwned.mBody = body.Get();
    mOwned.push_back(std::move(ioOwned));
    return body;
}

Status OdeAdapter::SetPropPieces(BodyId inBody, const std::vector<std::vector<Vec3>>& inPieces)
{
    const auto owned = std::find_if(mOwned.begin(), mOwned.end(), [&](const OwnedBody& o) { return o.mBody == inBody; });
    if (owned == mOwned.end() || !owned->mProp)
        return MakeError(EError::OutOfRange, "SetPropPieces: body " + std::to_string(inBody.mValue) + " is not a prop body of this adapter");
    if (Status valid = plugin::ValidatePropPieces(inPieces); !valid)
        return valid;
    for (dGeomID geom : owned->mGeoms)
        dGeomDestroy(geom);
    owned->mGeoms.clear();
    for (const std::vector<Vec3>& piece : inPieces)
        owned->mGeoms.push_back(MakeBoundingBox(owned->mSpace, owned->mOdeBody, piece));
    dBodyEnable(owned->mOdeBody);
    return Status::Ok();
}

bool OdeAdapter::IsHeldPropBody(BodyId inBody) const
{
    return std::any_of(mOwned.begin(), mOwned.end(), [&](const OwnedBody& inOwned) { return inOwned.mBody == inBody && inOwned.mHeld; });
}

Status OdeAdapter::SetHeldVelocity(BodyId inBody, const Vec3& inVelocity)
{
    Result<OwnedBody*> found = FindHeldPropBody(mOwned, inBody, "SetHeldVelocity");
    if (!found)
        return found.GetError();
    OwnedBody* const owned = found.Get();
    if (Status valid = plugin::ValidateHeldVelocity(inVelocity); !valid)
        return valid;
    owned->mHeldVelocity = inVelocity;
    // Between steps the body stands at its pose (HoldProps ran after the last one): moving it now makes the
    // next step's contacts see it.
    dBodySetLinearVel(owned->mOdeBody, inVelocity.x(), inVelocity.y(), inVelocity.z());
    (void)mDamage.ForgetImpacts(owned->mBody); // its velocity is set here, not by the contact solve
    if (!inVelocity.isZero(0.0))
        dBodyEnable(owned->mOdeBody);
    return Status::Ok();
}

Status OdeAdapter::SetHeldMass(BodyId inBody, double inMass)
{
    Result<OwnedBody*> found = FindHeldPropBody(mOwned, inBody, "SetHeldMass");
    if (!found)
        return found.GetError();
    OwnedBody* const owned = found.Get();
    if (Status valid = plugin::ValidateHeldMass(inMass); !valid)
        return valid;
    // intent: ODE has no infinite inertia. Each axis gets inMass times 100 R^2, R^2 the body's own
    // sum of squared radii of gyration (I_x + I_y + I_z) / m, so a contact within R of the centre of mass
    // meets inMass within 1 %; a million times R^2 made dWorldStep's LCP fail (measured: the fence
    // drive-through's car thrown back at 91 m/s)
    constexpr double cStiffTurn = 100.0;
    const double radius_squared = owned->mOwnInertia.sum() / owned->mOwnMass;
    const double mass = inMass > 0.0 ? inMass : owned->mOwnMass;
    const Vec3 inertia =
        inMass > 0.0 ? Vec3::Constant(inMass * cStiffTurn * radius_squared) : owned->mOwnInertia;
    dMass ode_mass;
    dMassSetParameters(&ode_mass, mass, 0.0, 0.0, 0.0, inertia.x(), inertia.y(), inertia.z(), 0.0, 0.0, 0.0);
    dBodySetMass(owned->mOdeBody, &ode_mass);
    return Status::Ok();
}

void OdeAdapter::HoldProps()
{
    for (const OwnedBody& owned : mOwned)
    {
        if (!owned.mHeld)
            continue;
        // Put back asleep or not: ODE disables a body at the end of a step in which it still moved, and a
        // disabled body left there would stand off its pose, with that step's velocity, when it wakes. Its
        // velocity is never the contact solve's, so its remembered impacts go too.
        SetPose(owned.mOdeBody, owned.mHomePosition, owned.mHomeOrientation);
        dBodySetLinearVel(owned.mOdeBody, owned.mHeldVelocity.x(), owned.mHeldVelocity.y(), owned.mHeldVelocity.z());
        dBodySetAngularVel(owned.mOdeBody, 0.0, 0.0, 0.0);
        dBodySetForce(owned.mOdeBody, 0.0, 0.0, 0.0);
        dBodySetTorque(owned.mOdeBody, 0.0, 0.0, 0.0);
        (void)mDamage.ForgetImpacts(owned.mBody);
    }
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
            for (dGeomID geom : owned->mGeoms)
                dGeomDestroy(geom);
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

BodyId OdeAdapter::FindBodyOfGeom(dGeomID inGeom) const
{
    dBodyID body = dGeomGetBody(inGeom);
    if (body == nullptr)
    {
        const auto found = mStaticGeoms.find(inGeom);
        return found == mStaticGeoms.end() ? mEnvironment : found->second;
    }
    const auto found = mBodies.find(body);
    return found == mBodies.end() ? BodyId{} : found->second;
}

void OdeAdapter::SnapshotOnce(dGeomID inGeom, BodyId inId)
{
    dBodyID body = dGeomGetBody(inGeom);
    if (body == nullptr)
        return;
    if (mSnapshotted.size() <= inId.mValue)
        mSnapshotted.resize(inId.mValue + 1, 0);
    if (mSnapshotted[inId.mValue] == 0)
    {
        mSnapshotted[inId.mValue] = 1;
        mSnapshottedList.push_back(inId);
        if (mDamage.SetBodyState(inId, OdeBodyState(body)))
            ++mCurrent.mBodiesSnapshotted;
    }
}

void OdeAdapter::OnCollide(dGeomID inGeom1, dGeomID inGeom2, std::span<const dContactGeom> inContacts, double inFriction)
{
    CollectContacts(inGeom1, inGeom2, inContacts.data(), inContacts.size(), sizeof(dContactGeom), nullptr, inFriction);
}

void OdeAdapter::OnCollide(dGeomID inGeom1, dGeomID inGeom2, std::span<const dContact> inContacts)
{
    CollectContacts(inGeom1, inGeom2, inContacts.empty() ? nullptr : &inContacts.front().geom, inContacts.size(), sizeof(dContact),
                    inContacts.data(), 0.0);
}

void OdeAdapter::CollectContacts(dGeomID inGeom1, dGeomID inGeom2, const dContactGeom* inFirst, std::size_t inCount,
                                 std::size_t inStride, const dContact* inFull, double inFriction)
{
    // intent: a pair with a body the adapter was not given (a game's crate on the ground) leaves before the
    // clock is read (when it is: OdeAdapterSettings::mMeasureCpuTime): the thread's CPU time is a system call
    // on some hosts (vDSO fallback, about a microsecond), and a scene's unregistered pairs can outnumber its
    // registered ones a hundred to one. Each geom's body is looked up once.
    if (inCount == 0)
        return;
    const BodyId a = FindBodyOfGeom(inGeom1);
    const BodyId b = FindBodyOfGeom(inGeom2);
    // intent: a body the game removed from the damage world itself (DamageWorld::RemoveBody, not ours) is
    // left out as an unmapped one: its contacts would make the world refuse the whole step's batch
    if (!a.IsValid() || !b.IsValid() || mDamage.GetBodyState(a) == nullptr ||
        mDamage.GetBodyState(b) == nullptr)
        return;
    const double start = CpuSeconds();
    // intent: every return below passes through this, so the step's time has all of its calls
    struct AddTime
    {
        const OdeAdapter& mAdapter;
        double mStart;
        double& mSeconds;
        ~AddTime() { mSeconds += mAdapter.CpuSeconds() - mStart; }
    } add_time{*this, start, mCurrent.mSeconds};
    SnapshotOnce(inGeom1, a);
    SnapshotOnce(inGeom2, b);
    if (a == b)
        return;
    for (std::size_t i = 0; i < inCount; ++i)
    {
        const dContactGeom& contact =
            *reinterpret_cast<const dContactGeom*>(reinterpret_cast<const unsigned char*>(inFirst) + i * inStride);
        ContactEvent event;
        event.mBodyA = a;
        event.mBodyB = b;
        // ODE gives one point in the overlap: Crumple splits it onto the surfaces by the depth.
        event.mPointOnA = event.mPointOnB = Vec3(contact.pos[0], contact.pos[1], contact.pos[2]);
        event.mNormal = Vec3(contact.normal[0], contact.normal[1], contact.normal[2]);
        event.mPenetrationDepth = static_cast<double>(contact.depth);
        event.mFriction = inFriction;
        if (inFull != nullptr)
        {
            const dSurfaceParameters& surface = inFull[i].surface;
            event.mFriction = (surface.mode & dContactApprox1_1) != 0 ? static_cast<double>(surface.mu) : 0.0;
        }
        mEvents.push_back(event);
    }
}

double OdeAdapter::CpuSeconds() const
{
    return mSettings.mMeasureCpuTime ? ThreadCpuSeconds() : 0.0;
}

void OdeAdapter::AfterStep(double inTimeStep)
{
    const double start = CpuSeconds();
    mTime += inTimeStep;
    for (ContactEvent& event : mEvents)
        event.mTime = mTime;
    mCurrent.mContactsReported = static_cast<int>(mEvents.size());
    // ODE's output is finite unless the game's simulation already diverged; then the step is skipped.
    if (!mEvents.empty() && !mDamage.SubmitContacts(mEvents, inTimeStep))
        mCurrent.mContactsRefused = static_cast<int>(mEvents.size());
    mCurrent.mUpdate = mDamage.Update(mTime);
    HoldProps();
    mCurrent.mSeconds += CpuSeconds() - start;

    // Ready for the next step.
    mLastStats = mCurrent;
    mCurrent = {};
    mEvents.clear();
    for (BodyId id : mSnapshottedList)
        mSnapshotted[id.mValue] = 0;
    mSnapshottedList.clear();
}

} // namespace crumple::ode
