// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <filesystem>
#include <string>

namespace crumple::fem
{

/// How Tetrahedralize runs TetGen (Hang Si, "TetGen, a Delaunay-based quality tetrahedral mesh generator",
/// ACM TOMS 41(2), 2015), version 1.5 as packaged by Debian (apt-get install tetgen, /usr/bin/tetgen).
///
/// Why a separate program and not the library: TetGen is licensed under the AGPL (v3 or later). Crumple is
/// MIT; linking libtet would put every program that links Crumple under the AGPL. Running the unmodified
/// tetgen executable as a separate process, exchanging plain files, keeps the two works separate, so Crumple
/// neither links nor ships TetGen: a user installs it where wanted, and only then is import available.
struct CRUMPLE_API TetgenSettings
{
    /// Smallest accepted nonzero mMaxRadiusEdgeRatio. TetGen proves termination above 2.0; in practice it
    /// terminates down to about 1.1, and below that it may refine forever.
    static constexpr double cMinRadiusEdgeRatio = 1.1;

    /// The program: a bare name is looked up on PATH like a shell would (without running a shell), a name
    /// with a '/' is used as that path.
    std::string mExecutable = "tetgen";
    /// Quality bound (tetgen -q): largest ratio of an element's circumradius to its shortest edge, 0 or >=
    /// cMinRadiusEdgeRatio (lower = better shaped, more elements). tetgen inserts points until the elements
    /// meet it, except elements touching the surface when mKeepSurface forbids splitting it. 0 = no quality
    /// refinement: a constrained Delaunay tetrahedralization of the surface vertices alone, which may hold
    /// slivers that TetMesh refuses. Dimensionless.
    double mMaxRadiusEdgeRatio = 1.5;
    /// Element volume bound (tetgen -a), m^3, >= 0; 0 = no limit; Tetrahedralize refuses one that would take
    /// more than TetMesh::cMaxCount elements to fill the surface. Smaller gives more, smaller elements. Like
    /// mMaxRadiusEdgeRatio it is a target tetgen refines toward, not a guarantee: TetGen 1.5 skips a
    /// refinement point that would crowd the surface, so a few elements may stay above it (an icosphere of
    /// 162 vertices and 0.15 m radius with a 2e-5 m^3 bound: 1 of 2654 elements at 2.06e-5 m^3).
    double mMaxVolume = 0.0;
    /// Keep the surface triangles unsplit (tetgen -Y): the mesh boundary is then exactly the input
    /// triangulation and no node is added on the surface, so a render mesh of the same file matches it vertex
    /// for vertex. false lets tetgen add nodes inside the surface facets (in their planes: the shape and
    /// volume are unchanged), which lets it refine elements at the surface too (the icosphere above: 1280
    /// boundary triangles instead of 320, 795 nodes instead of 283).
    bool mKeepSurface = true;
    /// Parent of the scratch folder tetgen works in (a fresh crumple-tetgen-XXXXXX, always removed
    /// afterwards); empty = std::filesystem::temp_directory_path() (TMPDIR, else /tmp).
    std::filesystem::path mTemporaryDirectory;
};

} // namespace crumple::fem
