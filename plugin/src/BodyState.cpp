// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/plugin/BodyState.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <string>

namespace crumple::plugin
{

Status ValidateBodyState(const BodyState& inState)
{
    if (inState.mMotionType != EMotionType::Dynamic && inState.mMotionType != EMotionType::Kinematic &&
        inState.mMotionType != EMotionType::Static)
        return MakeError(EError::InvalidArgument, "BodyState.mMotionType is not an EMotionType value");
    if (!IsFinite(inState.mMass) || !IsFinite(inState.mInverseInertiaWorld) || !IsFinite(inState.mCenterOfMass) ||
        !IsFinite(inState.mLinearVelocity) || !IsFinite(inState.mAngularVelocity) ||
        !IsFinite(inState.mTransform.mRotation) || !IsFinite(inState.mTransform.mTranslation))
        return MakeError(EError::NonFinite, "BodyState has a NaN or Inf field");
    if (!(inState.mLinearVelocity.norm() <= cMaxBodySpeed))
        return MakeError(EError::OutOfRange, "BodyState.mLinearVelocity is faster than 1e6 m/s");
    if (!(inState.mAngularVelocity.norm() <= cMaxBodyAngularSpeed))
        return MakeError(EError::OutOfRange, "BodyState.mAngularVelocity is faster than 1e6 rad/s");
    if (!(inState.mCenterOfMass.cwiseAbs().maxCoeff() <= cMaxBodyPosition) ||
        !(inState.mTransform.mTranslation.cwiseAbs().maxCoeff() <= cMaxBodyPosition))
        return MakeError(EError::OutOfRange, "BodyState is farther than 1e9 m from the world's origin");
    if (!IsRotation(inState.mTransform.mRotation, cRotationTolerance))
        return MakeError(EError::DegenerateGeometry, "BodyState.mTransform.mRotation is not a rotation");
    if (inState.mHasShapeBounds)
    {
        if (!IsFinite(inState.mShapeMin) || !IsFinite(inState.mShapeMax))
            return MakeError(EError::NonFinite, "BodyState.mShapeMin or mShapeMax has a NaN or Inf component");
        if (!(inState.mShapeMin.cwiseAbs().maxCoeff() <= cMaxBodyPosition) ||
            !(inState.mShapeMax.cwiseAbs().maxCoeff() <= cMaxBodyPosition))
            return MakeError(EError::OutOfRange, "BodyState.mShapeMin or mShapeMax is beyond 1e9 m (state an unbounded shape out to 1e9 m)");
        if (!(inState.mShapeMin.array() <= inState.mShapeMax.array()).all())
            return MakeError(EError::InvalidArgument, "BodyState.mShapeMin is above mShapeMax on an axis");
    }
    if (inState.mMotionType == EMotionType::Dynamic)
    {
        if (!(inState.mMass > 0.0))
            return MakeError(EError::InvalidArgument,
                             "BodyState.mMass = " + std::to_string(inState.mMass) + " kg: a dynamic body needs mass > 0");
        if (!(inState.mMass <= cMaxBodyMass))
            return MakeError(EError::OutOfRange, "BodyState.mMass is above 1e12 kg");
        // intent: a subnormal mass (4.9e-324 kg) passed as > 0 and had an infinite inverse: its contacts then
        // made no collision at all
        if (!(inState.mMass >= cMinBodyMass))
            return MakeError(EError::OutOfRange, "BodyState.mMass = " + std::to_string(inState.mMass) +
                                                     " kg: a dynamic body needs at least 1e-12 kg");
        if (!(inState.mInverseInertiaWorld.cwiseAbs().maxCoeff() <= cMaxInverseInertia))
            return MakeError(EError::OutOfRange, "BodyState.mInverseInertiaWorld has an entry above 1e12 1/(kg m^2)");
        const Mat3& inverse_inertia = inState.mInverseInertiaWorld;
        const double scale = inverse_inertia.cwiseAbs().maxCoeff();
        if (!((inverse_inertia - inverse_inertia.transpose()).cwiseAbs().maxCoeff() <=
              cInverseInertiaAsymmetry * scale))
            return MakeError(EError::InvalidArgument, "BodyState.mInverseInertiaWorld is not symmetric");
        // intent: a Cholesky factorisation that succeeds proves the matrix positive definite, far cheaper than
        // its eigenvalues (this runs for every awake body at every step); only a matrix it refuses (a zero or
        // negative eigenvalue) is judged by its smallest eigenvalue against the tolerance
        if (Eigen::LLT<Mat3>(inverse_inertia).info() == Eigen::Success)
            return Status::Ok();
        const Eigen::Vector3d eigenvalues = Eigen::SelfAdjointEigenSolver<Mat3>(inverse_inertia, Eigen::EigenvaluesOnly).eigenvalues();
        if (eigenvalues.minCoeff() < -1.0e-12 * scale)
            return MakeError(EError::InvalidArgument,
                             "BodyState.mInverseInertiaWorld has a negative eigenvalue: inertia must be positive");
    }
    return Status::Ok();
}

BodyState CanonicalBodyState(const BodyState& inState)
{
    BodyState state = inState;
    // intent: the strict bounds the library held before it took single-precision input; within them a state
    // is kept as given, so recordings of double-precision engines keep their bits
    if (!IsRotation(state.mTransform.mRotation, 1.0e-6))
        state.mTransform.mRotation = Quat(state.mTransform.mRotation).normalized().toRotationMatrix();
    // (a copy: the symmetric part written into the matrix it reads would alias)
    const Mat3 inverse_inertia = state.mInverseInertiaWorld;
    if ((inverse_inertia - inverse_inertia.transpose()).cwiseAbs().maxCoeff() >
        1.0e-9 * inverse_inertia.cwiseAbs().maxCoeff())
        state.mInverseInertiaWorld = 0.5 * (inverse_inertia + inverse_inertia.transpose());
    return state;
}

} // namespace crumple::plugin
