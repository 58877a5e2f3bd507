// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "StruckFront.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>
#include <utility>
#include <vector>

namespace crumple::plugin
{

double StruckFront::At(double inSide, double inThird) const
{
    if (mDepth.empty())
        return 0.0;
    const double u = std::clamp((inSide - mSideOrigin) / mBin, 0.0, static_cast<double>(mSideCount - 1));
    const double v = std::clamp((inThird - mThirdOrigin) / mBin, 0.0, static_cast<double>(mThirdCount - 1));
    const int i = std::min(static_cast<int>(u), std::max(mSideCount - 2, 0));
    const int j = std::min(static_cast<int>(v), std::max(mThirdCount - 2, 0));
    const double fu = u - i, fv = v - j;
    const int i1 = std::min(i + 1, mSideCount - 1), j1 = std::min(j + 1, mThirdCount - 1);
    auto at = [&](int inI, int inJ) { return mDepth[static_cast<std::size_t>(inJ) * static_cast<std::size_t>(mSideCount) + static_cast<std::size_t>(inI)]; };
    return (1.0 - fv) * ((1.0 - fu) * at(i, j) + fu * at(i1, j)) + fv * ((1.0 - fu) * at(i, j1) + fu * at(i1, j1));
}

StruckFront MeasureStruckFront(const CrushPlan& inPlan, const CrossRect& inRegion, const ffd::FfdDeformer& inDeformer,
                               std::span<const std::uint32_t> inLargeTriangles, double inSlope, SurfaceBins* outSurface)
{
    StruckFront grid;
    const double depth = inPlan.mDepth;
    const double margin = inPlan.mFlatLayer + inPlan.mRamp + inPlan.mSpacing;
    const double side0 = inRegion.mSideMin - margin, side1 = inRegion.mSideMax + margin;
    const double third0 = inRegion.mThirdMin - margin, third1 = inRegion.mThirdMax + margin;
    constexpr int cMaxBins = 256; // per axis: a bound on the grid's memory and on its sweeps
    const double bin = std::max({inPlan.mSpacing, (side1 - side0) / (cMaxBins - 1), (third1 - third0) / (cMaxBins - 1)});
    if (!(bin > 0.0) || !std::isfinite(bin))
        return grid;
    const int ns = static_cast<int>(std::ceil((side1 - side0) / bin)) + 1;
    const int nt = static_cast<int>(std::ceil((third1 - third0) / bin)) + 1;
    const std::size_t count = static_cast<std::size_t>(ns) * static_cast<std::size_t>(nt);
    std::vector<double> front(count, depth);
    std::vector<std::uint8_t> met(count, 0);
    auto index = [&](int inI, int inJ) { return static_cast<std::size_t>(inJ) * static_cast<std::size_t>(ns) + static_cast<std::size_t>(inI); };

    // The positions dents work on (GetCurrentPositions: a deferred dent is ahead of what the game sees).
    // Every vertex marks the bin its column falls in as met by the body (a column met only behind the slab,
    // above a bonnet say, must hold the slab's depth, not its neighbours') and lowers it to its own depth.
    const std::vector<Vec3>& positions = inDeformer.GetCurrentPositions();
    const double inverse = 1.0 / bin;
    // intent: the plan's axes and front in locals, and the grids by raw pointer: the stores into the grids
    // may alias the plan's doubles as far as the compiler knows, which reloaded all of them per vertex (the
    // same operations, so the same bits)
    const Vec3 side_axis = inPlan.mSide, third_axis = inPlan.mThird, direction = inPlan.mDirection;
    const double plan_front = inPlan.mFront;
    double* const front_bins = front.data();
    std::uint8_t* const met_bins = met.data();
    const double side_count = ns, third_count = nt;
    // Neighbouring vertices mostly share a bin: their least depth is kept in a register while they do, and
    // written when the bin changes (a minimum, so in any grouping and order the same value), rather than each
    // vertex waiting on the store of the one before.
    auto scan = [&](std::span<const std::uint32_t> inVertices) {
        constexpr std::size_t cNoBin = std::numeric_limits<std::size_t>::max();
        std::size_t run_bin = cNoBin;
        double run_least = 0.0;
        for (std::uint32_t v : inVertices)
        {
            const Vec3& p = positions[v];
            // Bin coordinates plus a half, so that truncation rounds to the nearest centre.
            const double u = (side_axis.dot(p) - side0) * inverse + 0.5;
            if (!(u >= 0.0 && u < side_count))
                continue;
            const double w = (third_axis.dot(p) - third0) * inverse + 0.5;
            if (!(w >= 0.0 && w < third_count))
                continue;
            const std::size_t b = index(static_cast<int>(u), static_cast<int>(w));
            const double depth_here = std::max(direction.dot(p) - plan_front, 0.0);
            if (b == run_bin)
            {
                run_least = std::min(run_least, depth_here);
                continue;
            }
            if (run_bin != cNoBin)
                front_bins[run_bin] = std::min(front_bins[run_bin], run_least);
            met_bins[b] = 1;
            run_bin = b;
            run_least = depth_here;
        }
        if (run_bin != cNoBin)
            front_bins[run_bin] = std::min(front_bins[run_bin], run_least);
    };
    // intent: the vertices cell by cell, the foremost cells first (FfdDeformer::ForEachVertexGroup), skipping
    // a cell that cannot change the grid, so a plan does not read the whole body: a cell whose box lies beside
    // the grid holds no vertex in it; a cell whose box's columns are all met already, none deeper than the
    // nearest its vertices can be, would only mark them met again and leave their depths (bins are a minimum
    // and a flag, so neither the order nor the skip changes a bit). Most of a car's cells go at once: its
    // sides, top and bottom stand behind the struck front in the same columns.
    inDeformer.ForEachVertexGroup(direction, [&](const ffd::VertexGroup& inGroup) {
        if (!inGroup.mBounded)
        {
            scan(inGroup.mVertices);
            return;
        }
        // [least, most] of axis.p over the box moved by its bound, widened by a hair far over the rounding of a
        // vertex's own dot product (so no vertex's computed value falls outside)
        const Vec3 centre = 0.5 * (inGroup.mLow + inGroup.mHigh), half = 0.5 * (inGroup.mHigh - inGroup.mLow);
        const double widening = inGroup.mMoved + 1.0e-9 * (1.0 + centre.cwiseAbs().maxCoeff() + half.maxCoeff() + inGroup.mMoved);
        auto reach = [&](const Vec3& inAxis) {
            const double middle = inAxis.dot(centre), extent = inAxis.cwiseAbs().dot(half) + widening;
            return std::array<double, 2>{middle - extent, middle + extent};
        };
        const std::array<double, 2> side = reach(side_axis), third = reach(third_axis);
        // The same operations as a vertex's, which are monotone: its bin lies in the box's range.
        const double u0 = (side[0] - side0) * inverse + 0.5, u1 = (side[1] - side0) * inverse + 0.5;
        const double w0 = (third[0] - third0) * inverse + 0.5, w1 = (third[1] - third0) * inverse + 0.5;
        if (!(u1 >= 0.0 && u0 < side_count && w1 >= 0.0 && w0 < third_count))
            return; // beside the grid
        // A vertex's depth is at least this (a bin at or above it keeps its value).
        const double nearest = reach(direction)[0] - plan_front;
        const int i0 = static_cast<int>(std::max(u0, 0.0)), i1 = static_cast<int>(std::min(u1, side_count - 1.0));
        const int j0 = static_cast<int>(std::max(w0, 0.0)), j1 = static_cast<int>(std::min(w1, third_count - 1.0));
        for (int j = j0; j <= j1; ++j)
            for (int i = i0; i <= i1; ++i)
                if (met_bins[index(i, j)] == 0 || front_bins[index(i, j)] > nearest)
                {
                    scan(inGroup.mVertices);
                    return;
                }
    });
    // A triangle larger than half a bin can hold a bin centre none of its vertices stands for: its depth
    // there, where it reaches into the slab.
    const std::vector<std::array<std::uint32_t, 3>>& triangles = inDeformer.GetRestMesh().mTriangles;
    for (std::uint32_t triangle : inLargeTriangles)
    {
        const std::array<std::uint32_t, 3>& t = triangles[triangle];
        std::array<double, 3> x{}, y{}, z{};
        for (std::size_t k = 0; k < 3; ++k)
            z[k] = inPlan.mDirection.dot(positions[t[k]]) - inPlan.mFront;
        if (std::min({z[0], z[1], z[2]}) >= depth)
            continue;
        for (std::size_t k = 0; k < 3; ++k)
        {
            x[k] = inPlan.mSide.dot(positions[t[k]]);
            y[k] = inPlan.mThird.dot(positions[t[k]]);
        }
        const double area = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
        if (!(std::abs(area) > 0.0))
            continue; // seen edge-on: its vertices stand for it
        const int i0 = std::max(static_cast<int>(std::ceil((std::min({x[0], x[1], x[2]}) - side0) * inverse)), 0);
        const int i1 = std::min(static_cast<int>(std::floor((std::max({x[0], x[1], x[2]}) - side0) * inverse)), ns - 1);
        const int j0 = std::max(static_cast<int>(std::ceil((std::min({y[0], y[1], y[2]}) - third0) * inverse)), 0);
        const int j1 = std::min(static_cast<int>(std::floor((std::max({y[0], y[1], y[2]}) - third0) * inverse)), nt - 1);
        for (int j = j0; j <= j1; ++j)
            for (int i = i0; i <= i1; ++i)
            {
                const double px = side0 + i * bin, py = third0 + j * bin;
                // Barycentric weights of the bin centre in the projected triangle.
                const double wb = ((px - x[0]) * (y[2] - y[0]) - (py - y[0]) * (x[2] - x[0])) / area;
                const double wc = ((x[1] - x[0]) * (py - y[0]) - (y[1] - y[0]) * (px - x[0])) / area;
                const double wa = 1.0 - wb - wc;
                if (wa < 0.0 || wb < 0.0 || wc < 0.0)
                    continue;
                const std::size_t k = index(i, j);
                met[k] = 1;
                front[k] = std::min(front[k], std::max(wa * z[0] + wb * z[1] + wc * z[2], 0.0));
            }
    }

    if (outSurface != nullptr)
    {
        outSurface->mSideOrigin = side0;
        outSurface->mThirdOrigin = third0;
        outSurface->mBin = bin;
        outSurface->mSideCount = ns;
        outSurface->mThirdCount = nt;
        outSurface->mDepth.assign(count, std::numeric_limits<double>::infinity());
        for (std::size_t k = 0; k < count; ++k)
            if (met[k] != 0)
                outSurface->mDepth[k] = front[k];
    }
    // Bins the body never meets take the least depth of their met neighbours, ring by ring.
    bool any = false;
    for (std::uint8_t m : met)
        any = any || m != 0;
    if (!any)
        return grid;
    // intent: layer by layer from the met bins outward, each bin visited once (not a pass over the whole grid
    // per ring: a car's front grid has about ten rings beside the body, the margin over the bin): a layer's
    // bins take the least depth of their neighbours met in earlier layers, as a ring did, and join the met ones
    // together. mark: 0 unmet, 1 met, 2 in the next layer.
    std::vector<std::uint8_t>& mark = met;
    struct Bin
    {
        int mI, mJ;
    };
    std::vector<Bin> layer, next_layer;
    layer.reserve(count);
    next_layer.reserve(count);
    // intent: the 3 x 3 bins around (i, j) within the grid, the bin itself included (it is never met while
    // asked about), by index; the range is clipped once instead of each neighbour being checked
    auto around = [&](int inI, int inJ, auto&& inVisit) {
        const int i0 = std::max(inI - 1, 0), i1 = std::min(inI + 1, ns - 1);
        const int j0 = std::max(inJ - 1, 0), j1 = std::min(inJ + 1, nt - 1);
        for (int jj = j0; jj <= j1; ++jj)
            for (int ii = i0; ii <= i1; ++ii)
                inVisit(ii, jj, index(ii, jj));
    };
    auto queue_unmet_neighbours = [&](int inI, int inJ) {
        around(inI, inJ, [&](int inII, int inJJ, std::size_t inK) {
            if (mark[inK] == 0)
            {
                mark[inK] = 2;
                next_layer.push_back({inII, inJJ});
            }
        });
    };
    for (int j = 0; j < nt; ++j)
        for (int i = 0; i < ns; ++i)
            if (mark[index(i, j)] == 1)
                queue_unmet_neighbours(i, j);
    while (!next_layer.empty())
    {
        layer.swap(next_layer);
        next_layer.clear();
        for (const Bin& b : layer)
        {
            double least = std::numeric_limits<double>::infinity();
            around(b.mI, b.mJ, [&](int, int, std::size_t inK) {
                if (mark[inK] == 1)
                    least = std::min(least, front[inK]);
            });
            front[index(b.mI, b.mJ)] = least; // read by no other bin of this layer: they read met ones only
        }
        for (const Bin& b : layer)
            mark[index(b.mI, b.mJ)] = 1;
        for (const Bin& b : layer)
            queue_unmet_neighbours(b.mI, b.mJ);
    }
    // Chamfer sweeps: no bin deeper than a neighbour's depth plus the slope times their distance.
    const double straight = inSlope * bin, diagonal = inSlope * bin * std::numbers::sqrt2;
    // intent: each sweep row by row, first from the row it follows (independent bins, so the loop runs wide),
    // then along the row from the bin before: a bin ends as the least of itself and the same four relaxed
    // neighbours as one bin at a time gives (a minimum is exact in any order)
    auto sweep_row = [&](double* ioRow, const double* inFrom, bool inForward) {
        const int last = ns - 1;
        for (int i = 0; i < ns; ++i)
        {
            double least = std::min(ioRow[i], inFrom[i] + straight);
            if (i > 0)
                least = std::min(least, inFrom[i - 1] + diagonal);
            if (i < last)
                least = std::min(least, inFrom[i + 1] + diagonal);
            ioRow[i] = least;
        }
        if (inForward)
            for (int i = 1; i < ns; ++i)
                ioRow[i] = std::min(ioRow[i], ioRow[i - 1] + straight);
        else
            for (int i = last - 1; i >= 0; --i)
                ioRow[i] = std::min(ioRow[i], ioRow[i + 1] + straight);
    };
    double* const bins = front.data();
    for (int i = 1; i < ns; ++i)
        bins[i] = std::min(bins[i], bins[i - 1] + straight);
    for (int j = 1; j < nt; ++j)
        sweep_row(bins + index(0, j), bins + index(0, j - 1), true);
    for (int i = ns - 2; i >= 0; --i)
        bins[index(i, nt - 1)] = std::min(bins[index(i, nt - 1)], bins[index(i + 1, nt - 1)] + straight);
    for (int j = nt - 2; j >= 0; --j)
        sweep_row(bins + index(0, j), bins + index(0, j + 1), false);
    bool flat = true;
    for (double f : front)
        flat = flat && f == 0.0;
    if (flat)
        return grid;
    grid.mSideOrigin = side0;
    grid.mThirdOrigin = third0;
    grid.mBin = bin;
    grid.mSlope = inSlope;
    grid.mSideCount = ns;
    grid.mThirdCount = nt;
    grid.mDepth = std::move(front);
    return grid;
}

double ProfileCrushDepth(const CrushPlan& inPlan, const DamageMaterial& inMaterial, double inPrevious, double inEnergy,
                         double inFlatDepth)
{
    constexpr int cStations = 32;
    const StruckFront& grid = inPlan.mStruckFront;
    const double width = inPlan.mSideMax - inPlan.mSideMin, height = inPlan.mThirdMax - inPlan.mThirdMin;
    const int rows = std::clamp(static_cast<int>(std::ceil(height / grid.mBin)), 1, 256);
    std::array<double, cStations> fronts{};
    double deepest = 0.0;
    for (int s = 0; s < cStations; ++s)
    {
        const double side = inPlan.mSideMin + (s + 0.5) * width / cStations;
        double least = std::numeric_limits<double>::infinity();
        for (int r = 0; r < rows; ++r)
            least = std::min(least, grid.At(side, inPlan.mThirdMin + (r + 0.5) * height / rows));
        fronts[static_cast<std::size_t>(s)] = least;
        deepest = std::max(deepest, least);
    }
    const double station = width / cStations;
    const double g = inPrevious > 0.0 ? 0.0 : inMaterial.mCrushG * width;
    auto energy = [&](double inDepth) {
        double e = g;
        for (double f : fronts)
        {
            const double c = inDepth - f;
            if (c > 0.0)
                e += station * (inMaterial.mCrushA * c + inMaterial.mCrushB * (inPrevious * c + 0.5 * c * c));
        }
        return e;
    };
    double low = inFlatDepth, high = inFlatDepth + deepest;
    for (int i = 0; i < 64 && high - low > 1.0e-12 * (1.0 + high); ++i)
    {
        const double middle = 0.5 * (low + high);
        (energy(middle) < inEnergy ? low : high) = middle;
    }
    return high;
}

} // namespace crumple::plugin
