// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/HexCompliancePrecompute.h>
#include <crumple/fem/HexComplianceSolve.h>
#include <crumple/fem/HexNodesInBox.h>
#include <crumple/fem/HexSourceCrc.h>
#include <crumple/fem/HexStaticPrecompute.h>
#include <crumple/fem/HexStaticSolve.h>

#include <catch2/catch.hpp>

#include <limits>

using namespace crumple;
using namespace crumple::fem;

namespace
{

// A steel plate 0.4 x 0.4 x 0.02 m, 8 x 8 x 2 cells, clamped along its edge x = 0 and its edge x = 0.4.
struct Plate
{
    HexMesh mMesh = HexMesh::Create(Settings()).Get();
    HexMaterial mMaterial = HexMaterial::Create({}).Get();
    std::vector<int> mFixed = Clamp(mMesh);
    HexStaticData mData = HexStaticPrecompute(mMesh, mMaterial, mFixed).Get();
    std::vector<int> mTop = HexNodesInBox(mMesh, Vec3(-1.0, -1.0, 0.02), Vec3(1.0, 1.0, 0.02));

    static HexMeshSettings Settings()
    {
        HexMeshSettings settings;
        settings.mSize = Vec3(0.4, 0.4, 0.02);
        settings.mCellCount = {8, 8, 2};
        return settings;
    }
    static std::vector<int> Clamp(const HexMesh& inMesh)
    {
        std::vector<int> fixed = HexNodesInBox(inMesh, Vec3(0.0, -1.0, -1.0), Vec3(0.0, 1.0, 1.0));
        const std::vector<int> far = HexNodesInBox(inMesh, Vec3(0.4, -1.0, -1.0), Vec3(0.4, 1.0, 1.0));
        fixed.insert(fixed.end(), far.begin(), far.end());
        return fixed;
    }
};

// Deterministic forces in [-100, 100] N.
Eigen::VectorXd Forces(Eigen::Index inCount)
{
    Eigen::VectorXd forces(inCount);
    for (Eigen::Index i = 0; i < inCount; ++i)
        forces[i] = 100.0 * std::sin(1.7 * static_cast<double>(i) + 0.3);
    return forces;
}

} // namespace

TEST_CASE("Hex compliance dents equal the direct sparse solve", "[fem][hex]")
{
    const Plate plate;
    // Loads: the top surface plus one clamped node (its column must be zero); outputs: all nodes.
    std::vector<int> loads = plate.mTop;
    loads.push_back(plate.mFixed[3]);
    const Result<HexCompliance> compliance = HexCompliancePrecompute(plate.mData, loads, {});
    REQUIRE(compliance.IsValid());
    const HexCompliance& c = compliance.Get();
    CHECK(c.mNodeCount == plate.mMesh.GetNodeCount());
    CHECK(c.mSourceCrc == HexSourceCrc(plate.mMesh, plate.mMaterial, plate.mData.mFixedNodes));
    // The fingerprint tells another material or support apart.
    HexMaterialSettings softer;
    softer.mYoungsModulus = 70.0e9;
    CHECK(c.mSourceCrc != HexSourceCrc(plate.mMesh, HexMaterial::Create(softer).Get(), plate.mData.mFixedNodes));
    CHECK(c.mSourceCrc != HexSourceCrc(plate.mMesh, plate.mMaterial, std::span(plate.mData.mFixedNodes).first(5)));
    CHECK(static_cast<int>(c.mOutputNodes.size()) == plate.mMesh.GetNodeCount());
    REQUIRE(c.mMatrix.rows() == 3 * plate.mMesh.GetNodeCount());
    REQUIRE(c.mMatrix.cols() == 3 * static_cast<Eigen::Index>(loads.size()));
    CHECK(c.mMatrix.rightCols<3>().isZero(0.0));

    // Same forces through the full solve: scatter onto all nodes (the clamped one is ignored by both).
    const Eigen::VectorXd load_forces = Forces(c.mMatrix.cols());
    Eigen::VectorXd all_forces = Eigen::VectorXd::Zero(3 * plate.mMesh.GetNodeCount());
    for (std::size_t l = 0; l < loads.size(); ++l)
        all_forces.segment<3>(3 * loads[l]) = load_forces.segment<3>(3 * static_cast<Eigen::Index>(l));
    const Eigen::VectorXd direct = HexStaticSolve(plate.mData, all_forces).Get();
    const Eigen::VectorXd dent = HexComplianceSolve(c, load_forces).Get();
    const double error = (dent - direct).norm() / direct.norm();
    WARN("compliance vs direct solve: relative error " << error << ", |u| max " << direct.lpNorm<Eigen::Infinity>()
                                                       << " m");
    CHECK(direct.lpNorm<Eigen::Infinity>() > 1.0e-6);
    CHECK(error < 1.0e-10);
}

TEST_CASE("Hex compliance onto chosen output nodes keeps their order and is reciprocal", "[fem][hex]")
{
    const Plate plate;
    const std::vector<int> full_rows(plate.mTop.rbegin(), plate.mTop.rend()); // reversed order on purpose
    const HexCompliance square = HexCompliancePrecompute(plate.mData, plate.mTop, plate.mTop).Get();
    const HexCompliance reversed = HexCompliancePrecompute(plate.mData, plate.mTop, full_rows).Get();
    const Eigen::Index n = static_cast<Eigen::Index>(plate.mTop.size());
    for (Eigen::Index o = 0; o < n; ++o)
        CHECK(reversed.mMatrix.middleRows<3>(3 * o) == square.mMatrix.middleRows<3>(3 * (n - 1 - o)));
    // Maxwell-Betti: the square block of K^-1 is symmetric.
    const double asymmetry = (square.mMatrix - square.mMatrix.transpose()).norm() / square.mMatrix.norm();
    CHECK(asymmetry < 1.0e-12);
    // A clamped output node has zero rows.
    const HexCompliance clamped = HexCompliancePrecompute(plate.mData, plate.mTop, plate.mFixed).Get();
    CHECK(clamped.mMatrix.isZero(0.0));
}

TEST_CASE("Hex compliance refuses bad input", "[fem][hex]")
{
    const Plate plate;
    SECTION("no load nodes, out of range, repeated")
    {
        CHECK(HexCompliancePrecompute(plate.mData, {}, {}).GetError().mCode == EError::InvalidArgument);
        const std::vector<int> out_of_range{1, 100000};
        const Result<HexCompliance> c = HexCompliancePrecompute(plate.mData, out_of_range, {});
        CHECK(c.GetError().mCode == EError::OutOfRange);
        CHECK(c.GetError().mMessage.find("load node 100000") != std::string::npos);
        const std::vector<int> repeated{5, 6, 5};
        CHECK(HexCompliancePrecompute(plate.mData, plate.mTop, repeated).GetError().mMessage.find(
                  "output node 5 is listed twice") != std::string::npos);
        CHECK(HexCompliancePrecompute(HexStaticData{}, plate.mTop, {}).GetError().mCode == EError::InvalidArgument);
    }
    SECTION("forces of the wrong length or NaN, an empty compliance")
    {
        const HexCompliance c = HexCompliancePrecompute(plate.mData, plate.mTop, plate.mTop).Get();
        CHECK(HexComplianceSolve(c, Eigen::VectorXd::Zero(5)).GetError().mCode == EError::InvalidArgument);
        Eigen::VectorXd forces = Eigen::VectorXd::Zero(c.mMatrix.cols());
        forces[2] = std::numeric_limits<double>::infinity();
        CHECK(HexComplianceSolve(c, forces).GetError().mCode == EError::NonFinite);
        CHECK(HexComplianceSolve(HexCompliance{}, Eigen::VectorXd()).GetError().mCode == EError::InvalidArgument);
    }
}
