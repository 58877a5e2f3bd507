// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "CarOnHeldFence.h"

namespace crumple::common
{

plugin::BodyState RacingFenceHeldBody()
{
    plugin::BodyState fence;
    fence.mMass = 0x1.9000009600004p+5;
    fence.mInverseInertiaWorld << 0x1.5b459ep-7, 0x0p+0, 0x0p+0, 0x0p+0, 0x1.51951ap-2, 0x0p+0, 0x0p+0,
        0x0p+0, 0x1.667ab6p-7;
    fence.mCenterOfMass = Vec3(0x1.686666p+5, 0x1.0cp-44, 0x1.3851ecp-1);
    fence.mLinearVelocity = Vec3::Zero();
    fence.mAngularVelocity = Vec3::Zero();
    fence.mTransform.mTranslation = fence.mCenterOfMass;
    return fence;
}

CarOnHeldFence MakeCarOnHeldFence()
{
    CarOnHeldFence c;
    c.mCar.mMass = 0x1.2bffff8620003p+10;
    c.mCar.mInverseInertiaWorld << 0x1.f3f24p-10, 0x1.7ec9f4p-14, -0x1.515f1ap-24, 0x1.7ec9f4p-14,
        0x1.1beadp-11, -0x1.8cd4b4p-28, -0x1.515f1ap-24, -0x1.8cd4b4p-28, 0x1.e04fc4p-12;
    c.mCar.mCenterOfMass = Vec3(0x1.56f2fep+5, 0x1.9e74c4p-1, 0x1.9e3646p-1);
    c.mCar.mLinearVelocity = Vec3(0x1.400daap+4, 0x1.54b32p+0, 0x1.5845bep-5);
    c.mCar.mAngularVelocity = Vec3(0x1.5fd76cp-14, -0x1.c5314cp-12, 0x1.681738p-26);
    c.mFence = RacingFenceHeldBody();
    for (plugin::BodyState* body : {&c.mCar, &c.mFence})
        body->mTransform.mTranslation = body->mCenterOfMass;
    c.mContacts = {
        {Vec3(0x1.67d546p+5, 0x1.ff4a11p-1, 0x1.cb347bp-2),
         Vec3(-0x1.feded9e74565fp-1, -0x1.0feb7bf2d66cep-4, 0x1.9372ebec788b6p-15), 0x1.1ac0abe897699p+3,
         0x1p-2},
        {Vec3(0x1.67d54bp+5, 0x1.ff4a29p-1, 0x1.9eaa77p-1),
         Vec3(-0x1.fededc17536dfp-1, -0x1.0fea74fbe5ff4p-4, 0x1.8f9b6c81c14f3p-15), 0x1.1a9b1748b84bap+3,
         0x1p-2},
        {Vec3(0x1.67e641p+5, 0x1.7f925fp-1, 0x1.b85204p-1),
         Vec3(-0x1.feded9982e358p-1, -0x1.0feb9fc8bd78fp-4, 0x1.c88fa9a337a02p-15), 0x1.363c30f08b553p+2,
         0x1p-2},
        {Vec3(0x1.67f736p+5, 0x1.ffb52ap-2, 0x1.b851f5p-1),
         Vec3(-0x1.feded805cb189p-1, -0x1.0fec5cf28f24p-4, 0x1.c21b6042008e2p-15), 0x1.ba89c77cc7717p-1,
         0x1p-2},
        {Vec3(0x1.67e63bp+5, 0x1.7f9246p-1, 0x1.cb3472p-2),
         Vec3(-0x1.feded73dbfd5p-1, -0x1.0fecbb989ad3bp-4, 0x1.a684755f581ffp-15), 0x1.369661b03c6a8p+2,
         0x1p-2},
        {Vec3(0x1.67f73p+5, 0x1.ffb4fap-2, 0x1.cb346ap-2),
         Vec3(-0x1.feded9daaaf2cp-1, -0x1.0feb81ec2116bp-4, 0x1.911b15e2b05bep-15), 0x1.bd5b2bba5039cp-1,
         0x1p-2},
        {Vec3(0x1.680826p+5, 0x1.0045648p-2, 0x1.cb345fp-2),
         Vec3(-0x1.feded9357c1c6p-1, -0x1.0febcf94350b3p-4, 0x1.8df5cf623e6a3p-15), 0x0p+0, 0x1p-2},
        {Vec3(0x1.68082bp+5, 0x1.004593p-2, 0x1.b851e4p-1),
         Vec3(-0x1.fedede45de31bp-1, -0x1.0fe96d35b3472p-4, 0x1.c992d00929faap-15), 0x0p+0, 0x1p-2},
        {Vec3(0x1.681921p+5, 0x1.ac01e4p-11, 0x1.b851d5p-1),
         Vec3(-0x1.fededac781ffcp-1, -0x1.0feb1159abe7ep-4, 0x1.c73222e9902edp-15), 0x0p+0, 0x1p-2},
        {Vec3(0x1.68191bp+5, 0x1.ab9e9cp-11, 0x1.cb344fp-2),
         Vec3(-0x1.feded838f56a3p-1, -0x1.0fec450dcb1fcp-4, 0x1.bcbebc73db945p-15), 0x0p+0, 0x1p-2},
        {Vec3(0x1.681b87p+5, -0x1.206c18p-5, 0x1.d70a1p-2),
         Vec3(-0x1.fffffff460b4ep-1, 0x1.78d9d7f77212fp-19, 0x1.b3bbe1f61be5ep-15), 0x0p+0, 0x1p-2},
        {Vec3(0x1.681b8cp+5, -0x1.2064dfp-5, 0x1.a52e31p-1),
         Vec3(-0x1.ffffffede2fd4p-1, 0x1.4a596ff450234p-16, 0x1.038f69f6d1404p-14), 0x0p+0, 0x1p-2}};
    return c;
}

} // namespace crumple::common
