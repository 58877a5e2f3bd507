// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Math.h>
#include <crumple/ffd/CubicBSplineWeights.h>

#include <array>
#include <cstddef>

namespace crumple::ffd
{

/// The cubic B-spline weights of one point along the three lattice axes (CubicBSplineWeights of its t).
struct CellWeights
{
    std::array<double, 4> mX, mY, mZ;
};

/// The weights at local parameter inT of a cell (LatticeLocation::mT)
inline CellWeights CellWeightsAt(const Vec3& inT)
{
    return {CubicBSplineWeights(inT.x()), CubicBSplineWeights(inT.y()), CubicBSplineWeights(inT.z())};
}

/// The tensor-product sum over a cell's 4 x 4 x 4 controls, sum_c wz[c] sum_b wy[b] sum_a wx[a] P(a, b, c),
/// in the fixed order (c, b, a) that makes it bitwise reproducible: each line ((w0 P0 + w1 P1) + w2 P2) + w3 P3,
/// each plane and the sum accumulated from +0 one term at a time.
/// @param[in] inFirst   the cell's first control P(0, 0, 0)
/// @param[in] inRow     controls from P(a, b, c) to P(a, b + 1, c) (the lattice's x count)
/// @param[in] inPlane   controls from P(a, b, c) to P(a, b, c + 1) (its x count times its y count)
Vec3 TensorProductSum(const Vec3* inFirst, std::ptrdiff_t inRow, std::ptrdiff_t inPlane, const CellWeights& inWeights);

/// The same sum with x, y and z in three lanes of one 256-bit AVX register: the same operations in the same
/// order lane by lane, so bitwise the same result as TensorProductSum, about twice as fast (the dent's
/// per-vertex cost). Each control is read as four doubles, its own three and the next control's x (in lane 4,
/// discarded): the cell's last control P(3, 3, 3) must therefore not be the last element of its array.
/// Call only where HasWideTensorProductSum().
Vec3 WideTensorProductSum(const Vec3* inFirst, std::ptrdiff_t inRow, std::ptrdiff_t inPlane, const CellWeights& inWeights);

/// A cell's 4 x 4 x 4 controls copied for WidePackedTensorProductSum: P(a, b, c) at mControls[16 c + 4 b + a]
/// as (x, y, z, 0), each on its own 32-byte boundary. The vertices of a cell share its controls: copied once,
/// each vertex's 64 reads are aligned, where three packed doubles apart half of them straddle a cache line.
struct alignas(32) PackedCellControls
{
    double mControls[64][4];
};

/// Copies the cell whose first control is inFirst (strides as TensorProductSum's).
void PackCellControls(const Vec3* inFirst, std::ptrdiff_t inRow, std::ptrdiff_t inPlane, PackedCellControls& outPacked);

/// WideTensorProductSum over a packed cell: the same operations in the same order, so the same bits. Call only
/// where HasWideTensorProductSum().
Vec3 WidePackedTensorProductSum(const PackedCellControls& inPacked, const CellWeights& inWeights);

/// Whether this build and this processor run WideTensorProductSum (x86-64 with AVX, GCC or Clang). Constant
/// for the process.
bool HasWideTensorProductSum();

} // namespace crumple::ffd
