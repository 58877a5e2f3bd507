// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/ffd/FfdDeformer.h>

#include "CellSurfaceIndex.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>

namespace crumple::ffd
{

namespace
{

// A point in probe coordinates: across (side, third) and along (depth).
struct ProbePoint
{
    double mSide, mThird, mDepth;
};

// A polygon of at most 3 + 4 corners (a triangle clipped by a rectangle's four edges). Its corners past
// mCount are left uninitialised: zeroing them cost more than the clip of most triangles.
struct SmallPolygon
{
    std::array<ProbePoint, 8> mCorners;
    std::size_t mCount = 0;
};

// Sutherland-Hodgman: keeps the part of inPolygon where inCoordinate(p) * inSign <= inLimit * inSign.
SmallPolygon ClipPolygon(const SmallPolygon& inPolygon, double ProbePoint::*inCoordinate, double inLimit, double inSign)
{
    SmallPolygon out;
    for (std::size_t i = 0; i < inPolygon.mCount; ++i)
    {
        const ProbePoint& a = inPolygon.mCorners[i];
        const ProbePoint& b = inPolygon.mCorners[(i + 1) % inPolygon.mCount];
        const double da = inSign * (a.*inCoordinate - inLimit), db = inSign * (b.*inCoordinate - inLimit);
        if (da <= 0.0)
            out.mCorners[out.mCount++] = a;
        if ((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0))
        {
            const double t = da / (da - db);
            out.mCorners[out.mCount++] = {a.mSide + t * (b.mSide - a.mSide), a.mThird + t * (b.mThird - a.mThird),
                                          a.mDepth + t * (b.mDepth - a.mDepth)};
        }
    }
    return out;
}

// The running scan: every vertex and triangle handed to it is tested exactly as a scan over the whole mesh
// would test it, so the order and repetition in which cells hand them over change nothing.
class ProbeScan
{
public:
    ProbeScan(const SurfaceProbe& inProbe, std::span<const Vec3> inPositions, std::span<const Vec3> inRest,
              std::span<const std::array<std::uint32_t, 3>> inTriangles)
        : mProbe(inProbe), mPositions(inPositions), mRest(inRest), mTriangles(inTriangles)
    {
    }

    void Vertex(std::uint32_t inVertex)
    {
        const ProbePoint c = Project(mPositions[inVertex]);
        if (Outside(c) == 0)
            Inside(inVertex, c);
    }

    void Inside(std::uint32_t inVertex, const ProbePoint& inProjected)
    {
        mFront = std::min(mFront, inProjected.mDepth);
        mMoveInside = std::max(mMoveInside, mProbe.mDirection.dot(mPositions[inVertex] - mRest[inVertex]));
        mVertexInside = true;
    }

    void Triangle(std::uint32_t inTriangle)
    {
        const std::array<std::uint32_t, 3>& triangle = mTriangles[inTriangle];
        std::array<ProbePoint, 3> corners;
        std::array<std::uint8_t, 3> outside;
        for (std::size_t i = 0; i < 3; ++i)
        {
            corners[i] = Project(mPositions[triangle[i]]);
            outside[i] = Outside(corners[i]);
        }
        ClippedTriangle(triangle, corners, outside);
    }

    // Every vertex and every triangle in memory order, each vertex projected once: the pass a probe falls back
    // to when it would visit much of the mesh anyway.
    void Everything()
    {
        std::vector<ProbePoint> projected(mPositions.size());
        std::vector<std::uint8_t> outside(mPositions.size());
        for (std::uint32_t v = 0; v < mPositions.size(); ++v)
        {
            projected[v] = Project(mPositions[v]);
            outside[v] = Outside(projected[v]);
            if (outside[v] == 0)
                Inside(v, projected[v]);
        }
        for (const std::array<std::uint32_t, 3>& triangle : mTriangles)
            ClippedTriangle(triangle, {projected[triangle[0]], projected[triangle[1]], projected[triangle[2]]},
                            {outside[triangle[0]], outside[triangle[1]], outside[triangle[2]]});
    }

    void ClippedTriangle(const std::array<std::uint32_t, 3>& triangle, const std::array<ProbePoint, 3>& corners,
                         const std::array<std::uint8_t, 3>& outside)
    {
        // intent: wholly beyond one edge, or wholly inside (its vertices are scanned as vertices)
        if ((outside[0] & outside[1] & outside[2]) != 0 || (outside[0] | outside[1] | outside[2]) == 0)
            return;
        SmallPolygon polygon;
        std::copy(corners.begin(), corners.end(), polygon.mCorners.begin());
        polygon.mCount = 3;
        polygon = ClipPolygon(polygon, &ProbePoint::mSide, mProbe.mSideMin, -1.0);
        polygon = ClipPolygon(polygon, &ProbePoint::mSide, mProbe.mSideMax, 1.0);
        polygon = ClipPolygon(polygon, &ProbePoint::mThird, mProbe.mThirdMin, -1.0);
        polygon = ClipPolygon(polygon, &ProbePoint::mThird, mProbe.mThirdMax, 1.0);
        if (polygon.mCount == 0)
            return;
        // Depth is linear over the triangle: its least over the clipped part is at a corner of it.
        for (std::size_t i = 0; i < polygon.mCount; ++i)
            mFront = std::min(mFront, polygon.mCorners[i].mDepth);
        for (std::uint32_t v : triangle)
            mMoveAcross = std::max(mMoveAcross, mProbe.mDirection.dot(mPositions[v] - mRest[v]));
    }

    double GetFront() const { return mFront; }
    bool HasVertexInside() const { return mVertexInside; }
    double GetMoveInside() const { return mMoveInside; }

    SurfaceProbeResult Result() const { return {mFront, mVertexInside, mVertexInside ? mMoveInside : mMoveAcross}; }

private:
    ProbePoint Project(const Vec3& inPoint) const
    {
        return {mProbe.mSide.dot(inPoint), mProbe.mThird.dot(inPoint), mProbe.mDirection.dot(inPoint)};
    }
    // Bits 0-3: beyond the prism's low side, high side, low third, high third.
    std::uint8_t Outside(const ProbePoint& inPoint) const
    {
        return static_cast<std::uint8_t>((inPoint.mSide < mProbe.mSideMin ? 1 : 0) | (inPoint.mSide > mProbe.mSideMax ? 2 : 0) |
                                         (inPoint.mThird < mProbe.mThirdMin ? 4 : 0) | (inPoint.mThird > mProbe.mThirdMax ? 8 : 0));
    }

    const SurfaceProbe& mProbe;
    std::span<const Vec3> mPositions;
    std::span<const Vec3> mRest;
    std::span<const std::array<std::uint32_t, 3>> mTriangles;
    double mFront = std::numeric_limits<double>::infinity();
    bool mVertexInside = false;
    double mMoveInside = 0.0;
    double mMoveAcross = 0.0;
};

// Where a region's surface may be now: the points q + m, q in its rest box [mLow, mHigh] and m in the box
// [mMoveLow, mMoveHigh] of how far its points moved.
struct MovedBox
{
    Vec3 mLow, mHigh;
    Vec3 mMoveLow = Vec3::Zero(), mMoveHigh = Vec3::Zero();
};

// Range of inAxis.p over the moved box, widened by a hair far over the round-off of a point's projection.
std::array<double, 2> BoxRange(const Vec3& inAxis, const MovedBox& inBox)
{
    const Vec3 centre = 0.5 * (inBox.mLow + inBox.mHigh) + 0.5 * (inBox.mMoveLow + inBox.mMoveHigh);
    const Vec3 half = 0.5 * (inBox.mHigh - inBox.mLow) + 0.5 * (inBox.mMoveHigh - inBox.mMoveLow);
    const double margin = 1.0e-9 * (1.0 + centre.cwiseAbs().maxCoeff() + half.maxCoeff());
    const double middle = inAxis.dot(centre);
    const double extent = inAxis.cwiseAbs().dot(half) + margin;
    return {middle - extent, middle + extent};
}

// Whether any point of the moved box can lie in the probe's prism.
bool MeetsPrism(const SurfaceProbe& inProbe, const MovedBox& inBox)
{
    const std::array<double, 2> side = BoxRange(inProbe.mSide, inBox);
    const std::array<double, 2> third = BoxRange(inProbe.mThird, inBox);
    return !(side[1] < inProbe.mSideMin || side[0] > inProbe.mSideMax || third[1] < inProbe.mThirdMin ||
             third[0] > inProbe.mThirdMax);
}

// Whether every point of the moved box lies in the probe's prism (so each triangle in it lies wholly inside,
// and a scan skips it).
bool InsidePrism(const SurfaceProbe& inProbe, const MovedBox& inBox)
{
    const std::array<double, 2> side = BoxRange(inProbe.mSide, inBox);
    const std::array<double, 2> third = BoxRange(inProbe.mThird, inBox);
    return side[0] > inProbe.mSideMin && side[1] < inProbe.mSideMax && third[0] > inProbe.mThirdMin &&
           third[1] < inProbe.mThirdMax;
}

// A lower bound of d.p over the moved box.
double NearestAlong(const SurfaceProbe& inProbe, const MovedBox& inBox)
{
    return BoxRange(inProbe.mDirection, inBox)[0];
}

// An upper bound of d.m over the displacements m in [inLow, inHigh] (the most a vertex moved along the
// probe), widened by a hair for the round-off of a vertex's own d.(p - rest).
double MostMovedAlong(const SurfaceProbe& inProbe, const Vec3& inLow, const Vec3& inHigh)
{
    double most = 0.0, scale = 0.0;
    for (int k = 0; k < 3; ++k)
    {
        const double d = inProbe.mDirection[k];
        most += std::max(d * inLow[k], d * inHigh[k]);
        scale += std::abs(d) * std::max(std::abs(inLow[k]), std::abs(inHigh[k]));
    }
    return most + 1.0e-9 * scale;
}

} // namespace

SurfaceProbeResult FfdDeformer::ProbeSurface(const SurfaceProbe& inProbe) const
{
    const bool finite = IsFinite(inProbe.mDirection) && IsFinite(inProbe.mSide) && IsFinite(inProbe.mThird) &&
                        std::isfinite(inProbe.mSideMin) && std::isfinite(inProbe.mSideMax) &&
                        std::isfinite(inProbe.mThirdMin) && std::isfinite(inProbe.mThirdMax);
    if (!finite)
        return {};
    ProbeScan scan(inProbe, GetCurrentPositions(), mRestMesh.mPositions, mRestMesh.mTriangles);

    // intent: what lies in no zone never moved and has no cell: scan it all
    for (std::uint32_t v : mSurfaceIndex->LooseVertices())
        scan.Vertex(v);
    for (std::uint32_t t : mSurfaceIndex->LooseTriangles())
        scan.Triangle(t);

    // How far any vertex has moved from its rest position (the union of the cells' displacement boxes and
    // zero: a slice's rest reach box holds its triangles' corners from other cells and from no zone)
    const double most_moved = MostMovedAlong(inProbe, mMoveUnionLow, mMoveUnionHigh);

    // Where a cell's surface is now: its rest reach box (its vertices and its triangles' corners) moved by
    // any displacement of the vertices of the cell and of the cells holding those corners, and by none for
    // corners in no zone
    auto current_reach = [&](int inCell, const CellMotion& inOwn)
    {
        MovedBox reach{mSurfaceIndex->ReachLow(inCell), mSurfaceIndex->ReachHigh(inCell), inOwn.mMoveLow,
                       inOwn.mMoveHigh};
        for (int linked : mSurfaceIndex->LinkedCells(inCell))
        {
            // intent: a linked cell holds a corner of the cell's triangles, so a slot
            const CellMotion& other = *FindMotion(linked);
            reach.mMoveLow = reach.mMoveLow.cwiseMin(other.mMoveLow);
            reach.mMoveHigh = reach.mMoveHigh.cwiseMax(other.mMoveHigh);
        }
        if (mSurfaceIndex->HasLooseCorner(inCell))
        {
            reach.mMoveLow = reach.mMoveLow.cwiseMin(Vec3::Zero());
            reach.mMoveHigh = reach.mMoveHigh.cwiseMax(Vec3::Zero());
        }
        return reach;
    };

    // intent: zone by zone, slices across the lattice axis nearest the probe's direction, front slice first
    // (so the front is found early); a slice whose reach misses the prism even moved as far as any vertex is
    // skipped at once, and a cell whose surface, where it is now, misses it too
    std::size_t visited = 0;
    const std::size_t budget = (mPositions.size() + mRestMesh.mTriangles.size()) / 4;
    for (std::size_t z = 0; z < mZones.size(); ++z)
    {
        const FfdLattice& zone = mZones[z];
        const std::array<int, 3>& cells = zone.GetCellCount();
        const Vec3 along = zone.GetSettings().mAxes.transpose() * inProbe.mDirection;
        Eigen::Index axis = 0;
        along.cwiseAbs().maxCoeff(&axis);
        const bool forward = along[axis] >= 0.0;
        const std::array<int, 2> others{axis == 0 ? 1 : 0, axis == 2 ? 1 : 2};
        const int offset = mCellOffset[z];
        const SliceReach& slices = mSlices[z];
        std::array<int, 3> ijk{};
        for (int s = 0; s < cells[static_cast<std::size_t>(axis)]; ++s)
        {
            const int slice = forward ? s : cells[static_cast<std::size_t>(axis)] - 1 - s;
            ijk[static_cast<std::size_t>(axis)] = slice;
            const MovedBox slice_box{
                slices.mLow[static_cast<std::size_t>(axis)][static_cast<std::size_t>(slice)],
                slices.mHigh[static_cast<std::size_t>(axis)][static_cast<std::size_t>(slice)], mMoveUnionLow,
                mMoveUnionHigh};
            if (!(slice_box.mLow.x() <= slice_box.mHigh.x()) || !MeetsPrism(inProbe, slice_box))
                continue;
            // intent: a slice wholly behind the front adds nothing once a vertex is inside, unless a vertex
            // moved along the probe further than any inside so far: the cells' test below on the slice's box
            // moved by the union of every cell's moves (most slices behind the struck face of a car go at
            // once)
            if (scan.HasVertexInside() && NearestAlong(inProbe, slice_box) > scan.GetFront() &&
                !(most_moved > scan.GetMoveInside()))
                continue;
            for (int b = 0; b < cells[static_cast<std::size_t>(others[1])]; ++b)
                for (int a = 0; a < cells[static_cast<std::size_t>(others[0])]; ++a)
                {
                    ijk[static_cast<std::size_t>(others[0])] = a;
                    ijk[static_cast<std::size_t>(others[1])] = b;
                    const int cell = offset + zone.CellIndex(ijk);
                    const CellMotion* motion = FindMotion(cell);
                    if (motion == nullptr)
                        continue; // no vertex in the cell
                    const MovedBox reach = current_reach(cell, *motion);
                    if (!MeetsPrism(inProbe, reach))
                        continue;
                    // intent: a cell wholly behind the front adds nothing once a vertex is inside, except a
                    // vertex that moved along the probe further than any inside so far
                    const bool behind =
                        NearestAlong(inProbe, reach) > scan.GetFront() && scan.HasVertexInside();
                    if (behind && !(MostMovedAlong(inProbe, motion->mMoveLow, motion->mMoveHigh) >
                                    scan.GetMoveInside()))
                        continue;
                    const auto local = static_cast<std::size_t>(cell - offset);
                    for (std::uint32_t i = mCellStart[z][local]; i < mCellStart[z][local + 1]; ++i)
                        scan.Vertex(mCellVertices[z][i]);
                    visited += mCellStart[z][local + 1] - mCellStart[z][local];
                    if (!behind && !InsidePrism(inProbe, reach))
                    {
                        for (std::uint32_t triangle : mSurfaceIndex->TrianglesOf(cell))
                            scan.Triangle(triangle);
                        visited += mSurfaceIndex->TrianglesOf(cell).size();
                    }
                    // intent: a probe that visits a good part of the mesh cell by cell (a wide one over a
                    // body dented deep) is cheaper as one pass in memory order: start over that way (same
                    // answer; cell order costs several times more per item on an imported mesh)
                    if (visited > budget)
                    {
                        ProbeScan everything(inProbe, GetCurrentPositions(), mRestMesh.mPositions, mRestMesh.mTriangles);
                        everything.Everything();
                        return everything.Result();
                    }
                }
        }
    }
    return scan.Result();
}

} // namespace crumple::ffd
