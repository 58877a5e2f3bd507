// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/PolarRotation.h>

#include <cmath>

namespace crumple::fem
{

// The polar rotation maximises f(R) = tr(R^T F) over rotations. With R <- R exp([w]) and B = R^T F,
//   f = tr(B) + g . w - w^T H w / 2 + O(|w|^3),
//   g = (B21 - B12, B02 - B20, B10 - B01),  H = tr(B) I - sym(B).
// Near the maximum H is positive definite and the Newton step w = H^-1 g converges quadratically. Where it is
// not (far from the answer, inverted elements) the step of Mueller et al. 2016, w = g / (|tr B| + eps), is
// used: it always moves uphill. The iterate is a unit quaternion, so the result is a rotation whatever
// happens.
Quat PolarRotation(const Mat3& inF, const Quat& inWarmStart, int inMaxIterations)
{
    Mat3 rotation;
    return PolarRotation(inF, inWarmStart, rotation, inMaxIterations);
}

Quat PolarRotation(const Mat3& inF, const Quat& inWarmStart, Mat3& outRotation, int inMaxIterations)
{
    // Converged when the update angle is below this (rad); the corotated strain sym(R^T F) - I is insensitive
    // to a rotation error to first order, so this is far below anything a force can see.
    constexpr double cAngleTolerance = 1.0e-12;
    // A Newton step below this angle (rad) is the last one: its remaining error is of order its square.
    constexpr double cNewtonFinish = 1.0e-6;
    // Keeps the fallback step finite when F is (near) zero.
    constexpr double cCurvatureFloor = 1.0e-9;

    Quat q = inWarmStart.normalized();
    // intent: the matrix of q as it stands; false once q moved past the last one computed
    bool matrix_current = false;
    for (int iteration = 0; iteration < inMaxIterations; ++iteration)
    {
        // Gradient and Hessian of tr(R^T F) in the local frame of the current iterate.
        outRotation = q.toRotationMatrix();
        matrix_current = true;
        const Mat3 b = outRotation.transpose() * inF;
        const Vec3 g(b(2, 1) - b(1, 2), b(0, 2) - b(2, 0), b(1, 0) - b(0, 1));
        const double trace = b(0, 0) + b(1, 1) + b(2, 2);
        const double h00 = trace - b(0, 0), h11 = trace - b(1, 1), h22 = trace - b(2, 2);
        const double h01 = -0.5 * (b(0, 1) + b(1, 0)), h02 = -0.5 * (b(0, 2) + b(2, 0)),
                     h12 = -0.5 * (b(1, 2) + b(2, 1));

        // Newton step where H is positive definite (Sylvester's criterion, solved by its adjugate), the
        // always-uphill step otherwise.
        const double c00 = h11 * h22 - h12 * h12, c01 = h02 * h12 - h01 * h22, c02 = h01 * h12 - h02 * h11;
        const double c11 = h00 * h22 - h02 * h02, c12 = h01 * h02 - h00 * h12, c22 = h00 * h11 - h01 * h01;
        const double det = h00 * c00 + h01 * c01 + h02 * c02;
        Vec3 omega;
        const bool newton = h00 > 0.0 && c22 > 0.0 && det > 0.0;
        if (newton)
            omega = Vec3(c00 * g[0] + c01 * g[1] + c02 * g[2], c01 * g[0] + c11 * g[1] + c12 * g[2],
                         c02 * g[0] + c12 * g[1] + c22 * g[2]) /
                    det;
        else
            omega = g / (std::abs(trace) + cCurvatureFloor);
        const double angle = omega.norm();
        if (!(angle > cAngleTolerance))
            break; // converged (or a non-finite F, which the callers refuse before it gets here)

        // Rotate by the Cayley-like quaternion (1, omega / 2), normalised: the rotation exp([omega]) up to
        // O(|omega|^3), which keeps Newton's quadratic convergence without trigonometry.
        q = q * Quat(1.0, 0.5 * omega[0], 0.5 * omega[1], 0.5 * omega[2]);
        q.normalize();
        matrix_current = false;

        // A Newton step this small leaves an error of order angle^2: done without another evaluation.
        if (newton && angle < cNewtonFinish)
            break;
    }
    if (!matrix_current)
        outRotation = q.toRotationMatrix();
    return q;
}

} // namespace crumple::fem
