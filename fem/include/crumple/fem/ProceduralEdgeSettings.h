// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>

#include <cstdint>

namespace crumple::fem
{

/// The material parameters of procedural broken edges (Morris & Anderson, "GPU destruction", section IV.C):
/// a wall-like prop is drawn as one display section per tetrahedral cube, the section boundaries jittered
/// and their edges given random extra vertices so that broken-off pieces show material-like edges.
///
/// Convention: the wall plane is spanned by the two largest axes of the box. "Width" runs along the longer
/// of them (u), "height" along the other (v); the shortest axis is the thickness. Horizontal section edges
/// run along u (their vertices are offset along v), vertical section edges run along v (offset along u).
///
/// Validated by ValidateProceduralEdgeSettings(); ProceduralEdgeMesh::Create() checks it again against the
/// actual cell sizes.
struct CRUMPLE_API ProceduralEdgeSettings
{
    /// Average section width along u (m), > 0: divided into the wall's width to choose the cell count
    double mAverageSectionWidth = 0.25;
    /// Average section height along v (m), > 0
    double mAverageSectionHeight = 0.25;
    /// Random section width: each interior lattice corner moves along u by a uniform random amount within
    /// +- this fraction of the cell width; in [0, cMaxRandomSection)
    double mRandomSectionWidth = 0.15;
    /// Random section height: the same along v, a fraction of the cell height; in [0, cMaxRandomSection)
    double mRandomSectionHeight = 0.15;
    /// Horizontal edge frequency: extra vertices per metre of (nominal) length on interior horizontal section
    /// edges (1/m), >= 0; an edge of length L gets round(f L) of them
    double mHorizontalEdgeFrequency = 8.0;
    /// Vertical edge frequency (1/m), >= 0, the same for interior vertical edges
    double mVerticalEdgeFrequency = 8.0;
    /// Horizontal edge amplitude (m), >= 0: each extra vertex of a horizontal edge is offset along v by a
    /// uniform random amount within +- this. At most cMaxAmplitudeFraction of the smallest possible section
    /// height (1 - 2 mRandomSectionHeight) h
    double mHorizontalEdgeAmplitude = 0.01;
    /// Vertical edge amplitude (m), >= 0: offset along u of the extra vertices of vertical edges. At most
    /// cMaxAmplitudeFraction (1 - 2 mRandomSectionWidth) w
    double mVerticalEdgeAmplitude = 0.01;
    /// Seed of the SplitMix64 stream: the same seed gives a bitwise identical mesh on every platform
    std::uint64_t mSeed = 0;

    /// Upper bound (excluded) of the random section fractions. Below 1/2 the jittered quadrilaterals stay
    /// star-shaped about their nominal centres, so sections cannot cross
    static constexpr double cMaxRandomSection = 0.45;
    /// Largest edge amplitude as a fraction of the smallest possible section size (1 - 2 r) s. Below 1/2 the
    /// horizontal edges of neighbouring rows (and vertical edges of neighbouring columns) stay in disjoint
    /// bands, which is what proves that section outlines never cross or fold (see ProceduralEdgeMesh.cpp);
    /// 0.4 keeps a gap of a fifth of the band between them
    static constexpr double cMaxAmplitudeFraction = 0.4;
};

/// Refuses (naming the field and value) a non-finite value, an average size <= 0, a random fraction outside
/// [0, cMaxRandomSection), a negative frequency or amplitude, a frequency above 1e6 /m, or an amplitude above
/// cMaxAmplitudeFraction (1 - 2 r) times the average section size across its edges (horizontal edge
/// amplitude against the average height, vertical against the average width). Amplitudes are refused, never
/// clamped.
/// @param[in] inSettings  the parameters to check
/// @return Ok, or the first violation found
CRUMPLE_API Status ValidateProceduralEdgeSettings(const ProceduralEdgeSettings& inSettings);

/// Checks the edge amplitudes against actual cell sizes inWidth (along u) and inHeight (along v), in metres:
/// mHorizontalEdgeAmplitude <= cMaxAmplitudeFraction (1 - 2 mRandomSectionHeight) inHeight and
/// mVerticalEdgeAmplitude <= cMaxAmplitudeFraction (1 - 2 mRandomSectionWidth) inWidth. Assumes the settings
/// are otherwise valid.
CRUMPLE_API Status ValidateEdgeAmplitudes(const ProceduralEdgeSettings& inSettings, double inWidth, double inHeight);

} // namespace crumple::fem
