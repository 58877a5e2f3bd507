// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "BulletTickCallbacks.h"
#include "ReplaceableHull.h"

#include <crumple/bullet/BulletAdapter.h>
#include <crumple/bullet/BulletBodyState.h>
#include <crumple/base/ThreadCpuClock.h>

#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <string>

namespace crumple::bullet
{

using namespace crumple::plugin;

namespace
{

Vec3 ToVec3(const btVector3& inV)
{
    return {static_cast<double>(inV.x()), static_cast<double>(inV.y()), static_cast<double>(inV.z())};
}

// The convex hull of inPoints (ReplaceableHull::SetPoints: the same bits as a prop piece's points replaced
// later).
std::unique_ptr<ReplaceableHull> MakeHull(const std::vector<Vec3>& inPoints)
{
    auto hull = std::make_unique<ReplaceableHull>();
    hull->SetPoints(inPoints);
    return hull;
}

// A prop body's shape: a compound of the first inCount hulls, in index order, each in the body's frame.
std::unique_ptr<btCompoundShape> CompoundOf(const std::vector<std::unique_ptr<ReplaceableHull>>& inHulls,
                                            std::size_t inCount)
{
    auto compound = std::make_unique<btCompoundShape>(true, static_cast<int>(inCount));
    for (std::size_t i = 0; i < inCount; ++i)
        compound->addChildShape(btTransform::getIdentity(), inHulls[i].get());
    return compound;
}

btTransform ToBulletPose(const Mat3& inRotation, const Vec3& inPosition)
{
    const Mat3& r = inRotation;
    const btMatrix3x3 basis(btScalar(r(0, 0)), btScalar(r(0, 1)), btScalar(r(0, 2)), btScalar(r(1, 0)), btScalar(r(1, 1)),
                            btScalar(r(1, 2)), btScalar(r(2, 0)), btScalar(r(2, 1)), btScalar(r(2, 2)));
    return btTransform(basis, btVector3(btScalar(inPosition.x()), btScalar(inPosition.y()), btScalar(inPosition.z())));
}

} // namespace

Result<std::unique_ptr<BulletAdapter>> BulletAdapter::Create(btDiscreteDynamicsWorld& inWorld, DamageWorld& inDamage,
                                                             const BulletAdapterSettings& inSettings)
{
    if (!(inSettings.mMaxSeparation >= 0.0 && inSettings.mMaxSeparation < 1.0))
        return MakeError(EError::InvalidArgument, "BulletAdapterSettings.mMaxSeparation must be in [0, 1) m");
    // Two adapters on one world would each chain the other forever: refuse the second.
    if (BulletTickCallbacks::InstalledPreTick(inWorld) == &BulletTickCallbacks::PreTick)
        return MakeError(EError::InvalidArgument, "this btDynamicsWorld already has a Crumple adapter");
    return std::unique_ptr<BulletAdapter>(new BulletAdapter(inWorld, inDamage, inSettings));
}

BulletAdapter::BulletAdapter(btDiscreteDynamicsWorld& inWorld, DamageWorld& inDamage, const BulletAdapterSettings& inSettings)
    : mWorld(inWorld), mDamage(inDamage), mSettings(inSettings)
{
    // Remember the game's callbacks and user pointer, then install ours (both use the one user pointer).
    mPreviousPreTick = BulletTickCallbacks::InstalledPreTick(inWorld);
    mPreviousPostTick = BulletTickCallbacks::InstalledPostTick(inWorld);
    mPreviousUserInfo = inWorld.getWorldUserInfo();
    inWorld.setInternalTickCallback(&BulletTickCallbacks::PreTick, this, true);
    inWorld.setInternalTickCallback(&BulletTickCallbacks::PostTick, this, false);
}

BulletAdapter::~BulletAdapter()
{
    // intent: the bodies this adapter made leave both worlds before they are deleted
    for (OwnedBody& owned : mOwned)
    {
        mWorld.removeRigidBody(owned.mRigidBody.get());
        (void)mDamage.RemoveBody(owned.mBody);
    }
    mWorld.setInternalTickCallback(mPreviousPreTick, mPreviousUserInfo, true);
    mWorld.setInternalTickCallback(mPreviousPostTick, mPreviousUserInfo, false);
    for (FollowingHull& hull : mHulls)
        if (hull.mOwner != nullptr && hull.mOwner->getCollisionShape() == hull.mShape.get())
            hull.mOwner->setCollisionShape(nullptr); // the shape dies with us: do not leave a dangling pointer
}

Result<BodyId> BulletAdapter::AddBody(btCollisionObject& inObject)
{
    if (mLookup.contains(&inObject))
        return MakeError(EError::InvalidArgument, "AddBody: this collision object is already registered");
    Result<BodyId> body = mDamage.CreateBody(BulletBodyState(inObject));
    if (!body)
        return body;
    mLookup.emplace(&inObject, body.Get());
    mBodies.push_back({&inObject, body.Get()});
    return body;
}

Status BulletAdapter::RemoveBody(const btCollisionObject& inObject)
{
    const auto found = mLookup.find(&inObject);
    if (found == mLookup.end())
        return MakeError(EError::OutOfRange, "RemoveBody: this collision object is not registered");
    const BodyId body = found->second;
    if (Status removed = mDamage.RemoveBody(body); !removed)
        return removed;
    mLookup.erase(found);
    std::erase_if(mBodies, [&](const MappedBody& m) { return m.mBody == body; });
    // The object may still use its hull as its shape: keep the shape alive (it stops following) until the
    // adapter goes.
    for (FollowingHull& hull : mHulls)
        if (hull.mOwner == &inObject)
            hull.mOwner = nullptr;
    // intent: a body this adapter made leaves the world and is deleted (inObject dies here)
    const auto owned = std::find_if(mOwned.begin(), mOwned.end(), [&](const OwnedBody& o) { return o.mBody == body; });
    if (owned != mOwned.end())
    {
        mWorld.removeRigidBody(owned->mRigidBody.get());
        mOwned.erase(owned);
    }
    return Status::Ok();
}

Result<BodyId> BulletAdapter::CreateConvexBody(const plugin::ConvexBodySettings& inSettings)
{
    if (Status valid = plugin::ValidateConvexBodySettings(inSettings); !valid)
        return valid.GetError();
    OwnedBody owned;
    owned.mShape = MakeHull(inSettings.mHullPoints);
    owned.mMotion = std::make_unique<btDefaultMotionState>(ToBulletPose(inSettings.mOrientation, inSettings.mPosition));
    const Vec3& inertia = inSettings.mPrincipalInertia;
    btRigidBody::btRigidBodyConstructionInfo info(btScalar(inSettings.mMass), owned.mMotion.get(), owned.mShape.get(),
                                                  btVector3(btScalar(inertia.x()), btScalar(inertia.y()), btScalar(inertia.z())));
    owned.mRigidBody = std::make_unique<btRigidBody>(info);
    const Vec3& v = inSettings.mLinearVelocity;
    const Vec3& w = inSettings.mAngularVelocity;
    owned.mRigidBody->setLinearVelocity(btVector3(btScalar(v.x()), btScalar(v.y()), btScalar(v.z())));
    owned.mRigidBody->setAngularVelocity(btVector3(btScalar(w.x()), btScalar(w.y()), btScalar(w.z())));
    return Own(std::move(owned));
}

Result<BodyId> BulletAdapter::Own(OwnedBody&& ioOwned)
{
    mWorld.addRigidBody(ioOwned.mRigidBody.get());
    Result<BodyId> body = AddBody(*ioOwned.mRigidBody);
    if (!body)
    {
        mWorld.removeRigidBody(ioOwned.mRigidBody.get());
        return body;
    }
    ioOwned.mBody = body.Get();
    mOwned.push_back(std::move(ioOwned));
    return body;
}

Result<BodyId> BulletAdapter::CreatePropBody(const plugin::PropBodySettings& inSettings)
{
    if (Status valid = plugin::ValidatePropBodySettings(inSettings); !valid)
        return valid.GetError();
    OwnedBody owned;
    for (const std::vector<Vec3>& piece : inSettings.mPieces)
        owned.mPieces.push_back(MakeHull(piece));
    owned.mCompound = CompoundOf(owned.mPieces, owned.mPieces.size());
    owned.mHeld = inSettings.mHeld;
    owned.mHome = ToBulletPose(inSettings.mOrientation, inSettings.mPosition);
    owned.mMotion = std::make_unique<btDefaultMotionState>(owned.mHome);
    const Vec3& inertia = inSettings.mPrincipalInertia;
    btRigidBody::btRigidBodyConstructionInfo info(btScalar(inSettings.mMass), owned.mMotion.get(), owned.mCompound.get(),
                                                  btVector3(btScalar(inertia.x()), btScalar(inertia.y()), btScalar(inertia.z())));
    owned.mRigidBody = std::make_unique<btRigidBody>(info);
    owned.mOwnMass = info.m_mass;
    owned.mOwnInertia = info.m_localInertia;
    if (owned.mHeld)
    {
        // intent: the ground holds it, not a contact with the ground (addRigidBody keeps its own gravity)
        owned.mRigidBody->setFlags(owned.mRigidBody->getFlags() | BT_DISABLE_WORLD_GRAVITY);
        owned.mRigidBody->setGravity(btVector3(0, 0, 0));
    }
    return Own(std::move(owned));
}

// Why the body leaves the world and takes a new compound even though its hulls are kept: Bullet's results
// depend on the order its contacts come in. Kept in the world with its compound's leaves updated in place
// (4b224eb), PropFenceTest's car lost 5.8 % (64 km/h) and 9.7 % (40 km/h) more momentum in Bullet than
// Crumple's impulses gave it, against 0.25 and 5.4 % this way (the tree's overlap queries visit the children
// in another order); with the tree built again in index order that drive-through came out bit for bit, but
// the racing fence, whose body then kept its place among the world's objects, stayed awake 933 engine steps
// instead of 137. Replacing the kept hulls' points spares their allocations (0.104 -> 0.072 ms per call for
// 80 pieces, commit 473694c) and gives the same bits as new hulls.
Status BulletAdapter::SetPropPieces(BodyId inBody, const std::vector<std::vector<Vec3>>& inPieces)
{
    const auto owned = std::find_if(mOwned.begin(), mOwned.end(), [&](const OwnedBody& o) { return o.mBody == inBody; });
    if (owned == mOwned.end() || owned->mCompound == nullptr)
        return MakeError(EError::OutOfRange, "SetPropPieces: body " + std::to_string(inBody.mValue) + " is not a prop body of this adapter");
    if (Status valid = plugin::ValidatePropPieces(inPieces); !valid)
        return valid;
    // intent: out of the world (its manifolds and broadphase pairs go with it), as a new shape would
    mWorld.removeRigidBody(owned->mRigidBody.get());
    // intent: the kept hulls take the new points, new hulls for more pieces
    const std::size_t kept = std::min(owned->mPieces.size(), inPieces.size());
    for (std::size_t i = 0; i < kept; ++i)
        owned->mPieces[i]->SetPoints(inPieces[i]);
    for (std::size_t i = kept; i < inPieces.size(); ++i)
        owned->mPieces.push_back(MakeHull(inPieces[i]));
    // intent: a new compound of the first inPieces.size() hulls, then the surplus ones go (the old compound,
    // which still names them, goes first)
    std::unique_ptr<btCompoundShape> compound = CompoundOf(owned->mPieces, inPieces.size());
    owned->mRigidBody->setCollisionShape(compound.get());
    owned->mCompound = std::move(compound);
    owned->mPieces.resize(inPieces.size());
    mWorld.addRigidBody(owned->mRigidBody.get());
    owned->mRigidBody->activate(true);
    return Status::Ok();
}

bool BulletAdapter::IsHeldPropBody(BodyId inBody) const
{
    return std::any_of(mOwned.begin(), mOwned.end(), [&](const OwnedBody& inOwned) { return inOwned.mBody == inBody && inOwned.mHeld; });
}

Status BulletAdapter::SetHeldVelocity(BodyId inBody, const Vec3& inVelocity)
{
    Result<OwnedBody*> found = FindHeldPropBody(mOwned, inBody, "SetHeldVelocity");
    if (!found)
        return found.GetError();
    OwnedBody* const owned = found.Get();
    if (Status valid = plugin::ValidateHeldVelocity(inVelocity); !valid)
        return valid;
    owned->mHeldVelocity = btVector3(btScalar(inVelocity.x()), btScalar(inVelocity.y()), btScalar(inVelocity.z()));
    // Between steps the body stands at its pose (HoldProps ran at the end of the last one): moving it now
    // makes the next step's contacts see it.
    owned->mRigidBody->setLinearVelocity(owned->mHeldVelocity);
    owned->mRigidBody->setInterpolationLinearVelocity(owned->mHeldVelocity);
    (void)mDamage.ForgetImpacts(owned->mBody); // its velocity is set here, not by the contact solve
    if (!inVelocity.isZero(0.0))
        owned->mRigidBody->activate(true);
    return Status::Ok();
}

Status BulletAdapter::SetHeldMass(BodyId inBody, double inMass)
{
    Result<OwnedBody*> found = FindHeldPropBody(mOwned, inBody, "SetHeldMass");
    if (!found)
        return found.GetError();
    OwnedBody* const owned = found.Get();
    if (Status valid = plugin::ValidateHeldMass(inMass); !valid)
        return valid;
    btRigidBody& body = *owned->mRigidBody;
    // intent: a zero local inertia is Bullet's infinite one (zero inverse): the contact meets inMass at any
    // point, as the FEM's effective mass was measured there
    if (inMass > 0.0)
        body.setMassProps(btScalar(inMass), btVector3(0, 0, 0));
    else
        body.setMassProps(owned->mOwnMass, owned->mOwnInertia);
    body.updateInertiaTensor();
    // intent: setMassProps scales the body's gravity by its mass; a held body has none
    body.setGravity(btVector3(0, 0, 0));
    return Status::Ok();
}

void BulletAdapter::HoldProps()
{
    const btVector3 zero(0, 0, 0);
    for (OwnedBody& owned : mOwned)
    {
        if (!owned.mHeld)
            continue;
        // Put back asleep or not: Bullet deactivates a body at the end of a step in which it still moved, and
        // a sleeping body left there would stand off its pose, with that step's velocity, when it wakes. Its
        // velocity is never the contact solve's, so its remembered impacts go too.
        btRigidBody& body = *owned.mRigidBody;
        body.setWorldTransform(owned.mHome);
        body.setInterpolationWorldTransform(owned.mHome);
        owned.mMotion->setWorldTransform(owned.mHome);
        body.setLinearVelocity(owned.mHeldVelocity);
        body.setAngularVelocity(zero);
        body.setInterpolationLinearVelocity(owned.mHeldVelocity);
        body.setInterpolationAngularVelocity(zero);
        body.clearForces();
        (void)mDamage.ForgetImpacts(owned.mBody);
    }
}

btRigidBody* BulletAdapter::GetConvexBody(BodyId inBody) const
{
    const auto owned = std::find_if(mOwned.begin(), mOwned.end(), [&](const OwnedBody& o) { return o.mBody == inBody; });
    return owned != mOwned.end() ? owned->mRigidBody.get() : nullptr;
}

BodyId BulletAdapter::FindBody(const btCollisionObject& inObject) const
{
    const auto found = mLookup.find(&inObject);
    return found == mLookup.end() ? BodyId{} : found->second;
}

Result<btConvexHullShape*> BulletAdapter::CreateFollowingHull(ObjectId inObject, int inMaxPoints)
{
    const DeformableObject* object = mDamage.GetObject(inObject);
    if (object == nullptr)
        return MakeError(EError::OutOfRange, "CreateFollowingHull: no such deformable object");
    if (inMaxPoints < 4)
        return MakeError(EError::InvalidArgument, "CreateFollowingHull: a hull needs at least 4 points");
    const BodyId body = mDamage.GetObjectBody(inObject);
    const auto owner = std::find_if(mBodies.begin(), mBodies.end(), [&](const MappedBody& m) { return m.mBody == body; });
    if (owner == mBodies.end())
        return MakeError(EError::OutOfRange, "CreateFollowingHull: the object's body is not a Bullet body of this adapter");

    // Hull points: an even subsample of the mesh vertices (the hull of a subsample of a closed car
    // surface keeps its silhouette; Bullet's GJK then works on at most inMaxPoints support points).
    const std::vector<Vec3>& positions = object->GetDeformer().GetPositions();
    FollowingHull hull;
    hull.mObject = inObject;
    hull.mOwner = owner->mObject;
    hull.mShape = std::make_unique<btConvexHullShape>();
    const std::size_t stride = std::max<std::size_t>(1, positions.size() / static_cast<std::size_t>(inMaxPoints));
    for (std::size_t v = 0; v < positions.size(); v += stride)
    {
        hull.mVertices.push_back(static_cast<std::uint32_t>(v));
        const Vec3& p = positions[v];
        hull.mShape->addPoint(btVector3(btScalar(p.x()), btScalar(p.y()), btScalar(p.z())), false);
    }
    hull.mShape->recalcLocalAabb();
    btConvexHullShape* shape = hull.mShape.get();
    mHulls.push_back(std::move(hull));
    return shape;
}

void BulletAdapter::PreTick(double)
{
    const bool timed = mSettings.mMeasureCpuTime;
    const double start = timed ? ThreadCpuSeconds() : 0.0;
    // Pre-solve snapshot of every awake mapped body; sleeping bodies keep their last (resting) state.
    int snapshotted = 0;
    for (const MappedBody& mapped : mBodies)
    {
        // intent: kinematic bodies moved by the game are snapshotted too (they carry CF_STATIC_OBJECT when
        // made with mass 0, as Bullet's examples make them)
        if (!mapped.mObject->isActive() ||
            (mapped.mObject->isStaticObject() && !mapped.mObject->isKinematicObject()))
            continue;
        if (mDamage.SetBodyState(mapped.mBody, BulletBodyState(*mapped.mObject)))
            ++snapshotted;
    }
    mLastStats = {};
    mLastStats.mBodiesSnapshotted = snapshotted;
    mLastStats.mSeconds = timed ? ThreadCpuSeconds() - start : 0.0;
}

void BulletAdapter::PostTick(double inTimeStep)
{
    const bool timed = mSettings.mMeasureCpuTime;
    const double start = timed ? ThreadCpuSeconds() : 0.0;
    mTime += inTimeStep;

    // Manifold points of mapped pairs that touch, in the dispatcher's (deterministic) order.
    mEvents.clear();
    btDispatcher* dispatcher = mWorld.getDispatcher();
    const int manifolds = dispatcher->getNumManifolds();
    for (int m = 0; m < manifolds; ++m)
    {
        const btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
        if (manifold->getNumContacts() == 0)
            continue;
        const auto a = mLookup.find(manifold->getBody0());
        const auto b = mLookup.find(manifold->getBody1());
        if (a == mLookup.end() || b == mLookup.end())
            continue;
        // intent: a body the game removed from the damage world itself (DamageWorld::RemoveBody, not ours) is
        // left out as an unmapped one: its contacts would make the world refuse the whole step's batch
        if (mDamage.GetBodyState(a->second) == nullptr || mDamage.GetBodyState(b->second) == nullptr)
            continue;
        for (int p = 0; p < manifold->getNumContacts(); ++p)
        {
            const btManifoldPoint& point = manifold->getContactPoint(p);
            const double distance = static_cast<double>(point.getDistance());
            if (distance > mSettings.mMaxSeparation)
                continue;
            ContactEvent event;
            event.mBodyA = a->second;
            event.mBodyB = b->second;
            event.mPointOnA = ToVec3(point.getPositionWorldOnA());
            event.mPointOnB = ToVec3(point.getPositionWorldOnB());
            event.mNormal = ToVec3(point.m_normalWorldOnB).normalized(); // from B towards A, as Crumple expects
            event.mPenetrationDepth = -distance;
            event.mFriction = static_cast<double>(point.m_combinedFriction); // what Bullet's solver uses for the point
            event.mTime = mTime;
            mEvents.push_back(event);
        }
    }
    mLastStats.mContactsReported = static_cast<int>(mEvents.size());
    // Bullet's output is finite unless the game's simulation already diverged; then the step is skipped.
    if (!mEvents.empty() && !mDamage.SubmitContacts(mEvents, inTimeStep))
        mLastStats.mContactsRefused = static_cast<int>(mEvents.size());
    mLastStats.mUpdate = mDamage.Update(mTime);
    if (!mHulls.empty() && mDamage.GetShapeRevision() != mHullRevision)
        UpdateHulls();
    HoldProps();
    if (timed)
        mLastStats.mSeconds += ThreadCpuSeconds() - start;
}

void BulletAdapter::UpdateHulls()
{
    mHullRevision = mDamage.GetShapeRevision();
    for (FollowingHull& hull : mHulls)
    {
        const DeformableObject* object = mDamage.GetObject(hull.mObject);
        if (object == nullptr || hull.mOwner == nullptr)
            continue;
        const std::vector<Vec3>& positions = object->GetDeformer().GetPositions();
        btVector3* points = hull.mShape->getUnscaledPoints();
        for (std::size_t i = 0; i < hull.mVertices.size(); ++i)
        {
            const Vec3& p = positions[hull.mVertices[i]];
            points[i] = btVector3(btScalar(p.x()), btScalar(p.y()), btScalar(p.z()));
        }
        hull.mShape->recalcLocalAabb();
        // intent: a compound caches its children's bounds (its AABB tree and its own box): refresh the hull's
        if (btCollisionShape* shape = hull.mOwner->getCollisionShape(); shape != nullptr && shape->isCompound())
        {
            auto* compound = static_cast<btCompoundShape*>(shape);
            for (int child = 0; child < compound->getNumChildShapes(); ++child)
                if (compound->getChildShape(child) == hull.mShape.get())
                    compound->updateChildTransform(child, compound->getChildTransform(child), true);
        }
        mWorld.updateSingleAabb(hull.mOwner);
    }
}

} // namespace crumple::bullet
