// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "TensorProductSum.h"

#include <crumple/base/Assert.h>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define CRUMPLE_FFD_WIDE_SUM 1
#endif

namespace crumple::ffd
{

Vec3 TensorProductSum(const Vec3* inFirst, std::ptrdiff_t inRow, std::ptrdiff_t inPlane, const CellWeights& inWeights)
{
    const std::array<double, 4>& wx = inWeights.mX;
    Vec3 sum = Vec3::Zero();
    for (std::ptrdiff_t c = 0; c < 4; ++c)
    {
        Vec3 plane = Vec3::Zero();
        for (std::ptrdiff_t b = 0; b < 4; ++b)
        {
            const Vec3* row = inFirst + c * inPlane + b * inRow;
            const Vec3 line = wx[0] * row[0] + wx[1] * row[1] + wx[2] * row[2] + wx[3] * row[3];
            plane += inWeights.mY[static_cast<std::size_t>(b)] * line;
        }
        sum += inWeights.mZ[static_cast<std::size_t>(c)] * plane;
    }
    return sum;
}

void PackCellControls(const Vec3* inFirst, std::ptrdiff_t inRow, std::ptrdiff_t inPlane, PackedCellControls& outPacked)
{
    for (std::ptrdiff_t c = 0; c < 4; ++c)
        for (std::ptrdiff_t b = 0; b < 4; ++b)
            for (std::ptrdiff_t a = 0; a < 4; ++a)
            {
                const Vec3& control = inFirst[c * inPlane + b * inRow + a];
                double* packed = outPacked.mControls[16 * c + 4 * b + a];
                packed[0] = control.x();
                packed[1] = control.y();
                packed[2] = control.z();
                packed[3] = 0.0;
            }
}

#ifdef CRUMPLE_FFD_WIDE_SUM

namespace
{

// intent: AVX without FMA (and the build's -ffp-contract=off): every product is rounded before its sum, as in
// the scalar sum. The controls are read four doubles at a time from inFirst: control (a, b, c) starts
// a inControl + b inRow + c inPlane doubles in (three apart in a lattice's Vec3s, four in a packed cell).
__attribute__((target("avx"))) Vec3 WideSum(const double* inFirst, std::ptrdiff_t inControl, std::ptrdiff_t inRow,
                                            std::ptrdiff_t inPlane, const CellWeights& inWeights)
{
    const __m256d w0 = _mm256_set1_pd(inWeights.mX[0]), w1 = _mm256_set1_pd(inWeights.mX[1]);
    const __m256d w2 = _mm256_set1_pd(inWeights.mX[2]), w3 = _mm256_set1_pd(inWeights.mX[3]);
    __m256d sum = _mm256_setzero_pd();
    for (std::ptrdiff_t c = 0; c < 4; ++c)
    {
        __m256d plane = _mm256_setzero_pd();
        for (std::ptrdiff_t b = 0; b < 4; ++b)
        {
            const double* row = inFirst + c * inPlane + b * inRow;
            __m256d line = _mm256_mul_pd(w0, _mm256_loadu_pd(row));
            line = _mm256_add_pd(line, _mm256_mul_pd(w1, _mm256_loadu_pd(row + inControl)));
            line = _mm256_add_pd(line, _mm256_mul_pd(w2, _mm256_loadu_pd(row + 2 * inControl)));
            line = _mm256_add_pd(line, _mm256_mul_pd(w3, _mm256_loadu_pd(row + 3 * inControl)));
            plane = _mm256_add_pd(plane, _mm256_mul_pd(_mm256_set1_pd(inWeights.mY[static_cast<std::size_t>(b)]), line));
        }
        sum = _mm256_add_pd(sum, _mm256_mul_pd(_mm256_set1_pd(inWeights.mZ[static_cast<std::size_t>(c)]), plane));
    }
    alignas(32) double lanes[4];
    _mm256_store_pd(lanes, sum);
    return Vec3(lanes[0], lanes[1], lanes[2]);
}

} // namespace

Vec3 WideTensorProductSum(const Vec3* inFirst, std::ptrdiff_t inRow, std::ptrdiff_t inPlane, const CellWeights& inWeights)
{
    return WideSum(inFirst->data(), 3, 3 * inRow, 3 * inPlane, inWeights);
}

Vec3 WidePackedTensorProductSum(const PackedCellControls& inPacked, const CellWeights& inWeights)
{
    return WideSum(inPacked.mControls[0], 4, 16, 64, inWeights);
}

bool HasWideTensorProductSum()
{
    // intent: asked once; the answer (the processor's and the OS's AVX support) cannot change in a process. The
    // explicit init makes it right even from a static constructor that runs before libgcc's own.
    static const bool sHasAvx = [] {
        __builtin_cpu_init();
        return __builtin_cpu_supports("avx") != 0;
    }();
    return sHasAvx;
}

#else

Vec3 WidePackedTensorProductSum(const PackedCellControls& inPacked, const CellWeights& inWeights)
{
    CRUMPLE_ASSERT(false, "WidePackedTensorProductSum: not built for this processor");
    return Vec3::Zero();
}

Vec3 WideTensorProductSum(const Vec3* inFirst, std::ptrdiff_t inRow, std::ptrdiff_t inPlane, const CellWeights& inWeights)
{
    CRUMPLE_ASSERT(false, "WideTensorProductSum: not built for this processor");
    return TensorProductSum(inFirst, inRow, inPlane, inWeights);
}

bool HasWideTensorProductSum()
{
    return false;
}

#endif

} // namespace crumple::ffd
