// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "CarFrontOnFenceStall.h"
#include "CarOnHeldFence.h"

namespace crumple::common
{

CarFrontOnFenceStall MakeCarFrontOnFenceStall()
{
    CarFrontOnFenceStall c;
    c.mCar.mMass = 0x1.2bffff8620003p+10;
    c.mCar.mInverseInertiaWorld << 0x1.f5832ap-10, -0x1.8642cap-17, -0x1.7d7862p-24, -0x1.8642cap-17,
        0x1.18c8f2p-11, -0x1.6af558p-23, -0x1.7d7862p-24, -0x1.6af558p-23, 0x1.e04fdep-12;
    c.mCar.mCenterOfMass = Vec3(0x1.57a724p+5, 0x1.41776cp-2, 0x1.9e2c56p-1);
    c.mCar.mLinearVelocity = Vec3(0x1.404e5ep+4, -0x1.043f3cp-2, 0x1.545888p-5);
    c.mCar.mAngularVelocity = Vec3(0x1.35ad6p-7, -0x1.50697cp-11, -0x1.0debecp-4);
    c.mFence = RacingFenceHeldBody();
    for (plugin::BodyState* body : {&c.mCar, &c.mFence})
        body->mTransform.mTranslation = body->mCenterOfMass;
    c.mContacts = {
        {Vec3(0x1.683fd4p+5, 0x1.47c311p+0, 0x1.9e8f54p-1),
         Vec3(-0x1.ffffffe93408cp-1, 0x1.5591e5f0caa8dp-15, 0x1.fac927e96f77dp-15), 0x0p+0, 0x1p-2},
        {Vec3(0x1.683fcfp+5, 0x1.478486p+0, 0x1.cafb24p-2),
         Vec3(-0x1.ffffffe9e8634p-1, 0x1.46d625f1e5b9bp-15, 0x1.f91c67ea347c2p-15), 0x0p+0, 0x1p-2},
        {Vec3(0x1.687309p+5, 0x1.47b80ep+0, 0x1.a4226cp-1),
         Vec3(-0x1.ffffffe7b8edcp-1, -0x1.dd0425e961972p-16, 0x1.23ec89f22863dp-14), 0x0p+0, 0x1p-2},
        {Vec3(0x1.6872c8p+5, 0x1.3ffca6p+0, 0x1.b851e1p-1),
         Vec3(-0x1.fffb534f1fcedp-1, 0x1.14bc8ab524356p-7, 0x1.f0e54f453fe03p-15), 0x0p+0, 0x1p-2},
        {Vec3(0x1.683d68p+5, 0x1.ffdeb2p-1, 0x1.9e9444p-1),
         Vec3(-0x1.fffb5569bde38p-1, 0x1.147e07aedaa2dp-7, 0x1.069ac5b2ee0bcp-14), 0x0p+0, 0x1p-2},
        {Vec3(0x1.686c4bp+5, 0x1.fff9ap-2, 0x1.b851e7p-1),
         Vec3(-0x1.fffb542766303p-1, 0x1.14a36c1549db1p-7, 0x1.fffc502766439p-15), 0x0p+0, 0x1p-2},
        {Vec3(0x1.686e6ep+5, 0x1.7ffba7p-1, 0x1.cb18d9p-2),
         Vec3(-0x1.fffb54c5834dep-1, 0x1.1491926ab1e94p-7, 0x1.bed4a2ac60fa6p-15), 0x0p+0, 0x1p-2},
        {Vec3(0x1.687097p+5, 0x1.fffa7ep-1, 0x1.cb0afcp-2),
         Vec3(-0x1.fffb544010b24p-1, 0x1.14a0e8229d733p-7, 0x1.ceea3839ece6dp-15), 0x0p+0, 0x1p-2},
        {Vec3(0x1.683911p+5, 0x1.ffc29ap-2, 0x1.cb23p-2),
         Vec3(-0x1.fffb518364c19p-1, 0x1.14f0cdbc9917cp-7, 0x1.30a1a9b5dbcd4p-14), 0x0p+0, 0x1p-2},
        {Vec3(0x1.6836edp+5, 0x1.ff88b4p-3, 0x1.9eaa6cp-1),
         Vec3(-0x1.fffb51bba1ed2p-1, 0x1.14ea6ddb05a5ap-7, 0x1.2956ebd84b75dp-14), 0x0p+0, 0x1p-2},
        {Vec3(0x1.6867fap+5, -0x1.b3b678p-18, 0x1.aedb6ep-1),
         Vec3(-0x1.fffb5379b1d0ep-1, 0x1.14b7ebb768f23p-7, 0x1.c3dfb789765d4p-15), 0x0p+0, 0x1p-2},
        {Vec3(0x1.6867f4p+5, -0x1.acbd3p-18, 0x1.d70a3ap-2),
         Vec3(-0x1.fffb542a4196fp-1, 0x1.14a32d022f552p-7, 0x1.f43806350c76fp-15), 0x0p+0, 0x1p-2},
        {Vec3(0x1.683069p+5, -0x1.0015fdp-1, 0x1.cb542fp-2),
         Vec3(-0x1.fffb533392f4ep-1, 0x1.14bec8a64158cp-7, 0x1.347754b94fc81p-14), 0x0p+0, 0x1p-2},
        {Vec3(0x1.6865cfp+5, -0x1.fffebbp-3, 0x1.a90168p-1),
         Vec3(-0x1.fffb53c09c8bfp-1, 0x1.14afb8f270917p-7, 0x1.c370938b9025p-15), 0x0p+0, 0x1p-2},
        {Vec3(0x1.6863a7p+5, -0x1.fffd0dp-2, 0x1.a32762p-1),
         Vec3(-0x1.fffb5391070b3p-1, 0x1.14b53cd8bdbb2p-7, 0x1.c17fa16015dbbp-15), 0x0p+0, 0x1p-2},
        {Vec3(0x1.68307p+5, -0x1.0019e7p-1, 0x1.9ebd64p-1),
         Vec3(-0x1.fffb52789c11ep-1, 0x1.14d4cd2c5f868p-7, 0x1.1c5fad269b721p-14), 0x0p+0, 0x1p-2},
    };
    c.mRestitution = 0x1.999999999999ap-4;
    c.mClosingSpeed = 0x1p-1;
    return c;
}

} // namespace crumple::common
