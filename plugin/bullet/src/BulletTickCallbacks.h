// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <LinearMath/btScalar.h>

class btDynamicsWorld;

namespace crumple::bullet
{

class BulletAdapter;

/// Bullet's internal tick callbacks, which forward to the adapter stored as the world's user info.
/// Also reads the game's previously installed callbacks, which btDynamicsWorld keeps protected.
struct BulletTickCallbacks
{
    static void PreTick(btDynamicsWorld* inWorld, btScalar inTimeStep);
    static void PostTick(btDynamicsWorld* inWorld, btScalar inTimeStep);
    using Callback = void (*)(btDynamicsWorld*, btScalar);
    static Callback InstalledPreTick(const btDynamicsWorld& inWorld);
    static Callback InstalledPostTick(const btDynamicsWorld& inWorld);
    static void CallPrevious(BulletAdapter& inAdapter, btDynamicsWorld* inWorld, btScalar inTimeStep, bool inPreTick);
};

} // namespace crumple::bullet
