// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Assert.h>
#include <crumple/base/Export.h>

#include <crumple/base/JobSystem.h>
#include <crumple/base/Result.h>
#include <crumple/ffd/DentReport.h>
#include <crumple/ffd/FfdDeformerSettings.h>
#include <crumple/ffd/FfdLattice.h>
#include <crumple/ffd/PointDisplacement.h>
#include <crumple/ffd/SurfaceProbe.h>
#include <crumple/ffd/TriangleMesh.h>
#include <crumple/ffd/VertexGroup.h>
#include <crumple/ffd/VertexRange.h>

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <span>
#include <vector>

namespace crumple::ffd
{

/// A vertex whose triangles' normals cancel to within this fraction of their summed areas has no normal of
/// its own (both sides of a double-sided sheet on the same vertices: the sum is round-off and points
/// anywhere): FfdDeformer gives it its largest triangle's.
inline constexpr double cSheetCancellation = 1.0e-3;

class CellSurfaceIndex;

/// Dents a render mesh through one or more FFD zones by direct manipulation (D4MD section 6.2).
///
/// Each vertex is bound once to the first zone whose box holds its rest position: its cell and local
/// parameter are precomputed and it is bucketed by cell. A dent solves dC = B^+ dP per zone, then
/// recomputes only the vertices in cells that a changed control reaches (a control reaches 4 cells per
/// axis), the face normals of their triangles and the normals of those triangles' vertices. The rest mesh
/// is kept, so damage can be reset or restored exactly. Not thread-safe; one deformer per object.
class CRUMPLE_API FfdDeformer
{
public:
    /// Most lattice cells over all zones (each costs about 70 bytes of index, and a cell that holds vertices 96
    /// more for where they are: CellMotion): 2^24, a 256^3 lattice
    static constexpr std::int64_t cMaxCellsInZones = std::int64_t{1} << 24;

    /// Validates the mesh and zones (at most cMaxCellsInZones cells in all) and binds vertices.
    static Result<FfdDeformer> Create(TriangleMesh inRestMesh, const FfdDeformerSettings& inSettings);

    /// Moves each point by its displacement (body frame, m), accumulating onto earlier dents.
    /// Points are assigned to zones, and a zone's points closer than mMergeDistance cells merge (their
    /// displacements averaged). A zone left with more than 1,024 points merges them further on a grid of
    /// lattice bins, from 1/4 cell wide up, until they fit (a cubic B-spline follows no finer detail, and the
    /// solve's cost grows with the square of the points: 4,096 took 4.7 s); DentReport::mPointsMerged counts
    /// both. Each zone solves its own minimum-norm system dC = B^+ dP. If the
    /// resulting field would move a vertex by more than inMaxStep, or beyond the zone's maximum total
    /// deformation, the zone's dC is scaled down uniformly (the dent keeps its shape) to the largest factor
    /// that respects both on every vertex. Then, unless mMinControlSpacing is 0, the fold guard (FoldGuard.h)
    /// pushes along any control that the scaled dent would push closer than that to its neighbour on a
    /// lattice line, and the bounds are checked again on the guarded dent, so the surface cannot fold.
    /// A NaN/Inf anywhere, or a displacement beyond cMaxMeshCoordinate, refuses the whole dent and changes
    /// nothing.
    /// A dent whose displacements are all zero changes no byte.
    /// @param[in] inMaxStep  bound on how far this dent may move any vertex (m), >= 0
    Result<DentReport> ApplyDent(std::span<const PointDisplacement> inPoints,
                                 double inMaxStep = std::numeric_limits<double>::infinity());

    /// Adds inDelta (one row per control, body frame, m) to the displacements of inControls (indices of
    /// inZone, ascending and unique), for a caller that builds the control field itself (a crush field,
    /// plugin::CampbellCrush) instead of asking for point displacements. The same bounds as ApplyDent
    /// follow: the change is scaled down as a whole to respect inMaxStep and the zone's maximum total
    /// deformation, and the fold guard runs. Bad input refuses the whole change and changes nothing.
    Result<DentReport> ApplyControlDelta(int inZone, std::span<const int> inControls, const Eigen::MatrixX3d& inDelta,
                                         double inMaxStep = std::numeric_limits<double>::infinity());

    /// Restores the undeformed mesh (all control displacements zero). Marks changed vertices dirty.
    void Reset();

    /// Recomputes every vertex and normal from the control displacements (the reference that the
    /// incremental update must equal; also used after a load).
    void RecomputeAll();

    /// Replaces all control displacements (one vector per zone, in ControlIndex order), e.g. from a saved
    /// state. Refused, changing nothing, when counts differ, a value is not finite or exceeds its zone's
    /// maximum total deformation.
    Status SetControlDisplacements(std::span<const std::vector<Vec3>> inPerZone);
    /// The checks of SetControlDisplacements without the change, so a caller holding several deformers
    /// can validate all of them before changing any.
    Status ValidateControlDisplacements(std::span<const std::vector<Vec3>> inPerZone) const;

    /// Deformed positions, body frame (m), #V: the published ones while publishing (SetPublishing)
    const std::vector<Vec3>& GetPositions() const { return mPublishing ? mPublishedPositions : mPositions; }
    /// Unit vertex normals (area-weighted), body frame, #V: the published ones while publishing
    const std::vector<Vec3>& GetNormals() const { return mPublishing ? mPublishedNormals : mNormals; }
    /// The positions dents work on: ahead of GetPositions() while a deferred dent is not yet published. The
    /// array may be another after any change or Publish: take it again rather than keep the reference.
    const std::vector<Vec3>& GetCurrentPositions() const { return mStale ? mPublishedPositions : mPositions; }

    /// Deferred publishing (plugin::DamageWorldSettings::mDeferDents): while on, GetPositions, GetNormals and
    /// the dirty ranges show the state of the last Publish(), which no dent writes, so the game may read
    /// them while a worker dents this deformer. Turning it on publishes the current state; off drops the copy.
    void SetPublishing(bool inOn);
    /// Makes the dents since the last Publish() the published state and marks their vertices for
    /// TakeDirtyRanges. RecomputeAll (Reset, SetControlDisplacements) publishes by itself.
    /// It costs a pass over one byte per vertex, whatever the dents moved: the published and working buffers
    /// trade places, and the next change to this deformer (on the worker that dents it) first copies the
    /// vertices the new working buffer lacks. So the arrays behind GetPositions() and GetNormals() may be
    /// others after a Publish: take them again rather than keep their data pointers.
    void Publish();
    bool IsPublishing() const { return mPublishing; }
    /// The undeformed mesh
    const TriangleMesh& GetRestMesh() const { return mRestMesh; }
    /// Zones, in settings order
    const std::vector<FfdLattice>& GetZones() const { return mZones; }
    const FfdDeformerSettings& GetSettings() const { return mSettings; }
    /// Index of the zone a vertex is bound to, -1 when it is in none (it never moves). An index past the mesh
    /// is a caller's error: the assertions build stops there, a release build answers -1 (no zone moves it)
    /// instead of reading past the array.
    int GetVertexZone(std::uint32_t inVertex) const
    {
        CRUMPLE_ASSERT(inVertex < mVertexZone.size(), "GetVertexZone: the vertex index is past the mesh");
        return inVertex < mVertexZone.size() ? mVertexZone[inVertex] : -1;
    }
    /// Smallest control spacing over all zones (m): the scale below which contacts need no interpolation
    double GetMinSpacing() const;

    /// Probes the current (deformed) surface: the foremost point inside a prism along a direction, and how
    /// far the surface there has moved (SurfaceProbe.h). Exactly the answer of a scan over every vertex and
    /// triangle, found from the cells whose surface meets the prism, nearest first: a cell's surface lies in
    /// its rest reach box (CellSurfaceIndex: its vertices and its triangles' corners) moved by the
    /// displacements of the vertices of its cells (CellMotion). Cells behind the front found so far are
    /// skipped, and so are their vertices once none of them can have moved further along the probe. A probe
    /// that is not finite finds nothing.
    SurfaceProbeResult ProbeSurface(const SurfaceProbe& inProbe) const;

    /// Hands inVisit the vertices in groups, each with a box that holds their current positions
    /// (GetCurrentPositions; VertexGroup): the vertices of each lattice cell that holds any, with the box of
    /// their current positions (their own extremes, mMoved 0), zone by zone, in slices across the lattice axis
    /// nearest inFirstAlong, the slice foremost along it first (so a scan that keeps a front meets it early);
    /// then the vertices in no zone (unbounded: they never moved). Every vertex comes once. For a scan over
    /// the surface that skips what a box rules out (plugin's struck front), as
    /// ProbeSurface does.
    void ForEachVertexGroup(const Vec3& inFirstAlong, const std::function<void(const VertexGroup&)>& inVisit) const;

    /// Vertex ranges changed since the last call, then forgets them (for the game's buffer upload).
    std::vector<VertexRange> TakeDirtyRanges();
    /// Vertex ranges changed since the last TakeDirtyRanges, without forgetting them.
    std::vector<VertexRange> PeekDirtyRanges() const { return VertexRangesFromFlags(mPublishing ? mPublishedDirty : mDirty); }

    /// Running count of vertex evaluations (positions recomputed): proves that idle frames do no
    /// per-vertex work without timing anything.
    std::uint64_t GetVertexEvaluationCount() const { return mVertexEvaluations; }

    /// Splits a dent's per-vertex work (positions, normals, bound checks) over the host's workers; null (the
    /// default) runs it on the calling thread. Not owned: it must outlive the deformer's dents. Results are
    /// bitwise identical with any job system (see JobSystem).
    void SetJobSystem(const JobSystem* inJobs) { mJobs = inJobs; }

private:
    FfdDeformer() = default;

    // Where a deformed body-frame point lies in zone inZone, in rest lattice coordinates.
    Vec3 RestLatticeCoordinate(int inZone, const Vec3& inPoint) const;
    // Marks the cells (numbered across zones) that inControls of inZone reach and hold a vertex, and lists
    // them ascending in mTouchedCells; a control (a,b,c) reaches cells a-3..a per axis.
    void TouchCells(int inZone, std::span<const int> inControls);
    // Clears what TouchCells marked.
    void UntouchCells();
    // Vertices bucketed in the touched cells, ascending by cell then vertex.
    std::vector<std::uint32_t> TouchedVertices() const;
    // Largest s in [0, 1] such that moving every vertex in inVertices by s times the field of inDelta
    // (control changes over inControls) respects inMaxStep and the zone's maximum total deformation.
    double DentScale(int inZone, std::span<const int> inControls, const Eigen::MatrixX3d& inDelta,
                     std::span<const std::uint32_t> inVertices, double inMaxStep);
    // Scales (DentScale), fold-guards (FoldGuard) and commits a change of the zone's controls, then updates
    // the vertices it reaches; the report gathers scale, counts and vertex work.
    void CommitZoneDelta(int inZone, std::span<const int> inControls, const Eigen::MatrixX3d& inDelta,
                         double inMaxStep, DentReport& ioReport);
    // Recompute positions of inVertices (the touched cells' vertices) from the zone's controls, then the
    // normals around the touched cells.
    void UpdateVertices(int inZone, std::span<const std::uint32_t> inVertices, DentReport& ioReport);
    // Recompute every face and vertex normal from the current positions, marking changed normals dirty.
    void RecomputeNormals();
    // Recompute face normals of the triangles with a vertex in a touched cell (inMoved: those vertices), then
    // the vertex normals of their corners.
    void UpdateNormalsAround(std::span<const std::uint32_t> inMoved, DentReport& ioReport);
    Vec3 VertexNormal(std::uint32_t inVertex) const;
    Vec3 FaceNormal(std::uint32_t inTriangle) const;
    // After a Publish the working buffers lack the vertices it published (mStale): copies them back from the
    // published ones. Every change to positions, normals or dirty marks calls it first.
    void CatchUp();

    FfdDeformerSettings mSettings;
    TriangleMesh mRestMesh;
    std::vector<FfdLattice> mZones;

    std::vector<Vec3> mPositions;
    std::vector<Vec3> mNormals;
    std::vector<Vec3> mFaceNormals;  ///< Unnormalized (area-weighted) face normals, #F
    std::vector<Vec3> mRestNormals;

    std::vector<int> mVertexZone;                 ///< #V zone index or -1
    std::vector<std::uint32_t> mVertexBucket;     ///< #V: the vertex's place in its zone's buckets (mCellVertices,
                                                  ///< mBucketLocations); 0 for a vertex of no zone
    std::vector<std::vector<std::uint32_t>> mCellStart;    ///< Per zone: CSR offsets, #cells + 1
    std::vector<std::vector<std::uint32_t>> mCellVertices; ///< Per zone: vertices bucketed by cell
    /// Per zone, in mCellVertices order: each vertex's lattice location and rest position, so a dent reads them
    /// in memory order (an imported mesh's vertex order scatters a cell's vertices over the arrays)
    std::vector<std::vector<LatticeLocation>> mBucketLocations;
    std::vector<std::vector<Vec3>> mBucketRest;
    std::vector<int> mCellOffset;                          ///< Per zone: number of its first cell across zones
    std::vector<int> mVertexCell;                          ///< #V: cell across zones, -1 for a vertex of no zone
    std::shared_ptr<const CellSurfaceIndex> mSurfaceIndex; ///< Triangles and rings per cell; immutable, shared by copies
    std::vector<std::vector<std::uint8_t>> mControlReaches; ///< Per zone, per control: 1 when it moves a vertex
    std::vector<std::uint32_t> mVertexTriangleStart;       ///< CSR offsets, #V + 1
    std::vector<std::uint32_t> mVertexTriangles;           ///< Triangles around each vertex
    /// #V, or empty where there is none: 1 where the vertex's triangles' rest normals cancel (both sides of a
    /// double-sided sheet on the same vertices): such a vertex takes its largest triangle's normal, not the
    /// round-off of their sum
    std::vector<std::uint8_t> mSheetVertices;

    // Scratch, all zero (marks) or empty between calls.
    std::vector<int> mTouchedCells;         ///< The cells a change reaches (TouchCells), ascending
    int mTouchedZone = 0;                   ///< The zone of mTouchedCells
    std::vector<std::uint8_t> mDilation[2]; ///< TouchCells' masks over the changed controls' box
    std::vector<std::array<int, 3>> mTouchedControls; ///< TouchCells' (a, b, c) of each changed control
    std::vector<std::uint64_t> mVertexBits;   ///< One bit per vertex (AscendingIndexSet)
    std::vector<std::uint64_t> mTriangleBits; ///< One bit per triangle (AscendingIndexSet)
    std::vector<std::vector<Vec3>> mScratchControls; ///< Per zone, all zero between calls
    std::vector<std::vector<Vec3>> mGuardControls;   ///< Per zone, equal to its controls between calls (fold guard's trial)
    std::vector<double> mZoneDisplacementBound; ///< Per zone: an upper bound of any vertex's displacement (m)
    /// Where a cell's vertices are now and how far they moved: the boxes of their current positions and of
    /// their displacements from rest, each the stored values' own extremes (exact, so a region query that
    /// skips a cell by them skips nothing it would have found). Kept for the cells that hold vertices, where
    /// positions are written (a dent's cells, a full recompute).
    struct CellMotion
    {
        Vec3 mLow = Vec3::Constant(std::numeric_limits<double>::infinity());      ///< Positions, body frame (m)
        Vec3 mHigh = Vec3::Constant(-std::numeric_limits<double>::infinity());    ///< (empty: low > high)
        Vec3 mMoveLow = Vec3::Constant(std::numeric_limits<double>::infinity());  ///< Position - rest (m)
        Vec3 mMoveHigh = Vec3::Constant(-std::numeric_limits<double>::infinity());

        void Include(const Vec3& inPosition, const Vec3& inDisplacement)
        {
            mLow = mLow.cwiseMin(inPosition);
            mHigh = mHigh.cwiseMax(inPosition);
            mMoveLow = mMoveLow.cwiseMin(inDisplacement);
            mMoveHigh = mMoveHigh.cwiseMax(inDisplacement);
        }
    };
    // The motion of cell inCell, one that holds vertices.
    CellMotion& MotionOf(int inCell)
    {
        return mCellMotion[static_cast<std::size_t>(mCellMotionSlot[static_cast<std::size_t>(inCell)])];
    }
    // The motion of cell inCell, or nullptr for a cell without vertices.
    const CellMotion* FindMotion(int inCell) const
    {
        const std::int32_t slot = mCellMotionSlot[static_cast<std::size_t>(inCell)];
        return slot >= 0 ? &mCellMotion[static_cast<std::size_t>(slot)] : nullptr;
    }
    std::vector<CellMotion> mCellMotion;       ///< Per cell holding vertices, in cell order
    std::vector<std::int32_t> mCellMotionSlot; ///< Per cell across zones: its slot in mCellMotion, -1 without vertices
    /// A box holding every cell's displacement box and zero (corners in no zone never move), body frame (m):
    /// grown by each dent, made exact again by a full recompute
    Vec3 mMoveUnionLow = Vec3::Zero(), mMoveUnionHigh = Vec3::Zero();
    /// Per zone, per lattice axis, per slice of cells across that axis: the union of the slice's reach boxes
    /// (rest, body frame, m), so probes skip whole slices.
    struct SliceReach
    {
        std::array<std::vector<Vec3>, 3> mLow, mHigh;
    };
    std::vector<SliceReach> mSlices;

    std::vector<std::uint8_t> mDirty; ///< #V: changed since the last TakeDirtyRanges (publishing: since Publish)
    bool mPublishing = false;
    std::vector<Vec3> mPublishedPositions;      ///< Publishing: what GetPositions shows
    std::vector<Vec3> mPublishedNormals;        ///< Publishing: what GetNormals shows
    std::vector<std::uint8_t> mPublishedDirty;  ///< Publishing: published and not yet taken
    /// Publishing: the vertices mPositions and mNormals lack since the last Publish (it swapped the buffers);
    /// while mStale, the published buffers are the current state. All zero when !mStale.
    std::vector<std::uint8_t> mStaleMarks;
    bool mStale = false;
    const JobSystem* mJobs = nullptr; ///< The host's workers for per-vertex work; null: inline
    std::uint64_t mVertexEvaluations = 0;
};

} // namespace crumple::ffd
