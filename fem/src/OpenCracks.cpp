// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/OpenCracks.h>

#include <cmath>
#include <string>

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

// What OpenCracks reads checked before anything breaks: sizes, every face's element and corner slots, every
// element's nodes (O(#faces + #T), a fraction of the stress pass that precedes each call).
Status CheckCrackInputs(const FractureLinks& inLinks, std::span<const PrincipalStress> inPrincipal,
                        std::span<const TetIndices> inElementNodes, std::span<const Vec3> inPositions,
                        std::span<const std::uint8_t> inBroken)
{
    const auto links = static_cast<std::size_t>(inLinks.GetLinkCount());
    if (inPrincipal.size() != static_cast<std::size_t>(inLinks.GetGroupCount()) || inBroken.size() != links ||
        inLinks.mLinkRestNormals.size() != links || inLinks.mLinkFaceOffsets.size() != links + 1 ||
        inLinks.mLinkFaceOffsets.front() != 0 || static_cast<std::size_t>(inLinks.mLinkFaceOffsets.back()) != inLinks.mLinkFaces.size())
        return MakeError(EError::InvalidArgument, "OpenCracks: the stresses (#G), broken flags (#L) or the links' faces do not fit the links");
    for (std::size_t link = 0; link < links; ++link)
    {
        const std::array<int, 2>& groups = inLinks.mLinkGroups[link];
        if (inLinks.mLinkFaceOffsets[link] > inLinks.mLinkFaceOffsets[link + 1] || groups[0] < 0 || groups[1] < 0 ||
            groups[0] >= inLinks.GetGroupCount() || groups[1] >= inLinks.GetGroupCount())
            return MakeError(EError::InvalidArgument, "OpenCracks: link " + std::to_string(link) + " is malformed");
    }
    for (const FractureLinkFace& face : inLinks.mLinkFaces)
        if (face.mElement < 0 || static_cast<std::size_t>(face.mElement) >= inElementNodes.size() || face.mCorners[0] > 3 ||
            face.mCorners[1] > 3 || face.mCorners[2] > 3)
            return MakeError(EError::OutOfRange, "OpenCracks: a link face names an element or corner slot out of range");
    for (std::size_t tet = 0; tet < inElementNodes.size(); ++tet)
        for (int node : inElementNodes[tet])
            if (node < 0 || static_cast<std::size_t>(node) >= inPositions.size())
                return MakeError(EError::OutOfRange, "OpenCracks: element " + std::to_string(tet) + " names node " +
                                                         std::to_string(node) + " of " + std::to_string(inPositions.size()));
    return Status::Ok();
}

} // namespace

Result<int> OpenCracks(const FractureLinks& inLinks, std::span<const PrincipalStress> inPrincipal,
                       std::span<const TetIndices> inElementNodes, std::span<const Vec3> inPositions,
                       double inTensileStrength, EFractureMode inMode, std::span<std::uint8_t> ioBroken)
{
    if (Status valid = CheckCrackInputs(inLinks, inPrincipal, inElementNodes, inPositions, ioBroken); !valid)
        return valid.GetError();
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
