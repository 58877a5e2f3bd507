// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "CarFrontOnFenceCrawl.h"

namespace crumple::common
{

CarFrontOnFenceCrawl MakeCarFrontOnFenceCrawl()
{
    CarFrontOnFenceCrawl c;
    c.mCar.mMass = 0x1.2bffff8620003p+10;
    c.mCar.mInverseInertiaWorld << 0x1.f2c10ap-10, -0x1.f966c8p-14, -0x1.b25d76p-24, -0x1.f966c8p-14,
        0x1.1e4ce4p-11, 0x1.fbd258p-22, -0x1.b25d76p-24, 0x1.fbd258p-22, 0x1.e05086p-12;
    c.mCar.mCenterOfMass = Vec3(0x1.5c831ep+5, 0x1.51aeecp-1, 0x1.a25c48p-1);
    c.mCar.mLinearVelocity = Vec3(0x1.0b11ep+4, -0x1.99d546p+0, 0x1.175d6ap-1);
    c.mCar.mAngularVelocity = Vec3(-0x1.a7cca4p-3, -0x1.d7c75ap-3, -0x1.76b382p-3);
    c.mFence.mMass = 0x1.9000009600004p+5;
    c.mFence.mInverseInertiaWorld << 0x1.5c0e5cp-7, 0x1.6a1e5ep-9, -0x1.166b9p-19, 0x1.6a1e5ep-9,
        0x1.518ed4p-2, -0x1.f1f5e8p-15, -0x1.166b9p-19, -0x1.f1f5e8p-15, 0x1.667acp-7;
    c.mFence.mCenterOfMass = Vec3(0x1.686666p+5, 0x1.0cp-44, 0x1.3851ecp-1);
    c.mFence.mLinearVelocity = Vec3(-0x1.ef3812p-1, -0x1.63f65p-3, -0x1.0a7032p-4);
    c.mFence.mAngularVelocity = Vec3(0x0p+0, 0x0p+0, 0x0p+0);
    c.mContacts = {
        {Vec3(0x1.6c8b81p+5, 0x1.3dd9d8p+0, 0x1.4c3775p-1),
         Vec3(-0x1.fe05d7441f06ap-1, 0x1.679ea97b8692p-4, 0x1.997ab56928a2cp-14), 0x0p+0, 0x1p-2},
        {Vec3(0x1.6ce492p+5, 0x1.121844p+0, 0x1.364444p-1),
         Vec3(-0x1.fe062c9d684ebp-1, 0x1.67806d060ec42p-4, 0x1.1a6be33ba5bf3p-14), 0x0p+0, 0x1p-2},
        {Vec3(0x1.6ce7a8p+5, 0x1.12111p+0, 0x1.36365cp-1),
         Vec3(-0x1.fe0636831aa72p-1, 0x1.677cee5c68771p-4, 0x1.6feb085e93371p-15), 0x0p+0, 0x1p-2},
        {Vec3(0x1.6cbf7p+5, 0x1.01ea3a8p+0, 0x1.3ccdb4p-1),
         Vec3(-0x1.fe05d840da94fp-1, 0x1.679e42c4b75d5p-4, 0x1.1a2cef089c95ap-13), 0x0p+0, 0x1p-2},
        {Vec3(0x1.6cce7ep+5, 0x1.d39fa3p-1, 0x1.37952p-1),
         Vec3(-0x1.fe05741735e02p-1, 0x1.67c1b4105f414p-4, 0x1.64211e1034fefp-13), 0x0p+0, 0x1p-2},
        {Vec3(0x1.6ceadbp+5, 0x1.720f25p-1, 0x1.2ef31ep-1),
         Vec3(-0x1.fe05d85812a7cp-1, 0x1.679e47a71cdeap-4, 0x1.9952e7e1982a7p-14), 0x0p+0, 0x1p-2},
        {Vec3(0x1.6d0f42p+5, 0x1.edf32ap-2, 0x1.3fd48dp-1),
         Vec3(-0x1.fe05d31d8e64ap-1, 0x1.67a016c959b01p-4, 0x1.1183e099235f4p-13), 0x0p+0, 0x1p-2},
        {Vec3(0x1.6cf99fp+5, 0x1.0f4fb4p-1, 0x1.28e50bp-1),
         Vec3(-0x1.fe05d834f1471p-1, 0x1.679e54255473ep-4, 0x1.98ccb82a6f633p-14), 0x0p+0, 0x1p-2},
        {Vec3(0x1.6c6992p+5, -0x1.062324p-1, 0x1.482993p-1),
         Vec3(-0x1.c178d4fd9a92bp-1, 0x1.ea606ee616927p-2, 0x1.436e174610586p-9), 0x0p+0, 0x1p-2},
        {Vec3(0x1.6c643ap+5, -0x1.0f086bp-1, 0x1.3338a4p-1),
         Vec3(-0x1.16ba3475cac93p-1, 0x1.ad79b2b57fd22p-1, 0x1.3849ee83f9b5bp-8), 0x0p+0, 0x1p-2},
        {Vec3(0x1.6c6351p+5, -0x1.02339dp-1, 0x1.359f8ap-1),
         Vec3(-0x1.f25df925eea69p-1, 0x1.d5737914e0b9bp-3, 0x1.ecdb0d22ae809p-11), 0x0p+0, 0x1p-2},
        {Vec3(0x1.6d0b8ap+5, 0x1.e744d6p-3, 0x1.3d0deep-1),
         Vec3(-0x1.fe05d8e1ade49p-1, 0x1.679e169f206b9p-4, 0x1.9cb4dcb69e2eap-14), 0x0p+0, 0x1p-2},
        {Vec3(0x1.6cf85fp+5, 0x1.e51ccdp-3, 0x1.24ebe9p-1),
         Vec3(-0x1.fe05db1923533p-1, 0x1.679d4d5d386c5p-4, 0x1.9d86bd44d132dp-14), 0x0p+0, 0x1p-2},
        {Vec3(0x1.6cad6bp+5, -0x1.04532cp-2, 0x1.2c01dp-1),
         Vec3(-0x1.fe05d307e24eap-1, 0x1.67a02a2316c24p-4, 0x1.962e2269e93fap-14), 0x0p+0, 0x1p-2},
        {Vec3(0x1.6c64ebp+5, -0x1.fd7171p-2, 0x1.356bd7p-1),
         Vec3(-0x1.fe05f84372ca8p-1, 0x1.6792f82f8d58dp-4, 0x1.7d09f2326408cp-14), 0x0p+0, 0x1p-2},
        {Vec3(0x1.6c7615p+5, -0x1.cbb226p-2, 0x1.335937p-1),
         Vec3(-0x1.fe05c76c62186p-1, 0x1.67a44797e8802p-4, 0x1.9728158a27e84p-14), 0x0p+0, 0x1p-2},
    };
    for (plugin::BodyState* body : {&c.mCar, &c.mFence})
        body->mTransform.mTranslation = body->mCenterOfMass;
    c.mRestitution = 0x1.999999999999ap-4;
    c.mClosingSpeed = 0x1p-1;
    return c;
}

} // namespace crumple::common
