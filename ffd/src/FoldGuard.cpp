// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/ffd/FoldGuard.h>

#include "AscendingIndexSet.h"

#include <algorithm>
#include <array>
#include <cstdint>

namespace crumple::ffd
{

namespace
{

// Sweeps over one line before the strict fallback. A head-on meeting next to a chain of pushers converges
// geometrically (each pass halves the overlap), so a few passes settle every case seen in practice.
constexpr int cMaxPasses = 16;

// Gap added above the bound when a control is moved, as a fraction of the spacing.
constexpr double cSlack = 1.0e-9;

// One lattice line along an axis: positions p (lattice-frame component a of the displacement after the
// dent, m) and q (the same before it) of its controls at lattice indices k (consecutive on a full line;
// with gaps where controls that move no vertex were left out). Resolves every violating pair; returns true
// if p changed.
class LineResolver
{
public:
    LineResolver(std::span<double> ioP, std::span<const double> inQ, std::span<const double> inK, double inSpacing,
                 double inMinSpacing)
        : mP(ioP), mQ(inQ), mK(inK), mSpacing(inSpacing), mMinGap(inMinSpacing * inSpacing)
    {
    }

    // Deformed gap minus the bound: X_{j+1} - X_j - m h with X_j = k_j h + p_j.
    bool Violates(std::size_t inJ) const { return Rest(inJ) + (mP[inJ + 1] - mP[inJ]) < mMinGap; }
    bool AnyViolation() const
    {
        for (std::size_t j = 0; j + 1 < mP.size(); ++j)
            if (Violates(j))
                return true;
        return false;
    }
    // Moved toward higher / lower index during this dent (guard moves included).
    bool MovedUp(std::size_t inJ) const { return mP[inJ] > mQ[inJ]; }
    bool MovedDown(std::size_t inJ) const { return mP[inJ] < mQ[inJ]; }

    void Resolve()
    {
        // intent: sweep in a fixed order until the line is clean or the pass bound is hit
        for (int pass = 0; pass < cMaxPasses && AnyViolation(); ++pass)
        {
            ForwardSweep();
            BackwardSweep();
            HeadOnSweep();
        }
        // intent: the strict fallback; after it sets j+1, later steps touch only j+2 onward
        for (std::size_t j = 0; j + 1 < mP.size(); ++j)
            if (Violates(j))
                mP[j + 1] = mP[j] + Target(j);
    }

private:
    // Rest gap of pair j, and the p_{j+1} - p_j that puts it on the bound (plus slack).
    double Rest(std::size_t inJ) const { return (mK[inJ + 1] - mK[inJ]) * mSpacing; }
    double Target(std::size_t inJ) const { return mMinGap - Rest(inJ) + cSlack * mSpacing; }
    // Pushes toward higher index: j+1 yields unless it pushes back (a pair where neither moved toward the
    // other can only violate when the state before was not ordered; j+1 yields then too).
    void ForwardSweep()
    {
        for (std::size_t j = 0; j + 1 < mP.size(); ++j)
            if (Violates(j) && !MovedDown(j + 1))
                mP[j + 1] = mP[j] + Target(j);
    }
    // Pushes toward lower index: j yields, cascading down the line.
    void BackwardSweep()
    {
        for (std::size_t j = mP.size() - 1; j-- > 0;)
            if (Violates(j) && MovedDown(j + 1) && !MovedUp(j))
                mP[j] = mP[j + 1] - Target(j);
    }
    // Both moved into each other: they meet around the midpoint of their wanted positions.
    void HeadOnSweep()
    {
        for (std::size_t j = 0; j + 1 < mP.size(); ++j)
            if (Violates(j) && MovedDown(j + 1) && MovedUp(j))
            {
                const double mid = 0.5 * (mP[j] + mP[j + 1]);
                mP[j] = mid - 0.5 * Target(j);
                mP[j + 1] = mid + 0.5 * Target(j);
            }
    }

    std::span<double> mP;
    std::span<const double> mQ;
    std::span<const double> mK;
    double mSpacing;
    double mMinGap;
};

} // namespace

std::vector<int> FoldGuard(const FfdLattice& inLattice, std::span<const Vec3> inBefore, std::span<Vec3> ioAfter,
                           std::span<const int> inChanged, double inMinSpacing, std::span<const std::uint8_t> inMoves)
{
    std::vector<int> moved;
    if (!(inMinSpacing > 0.0) || inChanged.empty())
        return moved;
    const std::array<int, 3>& n = inLattice.GetSettings().mControlCount;
    const Mat3& axes = inLattice.GetSettings().mAxes;
    const std::array<int, 3> stride{{1, n[0], n[0] * n[1]}};

    std::vector<std::uint32_t> lines;
    // intent: each axis's lines once and ascending, from one bit per control (no sort of the changed list)
    std::vector<std::uint64_t> line_bits((inLattice.GetControlDisplacements().size() + 63) / 64, 0);
    std::vector<double> p;
    std::vector<double> p_wanted;
    std::vector<double> q;
    std::vector<double> k;
    std::vector<std::size_t> members;
    // intent: each changed control's offset from the first control of its line along each axis (a, b n0,
    // c n0 n1), with two divisions per control instead of two per control and axis
    std::vector<std::array<int, 3>> offsets(inChanged.size());
    for (std::size_t i = 0; i < inChanged.size(); ++i)
    {
        const int c = inChanged[i] / stride[2], rest = inChanged[i] - c * stride[2];
        const int b = rest / n[0];
        offsets[i] = {rest - b * n[0], b * stride[1], c * stride[2]};
    }
    for (int axis = 0; axis < 3; ++axis)
    {
        // intent: the lines along this axis through a changed control, named by their first control
        lines.clear();
        AscendingIndexSet line_set(line_bits);
        for (std::size_t i = 0; i < inChanged.size(); ++i)
            line_set.Insert(static_cast<std::uint32_t>(inChanged[i] - offsets[i][static_cast<std::size_t>(axis)]));
        line_set.TakeAscending(lines);

        const Vec3 direction = axes.col(axis);
        const double spacing = inLattice.GetSpacing()[axis];
        const auto count = static_cast<std::size_t>(n[static_cast<std::size_t>(axis)]);
        const auto step = static_cast<std::size_t>(stride[static_cast<std::size_t>(axis)]);
        for (std::uint32_t line : lines)
        {
            // intent: project the line on the axis (lattice frame) and skip it cheaply when it is clean
            // Controls that move no vertex are left out of the line (they hold no surface to fold).
            members.clear();
            for (std::size_t j = 0; j < count; ++j)
            {
                const std::size_t control = static_cast<std::size_t>(line) + j * step;
                if (inMoves.empty() || inMoves[control] != 0)
                    members.push_back(j);
            }
            p.resize(members.size());
            q.resize(members.size());
            k.resize(members.size());
            for (std::size_t m = 0; m < members.size(); ++m)
            {
                p[m] = direction.dot(ioAfter[static_cast<std::size_t>(line) + members[m] * step]);
                k[m] = static_cast<double>(members[m]);
            }
            LineResolver resolver(p, q, k, spacing, inMinSpacing);
            if (!resolver.AnyViolation())
                continue;
            // intent: the positions before the dent only for a line that needs resolving (most are clean)
            for (std::size_t m = 0; m < members.size(); ++m)
                q[m] = direction.dot(inBefore[static_cast<std::size_t>(line) + members[m] * step]);
            p_wanted = p;
            resolver.Resolve();

            // intent: move each yielding control along the axis only, by what the sweeps changed
            for (std::size_t m = 0; m < members.size(); ++m)
                if (p[m] != p_wanted[m])
                {
                    const std::size_t control = static_cast<std::size_t>(line) + members[m] * step;
                    ioAfter[control] += (p[m] - p_wanted[m]) * direction;
                    moved.push_back(static_cast<int>(control));
                }
        }
    }
    std::sort(moved.begin(), moved.end());
    moved.erase(std::unique(moved.begin(), moved.end()), moved.end());
    return moved;
}

} // namespace crumple::ffd
