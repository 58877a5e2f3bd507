// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/Assert.h>
#include <crumple/ffd/BoundingBox.h>
#include <crumple/ffd/FfdDeformer.h>
#include <crumple/ffd/OneSidedControls.h>
#include <crumple/ffd/FoldGuard.h>

#include "AscendingIndexSet.h"
#include "CellSurfaceIndex.h"
#include "TensorProductSum.h"
#include "ZonePoints.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <iterator>
#include <limits>
#include <string>

namespace crumple::ffd
{

namespace
{

// Per-vertex work is split over the host's workers in pieces of at least this many items: below it the
// hand-off costs more than the work (a vertex costs about 0.1-0.3 us).
constexpr std::size_t cMinVerticesPerPiece = 2048;

// Piece inPiece of inPieces equal parts of inItems.
std::span<const std::uint32_t> PieceOf(std::span<const std::uint32_t> inItems, int inPiece, int inPieces)
{
    const std::size_t begin = inItems.size() * static_cast<std::size_t>(inPiece) / static_cast<std::size_t>(inPieces);
    const std::size_t end = inItems.size() * static_cast<std::size_t>(inPiece + 1) / static_cast<std::size_t>(inPieces);
    return inItems.subspan(begin, end - begin);
}

} // namespace

Result<FfdDeformer> FfdDeformer::Create(TriangleMesh inRestMesh, const FfdDeformerSettings& inSettings)
{
    // Validate everything before building anything.
    if (Status mesh_status = ValidateTriangleMesh(inRestMesh); !mesh_status)
        return mesh_status.GetError();
    if (inSettings.mZones.empty())
        return MakeError(EError::InvalidArgument, "FfdDeformerSettings.mZones is empty: a deformer needs a zone");
    if (!(inSettings.mRankTolerance > 0.0 && inSettings.mRankTolerance < 1.0))
        return MakeError(EError::InvalidArgument, "FfdDeformerSettings.mRankTolerance must be in (0, 1)");
    if (!(inSettings.mMergeDistance >= 0.0 && inSettings.mMergeDistance < 1.0))
        return MakeError(EError::InvalidArgument, "FfdDeformerSettings.mMergeDistance must be in [0, 1) cells");
    if (!(inSettings.mCaptureDistance >= 0.0 && inSettings.mCaptureDistance <= 4.0))
        return MakeError(EError::InvalidArgument, "FfdDeformerSettings.mCaptureDistance must be in [0, 4] cells");
    if (inSettings.mInverseIterations < 0 || inSettings.mInverseIterations > 32)
        return MakeError(EError::InvalidArgument, "FfdDeformerSettings.mInverseIterations must be in [0, 32]");
    if (!(inSettings.mMinControlSpacing >= 0.0 && inSettings.mMinControlSpacing < 1.0))
        return MakeError(EError::InvalidArgument,
                         "FfdDeformerSettings.mMinControlSpacing must be finite and in [0, 1) spacings");
    if (inSettings.mPrior != EDirectManipulationPrior::None && inSettings.mPrior != EDirectManipulationPrior::QuasiInterpolant)
        return MakeError(EError::InvalidArgument, "FfdDeformerSettings.mPrior is not an EDirectManipulationPrior value");
    if (!(inSettings.mMaxControlGain >= 1.0))
        return MakeError(EError::InvalidArgument, "FfdDeformerSettings.mMaxControlGain must be >= 1 (or infinity)");

    {
        // intent: every part non-empty, every index a vertex, no vertex in two parts, before anything is built
        std::vector<std::uint8_t> in_part(inRestMesh.mPositions.size(), 0);
        for (std::size_t part = 0; part < inSettings.mRigidParts.size(); ++part)
        {
            const std::string name = "FfdDeformerSettings.mRigidParts[" + std::to_string(part) + "]";
            if (inSettings.mRigidParts[part].empty())
                return MakeError(EError::InvalidArgument, name + " is empty");
            for (std::uint32_t v : inSettings.mRigidParts[part])
            {
                if (v >= in_part.size())
                    return MakeError(EError::OutOfRange, name + " names vertex " + std::to_string(v) + " of a mesh of " +
                                                             std::to_string(in_part.size()));
                if (in_part[v] != 0)
                    return MakeError(EError::InvalidArgument, name + ": vertex " + std::to_string(v) +
                                                                  " is in an earlier part, or twice in this one");
                in_part[v] = 1;
            }
        }
    }

    {
        // intent: the lattices' size refused before any is built (a zone of 256^3 controls alone holds 400 MB);
        // counted in double, exact far past the bound, so no product of counts can overflow. A count below 4
        // is FfdLattice::Create's to refuse.
        double cells_in_zones = 0.0;
        for (const FfdZoneSettings& zone : inSettings.mZones)
        {
            double cells = 1.0;
            for (int count : zone.mLattice.mControlCount)
                cells *= std::max(static_cast<double>(count) - 3.0, 0.0);
            cells_in_zones += cells;
        }
        if (cells_in_zones > static_cast<double>(cMaxCellsInZones))
            return MakeError(EError::InvalidArgument, "FfdDeformerSettings.mZones: " + std::to_string(static_cast<std::int64_t>(cells_in_zones)) +
                                                          " cells in all, more than the " + std::to_string(cMaxCellsInZones) +
                                                          " a deformer indexes");
    }

    FfdDeformer deformer;
    for (std::size_t z = 0; z < inSettings.mZones.size(); ++z)
    {
        const FfdZoneSettings& zone = inSettings.mZones[z];
        if (!(std::isfinite(zone.mMaxTotalDeformation) && zone.mMaxTotalDeformation >= 0.0))
            return MakeError(EError::InvalidArgument, "FfdDeformerSettings.mZones[" + std::to_string(z) +
                                                          "].mMaxTotalDeformation must be finite and >= 0 m");
        Result<FfdLattice> lattice = FfdLattice::Create(zone.mLattice);
        if (!lattice)
            return MakeError(lattice.GetError().mCode,
                             "mZones[" + std::to_string(z) + "]: " + lattice.GetError().mMessage);
        deformer.mZones.push_back(std::move(lattice).Get());
    }
    deformer.mSettings = inSettings;
    deformer.mRestMesh = std::move(inRestMesh);

    const auto vertex_count = static_cast<std::uint32_t>(deformer.mRestMesh.mPositions.size());
    const auto triangle_count = static_cast<std::uint32_t>(deformer.mRestMesh.mTriangles.size());

    // Bind each vertex to the first zone holding its rest position (a hair of tolerance for box faces).
    constexpr double cBindMargin = 1.0e-9;
    const auto bind = [&deformer](const Vec3& inRestPoint, int& outZone, LatticeLocation& outLocation) {
        for (std::size_t z = 0; z < deformer.mZones.size(); ++z)
        {
            const Vec3 u = deformer.mZones[z].LatticeCoordinate(inRestPoint);
            if (deformer.mZones[z].Contains(u, cBindMargin))
            {
                outZone = static_cast<int>(z);
                outLocation = deformer.mZones[z].Locate(u);
                return;
            }
        }
    };
    deformer.mVertexZone.assign(vertex_count, -1);
    // intent: each vertex's location only while the buckets are built; the deformer keeps them in bucket order
    // (mBucketLocations) and each vertex's place there (mVertexBucket), 4 bytes a vertex instead of 40
    std::vector<LatticeLocation> vertex_location(vertex_count, LatticeLocation{});
    for (std::uint32_t v = 0; v < vertex_count; ++v)
        bind(deformer.mRestMesh.mPositions[v], deformer.mVertexZone[v], vertex_location[v]);
    // A rigid part's vertices all take the lattice location of its rest bounding box's centre: every use of a
    // vertex's location (its displacement, its cell bucket, the surface index, the bounds) then moves the part
    // as one, and a dent touches it exactly when it changes a control that reaches the centre.
    for (const std::vector<std::uint32_t>& part : inSettings.mRigidParts)
    {
        std::vector<Vec3> rest(part.size());
        for (std::size_t i = 0; i < part.size(); ++i)
            rest[i] = deformer.mRestMesh.mPositions[part[i]];
        const AlignedBox box = BoundingBox(rest);
        int zone = -1;
        LatticeLocation location{};
        bind(0.5 * (box.mMin + box.mMax), zone, location);
        for (std::uint32_t v : part)
        {
            deformer.mVertexZone[v] = zone;
            vertex_location[v] = location;
        }
    }

    // Bucket vertices by cell per zone (counting sort keeps ascending vertex order inside a cell).
    deformer.mCellStart.resize(deformer.mZones.size());
    deformer.mCellVertices.resize(deformer.mZones.size());
    for (std::size_t z = 0; z < deformer.mZones.size(); ++z)
    {
        const FfdLattice& lattice = deformer.mZones[z];
        const auto cells = static_cast<std::size_t>(lattice.GetCellTotal());
        std::vector<std::uint32_t>& start = deformer.mCellStart[z];
        start.assign(cells + 1, 0);
        for (std::uint32_t v = 0; v < vertex_count; ++v)
            if (deformer.mVertexZone[v] == static_cast<int>(z))
                ++start[static_cast<std::size_t>(lattice.CellIndex(vertex_location[v].mCell)) + 1];
        for (std::size_t c = 0; c < cells; ++c)
            start[c + 1] += start[c];
        std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
        deformer.mCellVertices[z].resize(start[cells]);
        for (std::uint32_t v = 0; v < vertex_count; ++v)
            if (deformer.mVertexZone[v] == static_cast<int>(z))
                deformer.mCellVertices[z][fill[static_cast<std::size_t>(lattice.CellIndex(vertex_location[v].mCell))]++] = v;
    }

    // The bucketed vertices' locations and rest positions in bucket order.
    for (std::size_t z = 0; z < deformer.mZones.size(); ++z)
    {
        std::vector<LatticeLocation>& locations = deformer.mBucketLocations.emplace_back();
        std::vector<Vec3>& rest = deformer.mBucketRest.emplace_back();
        locations.reserve(deformer.mCellVertices[z].size());
        rest.reserve(deformer.mCellVertices[z].size());
        for (std::uint32_t v : deformer.mCellVertices[z])
        {
            locations.push_back(vertex_location[v]);
            rest.push_back(deformer.mRestMesh.mPositions[v]);
        }
    }
    deformer.mVertexBucket.assign(vertex_count, 0);
    for (std::size_t z = 0; z < deformer.mZones.size(); ++z)
        for (std::size_t k = 0; k < deformer.mCellVertices[z].size(); ++k)
            deformer.mVertexBucket[deformer.mCellVertices[z][k]] = static_cast<std::uint32_t>(k);

    // Cells numbered across zones, and each vertex's, for the surface index (about 70 bytes per cell, and 96
    // more for a cell that holds vertices: CellMotion).
    int cell_total = 0;
    for (const FfdLattice& zone : deformer.mZones)
    {
        deformer.mCellOffset.push_back(cell_total);
        cell_total += zone.GetCellTotal();
    }
    deformer.mVertexCell.assign(vertex_count, -1);
    for (std::uint32_t v = 0; v < vertex_count; ++v)
        if (const int zone = deformer.mVertexZone[v]; zone >= 0)
            deformer.mVertexCell[v] = deformer.mCellOffset[static_cast<std::size_t>(zone)] +
                                      deformer.mZones[static_cast<std::size_t>(zone)].CellIndex(vertex_location[v].mCell);
    // intent: given back before the surface index and the normals allocate theirs, which can reuse it
    std::vector<LatticeLocation>().swap(vertex_location);
    deformer.mSurfaceIndex = std::make_shared<const CellSurfaceIndex>(
        CellSurfaceIndex::Build(deformer.mRestMesh, deformer.mVertexCell, cell_total));

    // Which controls reach a vertex: the 4 x 4 x 4 of every cell that holds one. The others move nothing,
    // so dents never store a value in them and a loaded state must have them zero.
    deformer.mControlReaches.resize(deformer.mZones.size());
    for (std::size_t z = 0; z < deformer.mZones.size(); ++z)
    {
        const FfdLattice& lattice = deformer.mZones[z];
        const std::array<int, 3>& cells = lattice.GetCellCount();
        std::vector<std::uint8_t>& reaches = deformer.mControlReaches[z];
        reaches.assign(static_cast<std::size_t>(lattice.GetControlCount()), 0);
        for (int k = 0; k < cells[2]; ++k)
            for (int j = 0; j < cells[1]; ++j)
                for (int i = 0; i < cells[0]; ++i)
                {
                    const auto cell = static_cast<std::size_t>(lattice.CellIndex({i, j, k}));
                    if (deformer.mCellStart[z][cell + 1] == deformer.mCellStart[z][cell])
                        continue;
                    for (int c = 0; c < 4; ++c)
                        for (int b = 0; b < 4; ++b)
                            for (int a = 0; a < 4; ++a)
                                reaches[static_cast<std::size_t>(lattice.ControlIndex(i + a, j + b, k + c))] = 1;
                }
    }

    // Vertex -> triangle adjacency for normal updates.
    deformer.mVertexTriangleStart.assign(vertex_count + 1, 0);
    for (const auto& triangle : deformer.mRestMesh.mTriangles)
        for (std::uint32_t v : triangle)
            ++deformer.mVertexTriangleStart[v + 1];
    for (std::uint32_t v = 0; v < vertex_count; ++v)
        deformer.mVertexTriangleStart[v + 1] += deformer.mVertexTriangleStart[v];
    deformer.mVertexTriangles.resize(deformer.mVertexTriangleStart[vertex_count]);
    std::vector<std::uint32_t> fill(deformer.mVertexTriangleStart.begin(), deformer.mVertexTriangleStart.end() - 1);
    for (std::uint32_t f = 0; f < triangle_count; ++f)
        for (std::uint32_t v : deformer.mRestMesh.mTriangles[f])
            deformer.mVertexTriangles[fill[v]++] = f;

    for (const FfdLattice& zone : deformer.mZones)
        deformer.mScratchControls.emplace_back(static_cast<std::size_t>(zone.GetControlCount()), Vec3::Zero());
    deformer.mGuardControls = deformer.mScratchControls;
    deformer.mZoneDisplacementBound.assign(deformer.mZones.size(), 0.0);
    // intent: a slot for each cell that holds vertices, in cell order; at rest its vertices stand at their
    // rest positions, moved by nothing
    deformer.mCellMotionSlot.assign(static_cast<std::size_t>(cell_total), -1);
    for (std::uint32_t v = 0; v < vertex_count; ++v)
        if (const int cell = deformer.mVertexCell[v]; cell >= 0)
            deformer.mCellMotionSlot[static_cast<std::size_t>(cell)] = 0;
    std::int32_t occupied = 0;
    for (std::int32_t& slot : deformer.mCellMotionSlot)
        if (slot == 0)
            slot = occupied++;
    deformer.mCellMotion.assign(static_cast<std::size_t>(occupied), CellMotion{});
    for (std::uint32_t v = 0; v < vertex_count; ++v)
        if (const int cell = deformer.mVertexCell[v]; cell >= 0)
            deformer.MotionOf(cell).Include(deformer.mRestMesh.mPositions[v], Vec3::Zero());
    // intent: each slice's reach: the union of its cells' reach boxes, per axis
    for (std::size_t z = 0; z < deformer.mZones.size(); ++z)
    {
        const FfdLattice& zone = deformer.mZones[z];
        const std::array<int, 3>& cells = zone.GetCellCount();
        SliceReach slices;
        for (std::size_t axis = 0; axis < 3; ++axis)
        {
            slices.mLow[axis].assign(static_cast<std::size_t>(cells[axis]), Vec3::Constant(std::numeric_limits<double>::infinity()));
            slices.mHigh[axis].assign(static_cast<std::size_t>(cells[axis]), Vec3::Constant(-std::numeric_limits<double>::infinity()));
        }
        for (int k = 0; k < cells[2]; ++k)
            for (int j = 0; j < cells[1]; ++j)
                for (int i = 0; i < cells[0]; ++i)
                {
                    const int cell = deformer.mCellOffset[z] + zone.CellIndex({i, j, k});
                    const std::array<int, 3> ijk{i, j, k};
                    for (std::size_t axis = 0; axis < 3; ++axis)
                    {
                        Vec3& low = slices.mLow[axis][static_cast<std::size_t>(ijk[axis])];
                        Vec3& high = slices.mHigh[axis][static_cast<std::size_t>(ijk[axis])];
                        low = low.cwiseMin(deformer.mSurfaceIndex->ReachLow(cell));
                        high = high.cwiseMax(deformer.mSurfaceIndex->ReachHigh(cell));
                    }
                }
        deformer.mSlices.push_back(std::move(slices));
    }
    deformer.mVertexBits.assign((vertex_count + 63) / 64, 0);
    deformer.mTriangleBits.assign((triangle_count + 63) / 64, 0);
    deformer.mDirty.assign(vertex_count, 0);
    deformer.mPositions = deformer.mRestMesh.mPositions;
    deformer.mNormals.assign(vertex_count, Vec3::Zero());
    deformer.mFaceNormals.assign(triangle_count, Vec3::Zero());
    // Zero controls move no vertex by even an ulp (FfdLattice), so the positions are the rest mesh as
    // copied above: only the normals need computing.
    deformer.RecomputeNormals();
    // intent: a vertex whose triangles' normals cancel to within 1e-3 of their summed areas has no normal of
    // its own (a double-sided sheet on shared vertices: its sum is round-off and points anywhere, and a
    // renderer shades it as noise); it takes its largest triangle's, either side, as a surface facing one way
    // would
    bool any_sheet = false;
    deformer.mSheetVertices.assign(vertex_count, 0);
    for (std::uint32_t v = 0; v < vertex_count; ++v)
    {
        Vec3 sum = Vec3::Zero();
        double area = 0.0;
        for (std::uint32_t i = deformer.mVertexTriangleStart[v]; i < deformer.mVertexTriangleStart[v + 1];
             ++i)
        {
            sum += deformer.mFaceNormals[deformer.mVertexTriangles[i]];
            area += deformer.mFaceNormals[deformer.mVertexTriangles[i]].norm();
        }
        if (area > 0.0 && !(sum.norm() > cSheetCancellation * area))
            deformer.mSheetVertices[v] = any_sheet = true;
    }
    // intent: only the sheet vertices' normals change (the face normals and every other vertex's are as
    // computed above), so only they are computed again
    if (any_sheet)
    {
        for (std::uint32_t v = 0; v < vertex_count; ++v)
            if (deformer.mSheetVertices[v] != 0)
                deformer.mNormals[v] = deformer.VertexNormal(v);
    }
    else
        std::vector<std::uint8_t>().swap(deformer.mSheetVertices);
    deformer.mRestNormals = deformer.mNormals;
    std::fill(deformer.mDirty.begin(), deformer.mDirty.end(), std::uint8_t{0});
    deformer.mVertexEvaluations = 0;
    return deformer;
}

double FfdDeformer::GetMinSpacing() const
{
    double spacing = std::numeric_limits<double>::infinity();
    for (const FfdLattice& zone : mZones)
        spacing = std::min(spacing, zone.GetSpacing().minCoeff());
    return spacing;
}

Vec3 FfdDeformer::RestLatticeCoordinate(int inZone, const Vec3& inPoint) const
{
    // The point lies on the deformed surface: solve rest(u) + D(u) = p by fixed-point iteration
    // u <- L(p - D(u)), which converges while the displacement field does not fold the lattice.
    const FfdLattice& zone = mZones[static_cast<std::size_t>(inZone)];
    Vec3 u = zone.LatticeCoordinate(inPoint);
    for (int iteration = 0; iteration < mSettings.mInverseIterations; ++iteration)
        u = zone.LatticeCoordinate(inPoint - zone.Displacement(zone.Locate(u)));
    return u;
}

Result<DentReport> FfdDeformer::ApplyDent(std::span<const PointDisplacement> inPoints, double inMaxStep)
{
    // Refuse the whole dent before touching anything.
    for (std::size_t i = 0; i < inPoints.size(); ++i)
    {
        if (!IsFinite(inPoints[i].mPoint) || !IsFinite(inPoints[i].mDisplacement))
            return MakeError(EError::NonFinite, "ApplyDent: point " + std::to_string(i) + " is not finite");
        // intent: a displacement beyond any mesh's extent would overflow the solve in one zone and not another
        if (!(inPoints[i].mDisplacement.cwiseAbs().maxCoeff() <= cMaxMeshCoordinate))
            return MakeError(EError::OutOfRange, "ApplyDent: point " + std::to_string(i) + " moves further than 1e6 m");
    }
    if (!(inMaxStep >= 0.0)) // +inf: no bound
        return MakeError(std::isnan(inMaxStep) ? EError::NonFinite : EError::InvalidArgument,
                         "ApplyDent: the maximum step must be >= 0 m (or +inf)");

    DentReport report;
    const bool any_motion = std::any_of(inPoints.begin(), inPoints.end(),
                                        [](const PointDisplacement& p) { return !p.mDisplacement.isZero(0.0); });
    if (!any_motion)
        return report;

    // Assign each point to the first zone that holds it (within the capture distance), then merge
    // near-coincident points of a zone by averaging their displacements.
    std::vector<ZonePointSet> zone_points(mZones.size(), ZonePointSet(mSettings.mMergeDistance));
    for (const PointDisplacement& point : inPoints)
    {
        report.mMaxWanted = std::max(report.mMaxWanted, point.mDisplacement.norm());
        // The first zone that holds the point; only if none does, the first within the capture distance.
        int zone_index = -1;
        for (double margin : {1.0e-9, mSettings.mCaptureDistance})
            for (std::size_t z = 0; z < mZones.size() && zone_index < 0; ++z)
                if (mZones[z].Contains(mZones[z].LatticeCoordinate(point.mPoint), margin))
                    zone_index = static_cast<int>(z);
        if (zone_index < 0)
        {
            ++report.mPointsIgnored;
            continue;
        }
        const FfdLattice& zone = mZones[static_cast<std::size_t>(zone_index)];
        Vec3 u = RestLatticeCoordinate(zone_index, point.mPoint);
        u = u.cwiseMax(Vec3::Zero()).cwiseMin(Vec3(zone.GetCellCount()[0], zone.GetCellCount()[1], zone.GetCellCount()[2]));
        if (zone_points[static_cast<std::size_t>(zone_index)].Add(u, point.mDisplacement))
            ++report.mPointsMerged;
    }

    for (std::size_t z = 0; z < mZones.size(); ++z)
    {
        std::vector<ZonePoint>& points = zone_points[z].GetPoints();
        if (points.empty())
            continue;
        // intent: the solve's cost grows with the square of the points and more (cMaxZonePoints)
        report.mPointsMerged += ThinZonePoints(points);
        FfdLattice& zone = mZones[z];
        std::vector<LatticeLocation> locations;
        Eigen::MatrixX3d wanted(static_cast<Eigen::Index>(points.size()), 3);
        for (std::size_t i = 0; i < points.size(); ++i)
        {
            locations.push_back(zone.Locate(points[i].mLattice));
            wanted.row(static_cast<Eigen::Index>(i)) = points[i].mDisplacement.transpose();
        }
        report.mPointsApplied += static_cast<int>(points.size());

        // Solve dC = B^+ dP over the controls these points reach.
        const DirectManipulationData data = DirectManipulationPrecompute(zone, locations, mSettings.mRankTolerance);
        DirectManipulationSolveInfo solve_info;
        Eigen::MatrixX3d control_delta =
            DirectManipulationSolve(data, wanted, mSettings.mPrior, mSettings.mMaxControlGain, &solve_info);
        if (mSettings.mOneSidedDents && control_delta.allFinite())
            report.mControlsClipped += OneSidedControls(wanted, control_delta);
        // A solve past the double range moves nothing (and stores no NaN).
        if (!wanted.allFinite() || !control_delta.allFinite())
        {
            report.mScale = 0.0;
            continue;
        }
        report.mRankDeficiency += static_cast<int>(points.size()) - solve_info.mRank;
        report.mSolveTolerance = std::max(report.mSolveTolerance, solve_info.mTolerance);

        // Where the points are now, to measure what the dent achieved.
        std::vector<Vec3> before(locations.size());
        for (std::size_t i = 0; i < locations.size(); ++i)
            before[i] = zone.Displacement(locations[i]);

        CommitZoneDelta(static_cast<int>(z), data.mControls, control_delta, inMaxStep, report);

        for (std::size_t i = 0; i < locations.size(); ++i)
        {
            const Vec3 achieved = zone.Displacement(locations[i]) - before[i];
            const Vec3 target = wanted.row(static_cast<Eigen::Index>(i)).transpose();
            report.mMaxPointError = std::max(report.mMaxPointError, (achieved - target).norm());
        }
    }
    return report;
}

void FfdDeformer::CommitZoneDelta(int inZone, std::span<const int> inControls, const Eigen::MatrixX3d& inDelta,
                                  double inMaxStep, DentReport& ioReport)
{
    CatchUp();
    DentReport& report = ioReport;
    // Scale the dent down as a whole if it would move a vertex too far in one go or in total.
    std::vector<int> changed;
    for (std::size_t k = 0; k < inControls.size(); ++k)
        if (!inDelta.row(static_cast<Eigen::Index>(k)).isZero(0.0))
            changed.push_back(inControls[k]);
    TouchCells(inZone, changed);
    std::vector<std::uint32_t> reached = TouchedVertices();
    double scale = DentScale(inZone, inControls, inDelta, reached, inMaxStep);
    std::span<const int> dent_controls = inControls;
    const Eigen::MatrixX3d* dent_delta = &inDelta;
    double solve_scale = scale; // the factor on the solved dent, for the report

    // Fold guard on the dent as it would be committed (scaled): a control pushed into its neighbour along
    // a lattice line pushes it along. Guarding the unscaled solve instead would cascade its whole,
    // possibly much deeper, overshoot down the line before the scale shrinks it (the offset-wall example
    // then moved the car's rear by 8 cm). When nothing is pushed (the common case) the solve's controls,
    // rows and scale are committed as they are, bit for bit.
    std::vector<Vec3>& controls = mZones[static_cast<std::size_t>(inZone)].GetControlDisplacements();
    // intent: the guard's trial field, equal to the controls outside this call (no copy of the lattice)
    std::vector<Vec3>& after = mGuardControls[static_cast<std::size_t>(inZone)];
    std::vector<int> pushed;
    std::vector<int> guarded_controls;
    Eigen::MatrixX3d guarded_delta;
    if (mSettings.mMinControlSpacing > 0.0 && scale > 0.0 && !changed.empty())
    {
        for (std::size_t k = 0; k < inControls.size(); ++k)
            after[static_cast<std::size_t>(inControls[k])] +=
                scale * inDelta.row(static_cast<Eigen::Index>(k)).transpose();
        pushed = FoldGuard(mZones[static_cast<std::size_t>(inZone)], controls, after, changed, mSettings.mMinControlSpacing,
                           mControlReaches[static_cast<std::size_t>(inZone)]);
        if (!pushed.empty())
        {
            // intent: the changed set is the union of solved and pushed controls (both ascending)
            std::set_union(inControls.begin(), inControls.end(), pushed.begin(), pushed.end(),
                           std::back_inserter(guarded_controls));
            guarded_delta.resize(static_cast<Eigen::Index>(guarded_controls.size()), 3);
            changed.clear();
            for (std::size_t k = 0; k < guarded_controls.size(); ++k)
            {
                const auto control = static_cast<std::size_t>(guarded_controls[k]);
                guarded_delta.row(static_cast<Eigen::Index>(k)) = (after[control] - controls[control]).transpose();
                if (!guarded_delta.row(static_cast<Eigen::Index>(k)).isZero(0.0))
                    changed.push_back(guarded_controls[k]);
            }
            // intent: the pushes move more vertices, so the bounds are checked again on the guarded dent.
            // The guard's bound is a set of linear inequalities on the controls, hence convex; the
            // controls before (factor 0) and after the guard (factor 1) both satisfy it, so every factor
            // in [0, 1] that DentScale picks keeps it.
            UntouchCells();
            TouchCells(inZone, changed);
            reached = TouchedVertices();
            const double guarded_scale =
                DentScale(inZone, guarded_controls, guarded_delta, reached, inMaxStep);
            // The first factor is already in guarded_delta: commit with the second, report their product.
            solve_scale = scale * guarded_scale;
            scale = guarded_scale;
            dent_controls = guarded_controls;
            dent_delta = &guarded_delta;
        }
    }
    report.mScale = std::min(report.mScale, solve_scale);

    // Commit the controls (those that reach no vertex keep zero: they would move nothing), then recompute
    // the reached vertices from them.
    const std::vector<std::uint8_t>& reaches = mControlReaches[static_cast<std::size_t>(inZone)];
    for (std::size_t k = 0; k < dent_controls.size() && scale > 0.0; ++k)
        if (reaches[static_cast<std::size_t>(dent_controls[k])] != 0)
            controls[static_cast<std::size_t>(dent_controls[k])] +=
                scale * dent_delta->row(static_cast<Eigen::Index>(k)).transpose();
    report.mControlsChanged += scale > 0.0 ? static_cast<int>(changed.size()) : 0;
    report.mControlsPushed += scale > 0.0 ? static_cast<int>(pushed.size()) : 0;
    // intent: the trial field back to the controls, wherever the guard's trial wrote
    if (mSettings.mMinControlSpacing > 0.0)
    {
        for (int control : inControls)
            after[static_cast<std::size_t>(control)] = controls[static_cast<std::size_t>(control)];
        for (int control : pushed)
            after[static_cast<std::size_t>(control)] = controls[static_cast<std::size_t>(control)];
    }
    if (scale > 0.0)
        UpdateVertices(inZone, reached, report);
    UntouchCells();
}

Result<DentReport> FfdDeformer::ApplyControlDelta(int inZone, std::span<const int> inControls,
                                                  const Eigen::MatrixX3d& inDelta, double inMaxStep)
{
    // Refuse the whole change before touching anything.
    if (inZone < 0 || static_cast<std::size_t>(inZone) >= mZones.size())
        return MakeError(EError::OutOfRange, "ApplyControlDelta: zone " + std::to_string(inZone) + " does not exist");
    if (inDelta.rows() != static_cast<Eigen::Index>(inControls.size()) || inDelta.cols() != 3)
        return MakeError(EError::InvalidArgument, "ApplyControlDelta: one row of 3 displacements per control");
    const int count = mZones[static_cast<std::size_t>(inZone)].GetControlCount();
    for (std::size_t k = 0; k < inControls.size(); ++k)
    {
        if (inControls[k] < 0 || inControls[k] >= count || (k > 0 && inControls[k] <= inControls[k - 1]))
            return MakeError(EError::InvalidArgument,
                             "ApplyControlDelta: control indices must be ascending, unique and within the zone");
    }
    if (!inDelta.allFinite())
        return MakeError(EError::NonFinite, "ApplyControlDelta: a displacement is not finite");
    if (!(inMaxStep >= 0.0))
        return MakeError(EError::InvalidArgument, "ApplyControlDelta: the maximum step must be >= 0 m");
    DentReport report;
    if (inControls.empty() || inDelta.isZero(0.0))
        return report;
    CommitZoneDelta(inZone, inControls, inDelta, inMaxStep, report);
    return report;
}

void FfdDeformer::TouchCells(int inZone, std::span<const int> inControls)
{
    if (inControls.empty())
        return;
    const FfdLattice& zone = mZones[static_cast<std::size_t>(inZone)];
    const std::array<int, 3>& n = zone.GetSettings().mControlCount;
    const std::array<int, 3>& cells = zone.GetCellCount();

    // intent: the box of the changed controls, and the cells it can reach (a control reaches cells a-3..a);
    // each control's (a, b, c) worked out once, with two divisions (it took three, twice over)
    std::vector<std::array<int, 3>>& decoded = mTouchedControls;
    decoded.resize(inControls.size());
    std::array<int, 3> low{n[0], n[1], n[2]}, high{-1, -1, -1};
    const int plane = n[0] * n[1];
    for (std::size_t k = 0; k < inControls.size(); ++k)
    {
        const int c = inControls[k] / plane, rest = inControls[k] - c * plane;
        const int b = rest / n[0];
        decoded[k] = {rest - b * n[0], b, c};
        for (std::size_t axis = 0; axis < 3; ++axis)
        {
            low[axis] = std::min(low[axis], decoded[k][axis]);
            high[axis] = std::max(high[axis], decoded[k][axis]);
        }
    }
    std::array<int, 3> cell_low{}, cell_high{}, extent{};
    for (std::size_t axis = 0; axis < 3; ++axis)
    {
        cell_low[axis] = std::max(low[axis] - 3, 0);
        cell_high[axis] = std::min(high[axis], cells[axis] - 1);
        // One index range covers both the controls and the cells of the box along the axis.
        extent[axis] = high[axis] - cell_low[axis] + 1;
    }

    // intent: a cell is touched when a changed control lies in its 4 x 4 x 4: a window-4 OR along each
    // axis in turn over the box (separable dilation), linear in the box, not 64 marks per control
    const auto box = static_cast<std::size_t>(extent[0]) * static_cast<std::size_t>(extent[1]) * static_cast<std::size_t>(extent[2]);
    auto at = [&](int inI, int inJ, int inK) {
        return static_cast<std::size_t>(inI) +
               static_cast<std::size_t>(extent[0]) * (static_cast<std::size_t>(inJ) + static_cast<std::size_t>(extent[1]) * static_cast<std::size_t>(inK));
    };
    std::vector<std::uint8_t>& mask = mDilation[0];
    std::vector<std::uint8_t>& swept = mDilation[1];
    mask.assign(box, 0);
    swept.assign(box, 0);
    for (const std::array<int, 3>& abc : decoded)
        mask[at(abc[0] - cell_low[0], abc[1] - cell_low[1], abc[2] - cell_low[2])] = 1;
    // intent: along each axis, the box as blocks of lines across it (the stride of the axis is the length of a
    // contiguous block): a cell at coordinate x takes the OR of x .. x + 3 that lie in the box, block by block,
    // so the inner loop runs over contiguous bytes
    const std::array<std::size_t, 3> stride{1, static_cast<std::size_t>(extent[0]),
                                            static_cast<std::size_t>(extent[0]) * static_cast<std::size_t>(extent[1])};
    for (std::size_t axis = 0; axis < 3; ++axis)
    {
        const std::size_t block = stride[axis], length = static_cast<std::size_t>(extent[axis]);
        const std::size_t outer = box / (block * length);
        for (std::size_t o = 0; o < outer; ++o)
            for (std::size_t x = 0; x < length; ++x)
            {
                const std::uint8_t* from = mask.data() + (o * length + x) * block;
                std::uint8_t* to = swept.data() + (o * length + x) * block;
                const std::size_t reach = std::min<std::size_t>(4, length - x);
                for (std::size_t i = 0; i < block; ++i)
                {
                    std::uint8_t any = from[i];
                    for (std::size_t d = 1; d < reach; ++d)
                        any |= from[i + d * block];
                    to[i] = any;
                }
            }
        mask.swap(swept);
    }

    // intent: the touched cells that hold a vertex, ascending (CellIndex runs i fastest)
    const int offset = mCellOffset[static_cast<std::size_t>(inZone)];
    const std::vector<std::uint32_t>& start = mCellStart[static_cast<std::size_t>(inZone)];
    for (int k = cell_low[2]; k <= cell_high[2]; ++k)
        for (int j = cell_low[1]; j <= cell_high[1]; ++j)
            for (int i = cell_low[0]; i <= cell_high[0]; ++i)
            {
                const auto cell = static_cast<std::size_t>(zone.CellIndex({i, j, k}));
                if (mask[at(i - cell_low[0], j - cell_low[1], k - cell_low[2])] == 0 || start[cell + 1] == start[cell])
                    continue;
                mTouchedCells.push_back(offset + static_cast<int>(cell));
            }
    mTouchedZone = inZone;
}

void FfdDeformer::UntouchCells()
{
    mTouchedCells.clear();
}

std::vector<std::uint32_t> FfdDeformer::TouchedVertices() const
{
    std::vector<std::uint32_t> vertices;
    if (mTouchedCells.empty())
        return vertices;
    const int offset = mCellOffset[static_cast<std::size_t>(mTouchedZone)];
    const std::vector<std::uint32_t>& start = mCellStart[static_cast<std::size_t>(mTouchedZone)];
    const std::vector<std::uint32_t>& bucket = mCellVertices[static_cast<std::size_t>(mTouchedZone)];
    std::size_t total = 0;
    for (int cell : mTouchedCells)
        total += start[static_cast<std::size_t>(cell - offset) + 1] - start[static_cast<std::size_t>(cell - offset)];
    vertices.reserve(total);
    for (int cell : mTouchedCells)
        vertices.insert(vertices.end(), bucket.begin() + start[static_cast<std::size_t>(cell - offset)],
                        bucket.begin() + start[static_cast<std::size_t>(cell - offset) + 1]);
    return vertices;
}

double FfdDeformer::DentScale(int inZone, std::span<const int> inControls, const Eigen::MatrixX3d& inDelta,
                              std::span<const std::uint32_t> inVertices, double inMaxStep)
{
    const FfdLattice& zone = mZones[static_cast<std::size_t>(inZone)];
    const double max_total = mSettings.mZones[static_cast<std::size_t>(inZone)].mMaxTotalDeformation;

    // Cheap test first: a vertex moves by a convex combination of its controls' changes, so no vertex moves
    // further than the largest change. Within both bounds, the dent needs no per-vertex check.
    double largest_change = 0.0;
    for (Eigen::Index k = 0; k < inDelta.rows(); ++k)
    {
        const double change = inDelta.row(k).norm();
        if (!(change <= largest_change)) // NaN included: the cheap test then fails
            largest_change = change;
    }
    if (largest_change <= inMaxStep &&
        mZoneDisplacementBound[static_cast<std::size_t>(inZone)] + largest_change <= max_total)
        return 1.0;

    std::vector<Vec3>& scratch = mScratchControls[static_cast<std::size_t>(inZone)];
    const std::vector<LatticeLocation>& locations = mBucketLocations[static_cast<std::size_t>(inZone)];
    for (std::size_t k = 0; k < inControls.size(); ++k)
        scratch[static_cast<std::size_t>(inControls[k])] = inDelta.row(static_cast<Eigen::Index>(k)).transpose();

    // Per vertex: the dent moves it by s n on top of its current displacement o. The step bound asks
    // s |n| <= max_step; the total bound |o + s n| <= max_total holds up to the larger root of
    // |n|^2 s^2 + 2 (o.n) s + |o|^2 - max_total^2 = 0.
    // intent: per-piece minima over the host's workers; min is exact, so the piece count cannot change it
    const int pieces = PieceCount(mJobs, inVertices.size(), cMinVerticesPerPiece);
    std::vector<double> piece_scale(static_cast<std::size_t>(pieces), 1.0);
    ParallelFor(mJobs, pieces, [&](int inPiece) {
        double scale = 1.0;
        for (std::uint32_t v : PieceOf(inVertices, inPiece, pieces))
        {
            const Vec3 n = zone.Displacement(locations[mVertexBucket[v]], scratch);
            const double n2 = n.squaredNorm();
            if (n2 == 0.0)
                continue;
            // A field past the double range (its square overflows, or it is NaN) can be scaled by nothing
            // trustworthy: the dent is refused (scale 0). Every candidate below is taken in a form that keeps
            // a NaN (std::min would drop it and let the dent through unbounded).
            if (!std::isfinite(n2))
            {
                scale = 0.0;
                break;
            }
            const double step = inMaxStep / std::sqrt(n2);
            scale = step < scale ? step : scale;
            const Vec3 o = mPositions[v] - mRestMesh.mPositions[v];
            const double on = o.dot(n);
            const double slack = max_total * max_total - o.squaredNorm();
            const double discriminant = on * on + n2 * slack;
            const double root = discriminant > 0.0 ? (-on + std::sqrt(discriminant)) / n2 : 0.0;
            if (!(root >= 0.0) || !std::isfinite(on) || !std::isfinite(discriminant) || !std::isfinite(root))
            {
                scale = 0.0;
                break;
            }
            scale = root < scale ? root : scale;
        }
        piece_scale[static_cast<std::size_t>(inPiece)] = scale;
    });
    const double scale = *std::min_element(piece_scale.begin(), piece_scale.end());
    mVertexEvaluations += inVertices.size();
    for (int control : inControls)
        scratch[static_cast<std::size_t>(control)] = Vec3::Zero();
    // Stay a hair inside the bound, so that round-off in the recomputed positions cannot cross it.
    return scale < 1.0 ? scale * (1.0 - 1.0e-9) : 1.0;
}

void FfdDeformer::UpdateVertices(int inZone, std::span<const std::uint32_t> inVertices, DentReport& ioReport)
{
    const FfdLattice& zone = mZones[static_cast<std::size_t>(inZone)];
    double& bound = mZoneDisplacementBound[static_cast<std::size_t>(inZone)];
    // intent: inVertices are the touched cells' buckets in order: where each cell's run starts
    const int offset = mCellOffset[static_cast<std::size_t>(inZone)];
    const std::vector<std::uint32_t>& start = mCellStart[static_cast<std::size_t>(inZone)];
    const std::size_t cells = mTouchedCells.size();
    std::vector<std::size_t> run(cells + 1, 0);
    for (std::size_t c = 0; c < cells; ++c)
    {
        const auto local = static_cast<std::size_t>(mTouchedCells[c] - offset);
        run[c + 1] = run[c] + (start[local + 1] - start[local]);
    }

    // intent: pieces of whole cells, each writing only its own vertices and cells; the zone's bound is a
    // max, exact in any order
    const int pieces = PieceCount(mJobs, inVertices.size(), cMinVerticesPerPiece);
    std::vector<std::size_t> first_cell(static_cast<std::size_t>(pieces) + 1, cells);
    for (int p = 0; p < pieces; ++p)
    {
        const std::size_t begin = inVertices.size() * static_cast<std::size_t>(p) / static_cast<std::size_t>(pieces);
        first_cell[static_cast<std::size_t>(p)] =
            static_cast<std::size_t>(std::lower_bound(run.begin(), run.end() - 1, begin) - run.begin());
    }
    std::vector<double> piece_bound(static_cast<std::size_t>(pieces), 0.0);
    std::vector<CellMotion> piece_moves(
        static_cast<std::size_t>(pieces)); // each piece's union of moves (mMove*)
    const std::vector<LatticeLocation>& locations = mBucketLocations[static_cast<std::size_t>(inZone)];
    const std::vector<Vec3>& rest = mBucketRest[static_cast<std::size_t>(inZone)];
    // intent: a cell's vertices share its 64 controls: with AVX they are copied once per cell, aligned, and each
    // vertex sums the copy (WidePackedTensorProductSum: the same operations as Displacement, so the same bits)
    const bool packed = HasWideTensorProductSum();
    const std::vector<Vec3>& controls = zone.GetControlDisplacements();
    const std::ptrdiff_t row = zone.GetSettings().mControlCount[0], plane = row * zone.GetSettings().mControlCount[1];
    ParallelFor(mJobs, pieces, [&](int inPiece) {
        PackedCellControls cell_controls;
        double largest = 0.0;
        CellMotion moves;
        for (std::size_t c = first_cell[static_cast<std::size_t>(inPiece)]; c < first_cell[static_cast<std::size_t>(inPiece) + 1]; ++c)
        {
            // intent: the largest squared length of a displacement, one square root per cell (sqrt is
            // monotone and correctly rounded, so this is bitwise the largest length), for the zone's bound;
            // and the cell's motion from the stored positions and their offsets from rest (what a probe
            // measures; rounding the sum can make the offset differ from the displacement)
            double cell_largest = 0.0;
            CellMotion motion;
            // intent: the cell's bucket, read in memory order; only the outputs are scattered
            const std::size_t first = start[static_cast<std::size_t>(mTouchedCells[c] - offset)];
            // intent: a cell of one vertex sums from the lattice directly (the copy would cost more than it saves)
            const bool cell_packed = packed && run[c + 1] - run[c] >= 2;
            if (cell_packed)
            {
                const std::array<int, 3>& cell = locations[first].mCell;
                PackCellControls(&controls[static_cast<std::size_t>(zone.ControlIndex(cell[0], cell[1], cell[2]))], row, plane,
                                 cell_controls);
            }
            for (std::size_t i = run[c]; i < run[c + 1]; ++i)
            {
                const std::uint32_t v = inVertices[i];
                const std::size_t k = first + (i - run[c]);
                const Vec3 displacement = cell_packed ? WidePackedTensorProductSum(cell_controls, CellWeightsAt(locations[k].mT))
                                                 : zone.Displacement(locations[k]);
                const Vec3 position = rest[k] + displacement;
                mPositions[v] = position;
                cell_largest = std::max(cell_largest, displacement.squaredNorm());
                motion.Include(position, position - rest[k]);
                mDirty[v] = 1;
            }
            MotionOf(mTouchedCells[c]) = motion;
            moves.mMoveLow = moves.mMoveLow.cwiseMin(motion.mMoveLow);
            moves.mMoveHigh = moves.mMoveHigh.cwiseMax(motion.mMoveHigh);
            largest = std::max(largest, cell_largest);
        }
        piece_bound[static_cast<std::size_t>(inPiece)] = std::sqrt(largest);
        piece_moves[static_cast<std::size_t>(inPiece)] = moves;
    });
    for (double largest : piece_bound)
        bound = std::max(bound, largest);
    // intent: the union only grows here (a cell's moves may shrink): still a bound for every probe
    for (const CellMotion& moves : piece_moves)
    {
        mMoveUnionLow = mMoveUnionLow.cwiseMin(moves.mMoveLow);
        mMoveUnionHigh = mMoveUnionHigh.cwiseMax(moves.mMoveHigh);
    }
    mVertexEvaluations += inVertices.size();
    ioReport.mVerticesMoved += static_cast<std::uint32_t>(inVertices.size());
    UpdateNormalsAround(inVertices, ioReport);
}

Vec3 FfdDeformer::FaceNormal(std::uint32_t inTriangle) const
{
    const auto& t = mRestMesh.mTriangles[inTriangle];
    // Cross product of two edges: length is twice the area, so summing gives area weighting.
    return (mPositions[t[1]] - mPositions[t[0]]).cross(mPositions[t[2]] - mPositions[t[0]]);
}

Vec3 FfdDeformer::VertexNormal(std::uint32_t inVertex) const
{
    if (!mSheetVertices.empty() && mSheetVertices[inVertex] != 0)
    {
        // The largest triangle's normal, as it faces now; of two within round-off of each other (a sheet's
        // two sides) the first in the mesh's order, so that a sheet faces one way throughout, not side by
        // side at random.
        Vec3 largest = Vec3::Zero();
        for (std::uint32_t i = mVertexTriangleStart[inVertex]; i < mVertexTriangleStart[inVertex + 1]; ++i)
            if (const Vec3& face = mFaceNormals[mVertexTriangles[i]];
                face.squaredNorm() > (1.0 + 1.0e-6) * largest.squaredNorm())
                largest = face;
        const double length = largest.norm();
        return length > 0.0 ? Vec3(largest / length) : Vec3::Zero();
    }
    Vec3 sum = Vec3::Zero();
    for (std::uint32_t i = mVertexTriangleStart[inVertex]; i < mVertexTriangleStart[inVertex + 1]; ++i)
        sum += mFaceNormals[mVertexTriangles[i]];
    const double length = sum.norm();
    // An isolated or degenerate vertex has no meaningful normal: report zero rather than NaN.
    return length > 0.0 ? Vec3(sum / length) : Vec3::Zero();
}

namespace
{

// Bit for bit, not by value: -0.0 and +0.0 differ. A write that changes a vertex's bits must mark it dirty,
// or the published copy (and, after Publish swaps buffers, the working one) keeps the old bits.
bool SameBits(const Vec3& inA, const Vec3& inB)
{
    return std::memcmp(inA.data(), inB.data(), sizeof(Vec3)) == 0;
}

} // namespace

void FfdDeformer::UpdateNormalsAround(std::span<const std::uint32_t> inMoved, DentReport& ioReport)
{
    // intent: the triangles with a vertex in a touched cell and their corners (the moved vertices that have a
    // triangle and the ring around the touched cells), each once and ascending: the work then walks the mesh's
    // arrays in memory order, not in the cell order that scatters it over an imported mesh
    std::vector<std::uint32_t> triangles;
    AscendingIndexSet triangle_set(mTriangleBits);
    mSurfaceIndex->InsertTriangles(mTouchedCells, triangle_set);
    triangle_set.TakeAscending(triangles);
    std::vector<std::uint32_t> corners;
    AscendingIndexSet corner_set(mVertexBits);
    for (std::uint32_t v : inMoved)
        if (mVertexTriangleStart[v + 1] != mVertexTriangleStart[v])
            corner_set.Insert(v);
    mSurfaceIndex->InsertRing(mTouchedCells, corner_set);
    corner_set.TakeAscending(corners);
    // Face normals, then the normals of every corner of those triangles (a corner may not have moved
    // itself); each piece writes only its own elements.
    const int face_pieces = PieceCount(mJobs, triangles.size(), cMinVerticesPerPiece);
    ParallelFor(mJobs, face_pieces, [&](int inPiece) {
        for (std::uint32_t f : PieceOf(std::span<const std::uint32_t>(triangles), inPiece, face_pieces))
            mFaceNormals[f] = FaceNormal(f);
    });
    const int corner_pieces = PieceCount(mJobs, corners.size(), cMinVerticesPerPiece);
    ParallelFor(mJobs, corner_pieces, [&](int inPiece) {
        for (std::uint32_t v : PieceOf(std::span<const std::uint32_t>(corners), inPiece, corner_pieces))
        {
            mNormals[v] = VertexNormal(v);
            mDirty[v] = 1;
        }
    });
    ioReport.mTrianglesUpdated += static_cast<std::uint32_t>(triangles.size());
    ioReport.mNormalsUpdated += static_cast<std::uint32_t>(corners.size());
}

void FfdDeformer::RecomputeAll()
{
    CatchUp();
    // intent: the fold guard's trial field follows controls set from outside a dent (Reset, a loaded state)
    for (std::size_t z = 0; z < mZones.size(); ++z)
        mGuardControls[z] = mZones[z].GetControlDisplacements();
    const auto vertex_count = static_cast<std::uint32_t>(mPositions.size());
    std::fill(mZoneDisplacementBound.begin(), mZoneDisplacementBound.end(), 0.0);
    std::fill(mCellMotion.begin(), mCellMotion.end(), CellMotion{});
    mMoveUnionLow = mMoveUnionHigh = Vec3::Zero();
    for (std::uint32_t v = 0; v < vertex_count; ++v)
    {
        const int zone = mVertexZone[v];
        const Vec3 position = zone < 0 ? mRestMesh.mPositions[v]
                                       : Vec3(mRestMesh.mPositions[v] +
                                              mZones[static_cast<std::size_t>(zone)].Displacement(
                                                  mBucketLocations[static_cast<std::size_t>(zone)][mVertexBucket[v]]));
        if (!SameBits(position, mPositions[v]))
            mDirty[v] = 1;
        mPositions[v] = position;
        if (zone >= 0)
        {
            const Vec3 offset = position - mRestMesh.mPositions[v];
            mZoneDisplacementBound[static_cast<std::size_t>(zone)] =
                std::max(mZoneDisplacementBound[static_cast<std::size_t>(zone)], offset.norm());
            MotionOf(mVertexCell[v]).Include(position, offset);
            mMoveUnionLow = mMoveUnionLow.cwiseMin(offset);
            mMoveUnionHigh = mMoveUnionHigh.cwiseMax(offset);
        }
    }
    mVertexEvaluations += vertex_count;
    RecomputeNormals();
    if (mPublishing)
        Publish();
}

void FfdDeformer::SetPublishing(bool inOn)
{
    if (inOn == mPublishing)
        return;
    CatchUp();
    mPublishing = inOn;
    if (inOn)
    {
        mPublishedPositions = mPositions;
        mPublishedNormals = mNormals;
        mPublishedDirty = mDirty;
        std::fill(mDirty.begin(), mDirty.end(), std::uint8_t{0});
        mStaleMarks.assign(mDirty.size(), 0);
    }
    else
    {
        // Back to one state: what was published and not taken stays dirty.
        for (std::size_t v = 0; v < mDirty.size(); ++v)
            mDirty[v] = static_cast<std::uint8_t>(mDirty[v] | mPublishedDirty[v]);
        mPublishedPositions = {};
        mPublishedNormals = {};
        mPublishedDirty = {};
        mStaleMarks = {};
    }
}

void FfdDeformer::Publish()
{
    if (!mPublishing)
        return;
    // intent: one branch-free pass on the game's thread, where dents land. Through local pointers: a byte
    // store may alias anything, so indexing the vectors made the compiler reload their data pointers after
    // every byte and run the pass a byte at a time (0.1 ms on a 67k-vertex car); this one vectorizes.
    std::uint8_t any = 0;
    std::uint8_t* const published = mPublishedDirty.data();
    const std::uint8_t* const dirty = mDirty.data();
    const std::size_t count = mDirty.size();
    for (std::size_t v = 0; v < count; ++v)
    {
        published[v] = static_cast<std::uint8_t>(published[v] | dirty[v]);
        any = static_cast<std::uint8_t>(any | dirty[v]);
    }
    if (any == 0)
        return;
    // intent: whatever marked vertices dirty caught up first, so the working buffers hold the latest state
    // everywhere, and the stale marks are all zero: they become the fresh dirty marks
    CRUMPLE_ASSERT(!mStale, "FfdDeformer::Publish: a change did not catch up with the last Publish");
    mPositions.swap(mPublishedPositions);
    mNormals.swap(mPublishedNormals);
    mDirty.swap(mStaleMarks);
    mStale = true;
}

void FfdDeformer::CatchUp()
{
    if (!mStale)
        return;
    // intent: through local pointers, as in Publish (a byte store would reload every vector's data pointer)
    std::uint8_t* const stale = mStaleMarks.data();
    Vec3* const positions = mPositions.data();
    Vec3* const normals = mNormals.data();
    const Vec3* const published_positions = mPublishedPositions.data();
    const Vec3* const published_normals = mPublishedNormals.data();
    const std::size_t count = mStaleMarks.size();
    for (std::size_t v = 0; v < count; ++v)
        if (stale[v] != 0)
        {
            positions[v] = published_positions[v];
            normals[v] = published_normals[v];
            stale[v] = 0;
        }
    mStale = false;
}

void FfdDeformer::RecomputeNormals()
{
    const auto vertex_count = static_cast<std::uint32_t>(mPositions.size());
    for (std::uint32_t f = 0; f < mFaceNormals.size(); ++f)
        mFaceNormals[f] = FaceNormal(f);
    for (std::uint32_t v = 0; v < vertex_count; ++v)
    {
        const Vec3 normal = VertexNormal(v);
        if (!SameBits(normal, mNormals[v]))
            mDirty[v] = 1;
        mNormals[v] = normal;
    }
}

void FfdDeformer::Reset()
{
    for (FfdLattice& zone : mZones)
        std::fill(zone.GetControlDisplacements().begin(), zone.GetControlDisplacements().end(), Vec3::Zero());
    RecomputeAll();
}

Status FfdDeformer::ValidateControlDisplacements(std::span<const std::vector<Vec3>> inPerZone) const
{
    if (inPerZone.size() != mZones.size())
        return MakeError(EError::StateMismatch, "control state has " + std::to_string(inPerZone.size()) +
                                                    " zones, the deformer " + std::to_string(mZones.size()));
    for (std::size_t z = 0; z < mZones.size(); ++z)
    {
        if (inPerZone[z].size() != static_cast<std::size_t>(mZones[z].GetControlCount()))
            return MakeError(EError::StateMismatch, "zone " + std::to_string(z) + ": control state has " +
                                                        std::to_string(inPerZone[z].size()) + " controls, the lattice " +
                                                        std::to_string(mZones[z].GetControlCount()));
        for (std::size_t c = 0; c < inPerZone[z].size(); ++c)
        {
            if (!IsFinite(inPerZone[z][c]))
                return MakeError(EError::NonFinite,
                                 "zone " + std::to_string(z) + ": a control displacement is not finite");
            // A dent never stores a value in a control that reaches no vertex: a state with one was not
            // written by this library (and would steer later crushes from a control that moves nothing).
            if (mControlReaches[z][c] == 0 && !inPerZone[z][c].isZero(0.0))
                return MakeError(EError::InvalidArgument, "zone " + std::to_string(z) + ": control " + std::to_string(c) +
                                                              " reaches no vertex and must be zero");
        }
    }
    // The state must respect each zone's bound on every vertex, as a dent would.
    for (std::uint32_t v = 0; v < mVertexZone.size(); ++v)
    {
        const int z = mVertexZone[v];
        if (z < 0)
            continue;
        const double limit = mSettings.mZones[static_cast<std::size_t>(z)].mMaxTotalDeformation * (1.0 + 1.0e-9);
        if (mZones[static_cast<std::size_t>(z)]
                .Displacement(mBucketLocations[static_cast<std::size_t>(z)][mVertexBucket[v]], inPerZone[static_cast<std::size_t>(z)])
                .norm() > limit)
            return MakeError(EError::InvalidArgument, "zone " + std::to_string(z) + ": the state moves vertex " +
                                                          std::to_string(v) + " beyond the zone's maximum total deformation");
    }
    return Status::Ok();
}

Status FfdDeformer::SetControlDisplacements(std::span<const std::vector<Vec3>> inPerZone)
{
    // Validate all zones before changing any.
    if (Status valid = ValidateControlDisplacements(inPerZone); !valid)
        return valid;
    for (std::size_t z = 0; z < mZones.size(); ++z)
        mZones[z].GetControlDisplacements() = inPerZone[z];
    RecomputeAll();
    return Status::Ok();
}

std::vector<VertexRange> FfdDeformer::TakeDirtyRanges()
{
    std::vector<std::uint8_t>& dirty = mPublishing ? mPublishedDirty : mDirty;
    std::vector<VertexRange> ranges = VertexRangesFromFlags(dirty);
    std::fill(dirty.begin(), dirty.end(), std::uint8_t{0});
    return ranges;
}

} // namespace crumple::ffd
