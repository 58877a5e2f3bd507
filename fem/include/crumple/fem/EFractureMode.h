// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <cstdint>

namespace crumple::fem
{

/// Which faces of an element group (a 5- or 6-tet cube, or a single tetrahedron) break when its largest
/// principal stress exceeds the material's tensile strength (Rankine's criterion).
enum class EFractureMode : std::uint8_t
{
    /// The crack plane is perpendicular to the principal direction d: the group detaches across each face
    /// whose unit normal n has |n . d| >= cos 55 degrees. A cube pulled along x leaves its two x neighbours
    /// and keeps the others; pulled along a face diagonal it leaves four; along a body diagonal all six
    /// (every direction is within 54.7 degrees of some face normal of a cube, so a cube always cracks).
    CrackPlane,
    /// The whole group detaches from all its neighbours, as in the GPU destruction paper (Morris & Anderson,
    /// section IV.B): brittle, cube-sized debris.
    DetachGroup,
};

/// Short name of an EFractureMode, for messages.
CRUMPLE_API const char* ToString(EFractureMode inMode);

} // namespace crumple::fem
