// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The hand-over worked out on a step's task (PropWorldSettings::mStepOffThread): the fragments and the new
// collision shape the game will ask for between landing the step and starting the next, so that its thread
// does not work them out at the moment a prop breaks (ComputeFragments, PropCollisionPieces: most of the
// fence's hand-over in the racing samples).
#include <crumple/props/PropWorld.h>

#include <algorithm>
#include <cstring>

namespace crumple::props
{

std::vector<std::size_t> PropWorld::LeavingFragments(const Prop& inProp, const std::vector<fem::TetFragment>& inFragments)
{
    // A piece taken before has all its nodes fixed by us: it anchors nothing. The prop is held by a node
    // fixed otherwise; a prop held by none keeps the piece holding group 0 (its body carries it).
    const auto taken = [&](const fem::TetFragment& inPiece)
    {
        const auto element = static_cast<std::size_t>(inPiece.mElements[0]);
        return element < inProp.mTakenElements.size() && inProp.mTakenElements[element] != 0;
    };
    const bool held = std::any_of(inFragments.begin(), inFragments.end(),
                                  [&](const fem::TetFragment& inPiece) { return inPiece.mAnchored && !taken(inPiece); });
    std::vector<std::size_t> leaving;
    for (std::size_t f = 0; f < inFragments.size(); ++f)
        if (!inFragments[f].mAnchored && (held || f != 0))
            leaving.push_back(f);
    return leaving;
}

bool PropWorld::ShapeChanged(const Prop& inProp, std::span<const Vec3> inPositions, double inTolerance)
{
    bool changed = inProp.mShapeRevision != inProp.mPiecesTaken || inProp.mShapePositions.size() != inPositions.size();
    for (std::size_t node = 0; node < inPositions.size() && !changed; ++node)
        changed = (inPositions[node] - inProp.mShapePositions[node]).squaredNorm() > inTolerance * inTolerance;
    return changed;
}

void PropWorld::ForecastHandOver(Prop& ioProp)
{
    // intent: reads only the prop and what the game's thread writes while no step is in flight (what was
    // taken and settled, the last shape's arguments); never the damage world, whose bodies the engine moves
    HandOverForecast& forecast = ioProp.mForecast;
    forecast.mBrokenLinks = ioProp.mProp.GetBrokenLinkCount();
    forecast.mElements = ioProp.mProp.GetElementNodes();
    ioProp.mProp.ReadPositions(forecast.mPositions);
    forecast.mInverseMasses = ioProp.mProp.GetInverseMasses();
    // intent: the fragments once the game takes loose pieces (it has settled the prop once), and only while
    // they can have changed
    forecast.mHasFragments = ioProp.mSettledBrokenLinks >= 0 && !IsSettled(ioProp);
    forecast.mFragments.clear();
    if (forecast.mHasFragments)
        forecast.mFragments = ioProp.mProp.ComputeFragments();
    // intent: the shape once the pieces foreseen have left (what TakeLooseFragments then takes: their
    // elements), when the game asks for shapes and this one changed
    forecast.mHasPieces = false;
    forecast.mPieces.clear();
    if (ioProp.mShapeTolerance < 0.0)
        return;
    forecast.mTakenElements = ioProp.mTakenElements;
    forecast.mTakenElements.resize(forecast.mElements.size(), 0);
    forecast.mPiecesTaken = ioProp.mPiecesTaken;
    if (forecast.mHasFragments)
        for (std::size_t f : LeavingFragments(ioProp, forecast.mFragments))
        {
            ++forecast.mPiecesTaken;
            for (int element : forecast.mFragments[f].mElements)
                forecast.mTakenElements[static_cast<std::size_t>(element)] = 1;
        }
    if (forecast.mPiecesTaken == ioProp.mPiecesTaken && !ShapeChanged(ioProp, forecast.mPositions, ioProp.mShapeTolerance))
        return;
    if (Result<std::vector<std::vector<Vec3>>> pieces =
            PiecesOf(ioProp, forecast.mTakenElements, forecast.mPositions, ioProp.mShapeCellSize);
        pieces)
    {
        forecast.mHasPieces = true;
        forecast.mPieces = std::move(pieces).Get();
        forecast.mCellSize = ioProp.mShapeCellSize;
    }
}

bool PropWorld::ForecastHolds(const Prop& inProp, std::span<const Vec3> inPositions, bool inSameFixedNodes)
{
    // intent: positions bit for bit (-0.0 and +0.0 give the same cubes but other pieces' bits), the elements'
    // nodes themselves (fracture renumbers them; the broken links' count is the quick test)
    const HandOverForecast& forecast = inProp.mForecast;
    return forecast.mBrokenLinks == inProp.mProp.GetBrokenLinkCount() &&
           inPositions.size() == forecast.mPositions.size() &&
           std::memcmp(inPositions.data(), forecast.mPositions.data(), inPositions.size() * sizeof(Vec3)) == 0 &&
           forecast.mElements == inProp.mProp.GetElementNodes() &&
           (!inSameFixedNodes || forecast.mInverseMasses == inProp.mProp.GetInverseMasses());
}

bool PropWorld::ShapeForecastHolds(const Prop& inProp, std::span<const Vec3> inPositions, double inCellSize)
{
    const HandOverForecast& forecast = inProp.mForecast;
    return forecast.mHasPieces && forecast.mCellSize == inCellSize &&
           forecast.mPiecesTaken == inProp.mPiecesTaken &&
           SameTaken(forecast.mTakenElements, inProp.mTakenElements) &&
           ForecastHolds(inProp, inPositions, false);
}

bool PropWorld::SameTaken(std::span<const std::uint8_t> inA, std::span<const std::uint8_t> inB)
{
    const std::size_t common = std::min(inA.size(), inB.size());
    const auto none = [](std::span<const std::uint8_t> inRest) {
        return std::all_of(inRest.begin(), inRest.end(), [](std::uint8_t inTaken) { return inTaken == 0; });
    };
    return std::equal(inA.begin(), inA.begin() + static_cast<std::ptrdiff_t>(common), inB.begin()) &&
           none(inA.subspan(common)) && none(inB.subspan(common));
}

} // namespace crumple::props
