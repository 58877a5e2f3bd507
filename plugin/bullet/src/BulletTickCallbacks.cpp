// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "BulletTickCallbacks.h"

#include <crumple/bullet/BulletAdapter.h>

#include <btBulletDynamicsCommon.h>

namespace crumple::bullet
{

namespace
{

// btDynamicsWorld keeps its callbacks protected and has no getter. A member pointer formed inside a
// derived class is the standard, well-defined way to read them (no cast of the world object itself).
struct CallbackAccess : btDynamicsWorld
{
    static constexpr auto cPreTick = &CallbackAccess::m_internalPreTickCallback;
    static constexpr auto cPostTick = &CallbackAccess::m_internalTickCallback;
};

} // namespace

BulletTickCallbacks::Callback BulletTickCallbacks::InstalledPreTick(const btDynamicsWorld& inWorld)
{
    return inWorld.*CallbackAccess::cPreTick;
}

BulletTickCallbacks::Callback BulletTickCallbacks::InstalledPostTick(const btDynamicsWorld& inWorld)
{
    return inWorld.*CallbackAccess::cPostTick;
}

void BulletTickCallbacks::CallPrevious(BulletAdapter& inAdapter, btDynamicsWorld* inWorld, btScalar inTimeStep,
                                       bool inPreTick)
{
    const Callback previous = inPreTick ? inAdapter.mPreviousPreTick : inAdapter.mPreviousPostTick;
    if (previous == nullptr)
        return;
    // The game's callback reads its own user pointer from the world: restore it around the call.
    void* ours = inWorld->getWorldUserInfo();
    inWorld->setWorldUserInfo(inAdapter.mPreviousUserInfo);
    previous(inWorld, inTimeStep);
    inWorld->setWorldUserInfo(ours);
}

void BulletTickCallbacks::PreTick(btDynamicsWorld* inWorld, btScalar inTimeStep)
{
    auto* adapter = static_cast<BulletAdapter*>(inWorld->getWorldUserInfo());
    CallPrevious(*adapter, inWorld, inTimeStep, true);
    adapter->PreTick(static_cast<double>(inTimeStep));
}

void BulletTickCallbacks::PostTick(btDynamicsWorld* inWorld, btScalar inTimeStep)
{
    auto* adapter = static_cast<BulletAdapter*>(inWorld->getWorldUserInfo());
    adapter->PostTick(static_cast<double>(inTimeStep));
    CallPrevious(*adapter, inWorld, inTimeStep, false);
}

} // namespace crumple::bullet
