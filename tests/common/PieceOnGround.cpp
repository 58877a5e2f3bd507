// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "PieceOnGround.h"

namespace crumple::common
{

PieceOnGround MakePieceOnGround()
{
    PieceOnGround c;
    c.mGround.mMotionType = plugin::EMotionType::Static;
    c.mPiece.mMass = 0x1.0fffffffffffap+1;
    c.mPiece.mInverseInertiaWorld << 0x1.b91720cd20f35p+7, -0x1.b5c39c30f8596p+6, -0x1.00c136b42c10bp+1,
        -0x1.b5c39c30f8596p+6, 0x1.6bca4b09de4f8p+6, 0x1.24ba86f71b99ep+0, -0x1.00c136b42c10bp+1,
        0x1.24ba86f71b99ep+0, 0x1.c9efb2f2e88f5p+4;
    c.mPiece.mCenterOfMass = Vec3(0x1.99837f5232da7p+5, 0x1.d6b1f2d68d929p+0, 0x1.218a3be1e0316p-4);
    c.mPiece.mLinearVelocity = Vec3(0x1.1daa55cb6052dp+4, 0x1.150680f387b57p-3, -0x1.073a72b894d91p+0);
    c.mPiece.mAngularVelocity = Vec3(0x1.0fec0a92ed7cep+1, 0x1.d24954e0b3782p+1, 0x1.985f143dbabf3p+0);
    c.mPiece.mTransform.mTranslation = c.mPiece.mCenterOfMass;
    const Vec3 down(-0x0p+0, -0x0p+0, -0x1p+0);
    const double friction = 0x1.3333333333333p-2;
    c.mContacts = {
        {Vec3(0x1.9b5198c9056c3p+5, 0x1.cba86d838facep+0, -0x1.161326aba9ff1p-8), down, 0.0, friction},
        {Vec3(0x1.9abec5d06eb9ap+5, 0x1.ab76613ea09e4p+0, -0x1.147441dbb20bp-8), down, 0.0, friction},
        {Vec3(0x1.9819c98fe6a47p+5, 0x1.032e078cdc5p+1, -0x1.4c625590cfap-15), down, 0.0, friction},
        {Vec3(0x1.9786f6974ff1dp+5, 0x1.e62a02d4c9916p+0, -0x1.f3bfb653566p-17), down, 0.0, friction},
    };
    return c;
}

} // namespace crumple::common
