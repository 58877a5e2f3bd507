// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/props/FragmentBody.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <string>

namespace crumple::props
{

Result<FragmentRigidBody> FragmentBody(const fem::TetFragment& inFragment, std::span<const Vec3> inPositions,
                                       std::span<const Vec3> inVelocities, std::span<const double> inMasses,
                                       const plugin::BodyState& inPropBody)
{
    // intent: refuse before computing anything
    if (inFragment.mAnchored)
        return MakeError(EError::InvalidArgument, "FragmentBody: the fragment is anchored: it is not loose");
    if (inPositions.size() != inVelocities.size() || inPositions.size() != inMasses.size())
        return MakeError(EError::InvalidArgument, "FragmentBody: positions, velocities and masses differ in count");
    if (inFragment.mNodes.size() < 4 || !(inFragment.mMass > 0.0))
        return MakeError(EError::DegenerateGeometry, "FragmentBody: a fragment needs mass and at least 4 nodes");
    for (int node : inFragment.mNodes)
        if (node < 0 || static_cast<std::size_t>(node) >= inPositions.size())
            return MakeError(EError::OutOfRange, "FragmentBody: fragment node " + std::to_string(node) + " is not a node");
    if (Status state = plugin::ValidateBodyState(inPropBody); !state)
        return state.GetError();
    // intent: a single-precision engine's frame within round-off of a rotation, made one
    const plugin::BodyState prop_body = plugin::CanonicalBodyState(inPropBody);
    // intent: the nodes' lumped masses are the fragment's mass shared out (the body's momentum is theirs)
    double fragment_nodes_mass = 0.0;
    for (int node : inFragment.mNodes)
    {
        const double m = inMasses[static_cast<std::size_t>(node)];
        if (!(std::isfinite(m) && m >= 0.0))
            return MakeError(EError::InvalidArgument, "FragmentBody: node " + std::to_string(node) + "'s mass is not finite and >= 0 kg");
        fragment_nodes_mass += m;
    }
    // intent: each element lumps its mass onto its own nodes, so they hold at least the fragment's mass; they may
    // hold more where a node is shared with another fragment's elements (a group of separate components)
    if (!(fragment_nodes_mass >= inFragment.mMass * (1.0 - 1.0e-9)))
        return MakeError(EError::InvalidArgument, "FragmentBody: the nodes' masses (" + std::to_string(fragment_nodes_mass) +
                                                      " kg) are less than the fragment's (" + std::to_string(inFragment.mMass) + " kg)");

    // intent: the principal frame of the fragment's inertia, right-handed, moments ascending
    const Eigen::SelfAdjointEigenSolver<Mat3> eigen(inFragment.mInertia);
    if (eigen.info() != Eigen::Success || !IsFinite(inFragment.mInertia))
        return MakeError(EError::NonFinite, "FragmentBody: the fragment's inertia is not finite");
    Mat3 axes = eigen.eigenvectors();
    if (axes.determinant() < 0.0)
        axes.col(2) = -axes.col(2);
    const Vec3& c = inFragment.mCenterOfMass;

    // intent: two passes over the nodes instead of six (a piece can hold most of a prop's nodes: 1,567 in the
    // racing fence's, on the game's thread). Every sum keeps its own terms in node order, so each is bit for bit
    // what a pass of its own gave. The first: momentum, mass centre, angular momentum about c, hull points and
    // the nodes' world kinetic energy (the prop body's motion added to every node as to the body).
    const Mat3& rotation = prop_body.mTransform.mRotation;
    FragmentRigidBody result;
    plugin::ConvexBodySettings& body = result.mBody;
    body.mHullPoints.reserve(inFragment.mNodes.size());
    double nodal_mass = 0.0, world_nodal = 0.0;
    Vec3 momentum = Vec3::Zero(), mass_centre = Vec3::Zero();
    Vec3 angular = Vec3::Zero(); // the nodes' angular momentum about the body's centre of mass
    for (int node : inFragment.mNodes)
    {
        const auto n = static_cast<std::size_t>(node);
        nodal_mass += inMasses[n];
        momentum += inMasses[n] * inVelocities[n];
        mass_centre += inMasses[n] * inPositions[n];
        angular += inMasses[n] * (inPositions[n] - c).cross(inVelocities[n]);
        body.mHullPoints.push_back(axes.transpose() * (inPositions[n] - c));
        const Vec3 world_velocity = rotation * inVelocities[n] +
                                    prop_body.PointVelocity(prop_body.mTransform.ToWorld(inPositions[n]));
        world_nodal += 0.5 * inMasses[n] * world_velocity.squaredNorm();
    }
    if (!(nodal_mass > 0.0))
        return MakeError(EError::InvalidArgument, "FragmentBody: the fragment's nodes have no mass");
    mass_centre /= nodal_mass;
    // The second: the rigid spin about the nodes' mass centre (least squares under the lumped masses).
    Vec3 lumped_angular = Vec3::Zero();
    Mat3 lumped_inertia = Mat3::Zero();
    for (int node : inFragment.mNodes)
    {
        const auto n = static_cast<std::size_t>(node);
        const Vec3 r = inPositions[n] - mass_centre;
        lumped_angular += inMasses[n] * r.cross(inVelocities[n]);
        // m (|r|^2 I - r r^T), entry by entry: the matrix expression was not inlined (0.1 ms for a piece of
        // 1,500 nodes, on the game's thread when a prop breaks). The same products and sums in the same order,
        // so the bits are the expression's: |r|^2 * 1 on the diagonal, |r|^2 * 0 = +0 off it, minus r_i r_j.
        const double squared = r.squaredNorm();
        for (int col = 0; col < 3; ++col)
            for (int row = 0; row < 3; ++row)
                lumped_inertia(row, col) += inMasses[n] * (squared * (row == col ? 1.0 : 0.0) - r[row] * r[col]);
    }
    const Vec3 velocity = momentum / inFragment.mMass;
    const Vec3 spin = lumped_inertia.ldlt().solve(lumped_angular);
    if (!IsFinite(velocity) || !IsFinite(spin))
        return MakeError(EError::NonFinite, "FragmentBody: the nodes' velocities give no finite rigid motion");
    result.mAngularMomentumChange = (inFragment.mInertia * spin - angular).norm();

    // intent: to the world through the prop body's state
    body.mMass = inFragment.mMass;
    body.mPrincipalInertia = eigen.eigenvalues();
    body.mPosition = prop_body.mTransform.ToWorld(c);
    body.mOrientation = rotation * axes;
    body.mLinearVelocity = rotation * velocity + prop_body.PointVelocity(body.mPosition);
    body.mAngularVelocity =
        rotation * spin +
        (prop_body.mMotionType == plugin::EMotionType::Static ? Vec3::Zero() : prop_body.mAngularVelocity);
    result.mNodalKineticEnergy = world_nodal;
    result.mRigidKineticEnergy = 0.5 * body.mMass * body.mLinearVelocity.squaredNorm() +
                                 0.5 * body.mAngularVelocity.dot(body.WorldInertia() * body.mAngularVelocity);
    if (Status valid = plugin::ValidateConvexBodySettings(body); !valid)
        return valid.GetError();
    return result;
}

} // namespace crumple::props
