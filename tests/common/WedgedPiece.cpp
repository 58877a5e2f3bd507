// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "WedgedPiece.h"

namespace crumple::common
{

using plugin::BodyState;

WedgedPiece MakeWedgedPiece()
{
    WedgedPiece w;
    w.mFence.mMass = 0x1.9000009600004p+5;
    w.mFence.mInverseInertiaWorld << 0x1.5b472ep-7, 0x1.fb85cp-13, 0x1.6c226p-22, 0x1.fb85cp-13,
        0x1.519512p-2, -0x1.226842p-17, 0x1.6c226p-22, -0x1.226842p-17, 0x1.667abap-7;
    w.mFence.mCenterOfMass = Vec3(0x1.686666p+5, 0x1.0cp-44, 0x1.3851ecp-1);
    w.mFence.mLinearVelocity = Vec3(0x1.208248p+4, -0x1.d20cc4p+1, -0x1.8b61f4p-8);
    w.mPiece.mMass = 0x1p-3;
    w.mPiece.mInverseInertiaWorld << 0x1.2a2918p+14, -0x1.290af6p+8, -0x1.141feep+7, -0x1.290af6p+8,
        0x1.e17d04p+12, -0x1.320cp+2, -0x1.141feep+7, -0x1.320cp+2, 0x1.e2acacp+12;
    w.mPiece.mCenterOfMass = Vec3(0x1.6865ap+5, -0x1.f8fc64p+0, 0x1.66ceb4p-4);
    w.mPiece.mLinearVelocity = Vec3(0x1.3f46c2p+4, 0x1.42c65ap+0, 0x1.1fbf9ep-1);
    w.mPiece.mAngularVelocity = Vec3(-0x1.de5214p+3, 0x1.dada82p+0, -0x1.0f6448p+2);
    for (BodyState* body : {&w.mFence, &w.mPiece})
        body->mTransform.mTranslation = body->mCenterOfMass;
    w.mContacts = {{Vec3(0x1.68440dp+5, -0x1.f86108p+0, 0x1.ce7b6cp-4),
                    Vec3(0x1.04166d5c82541p-6, 0x1.2b8f0d43b2915p-4, 0x1.fe9070bf0f456p-1), 0.0, 0.25},
                   {Vec3(0x1.689927p+5, -0x1.f8c2e3p+0, 0x1.c849e8p-4),
                    Vec3(0x1.586ffc6f9da3p-6, 0x1.42c0b488d29bfp-4, 0x1.fe4b65aed1912p-1), 0.0, 0.25},
                   {Vec3(0x1.688058p+5, -0x1.f61138p+0, 0x1.29836p-4),
                    Vec3(0x1.55f9d8a2680e9p-7, 0x1.5fc564a70ee8p-1, -0x1.73fc10b0a863cp-1), 0.0, 0.25},
                   {Vec3(0x1.68343bp+5, -0x1.f5e489p+0, 0x1.2a9418p-4),
                    Vec3(0x1.eadf2618b1188p-8, 0x1.5fb3ba11b0f7fp-1, -0x1.74118812b73b9p-1), 0.0, 0.25}};
    return w;
}

} // namespace crumple::common
