// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/OpenCracks.h>

#include <cmath>

namespace crumple::fem
{

namespace
{

// Unit normal of a link's shared face now (area-weighted over its triangles, from group A to B); the rest
// normal when the face has collapsed.
Vec3 CurrentNormal(const FractureLinks& inLinks, int inLink, std::span<const TetIndices> inElementNodes,
                   std::span<const Vec3> inPositions)
{
    Vec3 normal = Vec3::Zero();
    for (int face = inLinks.mLinkFaceOffsets[inLink]; face < inLinks.mLinkFaceOffsets[inLink + 1]; ++face)
    {
        const FractureLinkFace& triangle = inLinks.mLinkFaces[face];
        const TetIndices& nodes = inElementNodes[triangle.mElement];
        const Vec3& x0 = inPositions[nodes[triangle.mCorners[0]]];
        normal += (inPositions[nodes[triangle.mCorners[1]]] - x0).cross(inPositions[nodes[triangle.mCorners[2]]] - x0);
    }
    const double length = normal.norm();
    return length > 0.0 && std::isfinite(length) ? Vec3(normal / length) : inLinks.mLinkRestNormals[inLink];
}

// True when a cracking group's crack plane opens the face with normal inNormal.
bool Opens(const PrincipalStress& inStress, double inTensileStrength, EFractureMode inMode, const Vec3& inNormal)
{
    if (!(inStress.mValue > inTensileStrength))
        return false;
    return inMode == EFractureMode::DetachGroup || std::abs(inNormal.dot(inStress.mDirection)) >= cCrackFaceCosine;
}

} // namespace

int OpenCracks(const FractureLinks& inLinks, std::span<const PrincipalStress> inPrincipal,
               std::span<const TetIndices> inElementNodes, std::span<const Vec3> inPositions,
               double inTensileStrength, EFractureMode inMode, std::span<std::uint8_t> ioBroken)
{
    int broken = 0;
    for (int link = 0; link < inLinks.GetLinkCount(); ++link)
    {
        if (ioBroken[link] != 0)
            continue;
        const PrincipalStress& a = inPrincipal[inLinks.mLinkGroups[link][0]];
        const PrincipalStress& b = inPrincipal[inLinks.mLinkGroups[link][1]];
        if (!(a.mValue > inTensileStrength) && !(b.mValue > inTensileStrength))
            continue; // the cheap test first: neither side is cracking
        const Vec3 normal = CurrentNormal(inLinks, link, inElementNodes, inPositions);
        if (Opens(a, inTensileStrength, inMode, normal) || Opens(b, inTensileStrength, inMode, normal))
        {
            ioBroken[link] = 1;
            ++broken;
        }
    }
    return broken;
}

} // namespace crumple::fem
