// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/CellCountForSections.h>
#include <crumple/fem/FemMaterial.h>
#include <crumple/fem/ProceduralEdgeMesh.h>
#include <crumple/fem/PropMaterialPreset.h>
#include <crumple/fem/TetGrid.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace crumple;
using namespace crumple::fem;

namespace
{

constexpr EPropMaterial cAll[] = {EPropMaterial::Glass, EPropMaterial::Wood, EPropMaterial::Brick,
                                  EPropMaterial::Rubber, EPropMaterial::Steel};

} // namespace

TEST_CASE("Every prop material preset is valid and builds a wall", "[fem]")
{
    for (const EPropMaterial material : cAll)
    {
        INFO(ToString(material));
        Result<PropMaterialPreset> preset = MakePropMaterialPreset(material);
        REQUIRE(preset.IsValid());
        const Result<FemMaterial> fem = FemMaterial::Create(preset.Get().mMaterial);
        INFO((fem.HasError() ? fem.GetError().mMessage : std::string()));
        CHECK(fem.IsValid());
        const Status edges = ValidateProceduralEdgeSettings(preset.Get().mEdges);
        INFO((edges.HasError() ? edges.GetError().mMessage : std::string()));
        CHECK(edges.IsValid());
        CHECK(preset.Get().mMaterial.mMassDamping > 0.0); // props come to rest
        CHECK(preset.Get().mMaterial.mStiffnessDamping > 0.0);

        // A 2.4 x 1.3 x 0.1 m wall and a 2 x 0.16 x 0.05 m plank (whose sections CellCountForSections
        // shrinks towards 2/3 of the average height, the tightest case for the edge amplitude).
        for (const Vec3& size : {Vec3(2.4, 1.3, 0.1), Vec3(2.0, 0.16, 0.05)})
        {
            TetGridSettings grid;
            grid.mSize = size;
            grid.mCellCount = CellCountForSections(grid.mSize, preset.Get().mEdges).Get();
            const TetMesh mesh = TetGrid(grid).Get();
            const Result<ProceduralEdgeMesh> wall = ProceduralEdgeMesh::Create(grid, mesh, preset.Get().mEdges);
            INFO((wall.HasError() ? wall.GetError().mMessage : std::string()));
            REQUIRE(wall.IsValid());
            CHECK(wall.Get().GetSections().size() ==
                  static_cast<std::size_t>(grid.mCellCount[0] * grid.mCellCount[1] * grid.mCellCount[2]));
        }
    }
}

TEST_CASE("Prop material presets carry the handbook values", "[fem]")
{
    const PropMaterialPreset glass = MakePropMaterialPreset(EPropMaterial::Glass).Get();
    CHECK(glass.mMaterial.mYoungsModulus == 70.0e9);
    CHECK(glass.mMaterial.mPoissonRatio == 0.22);
    CHECK(glass.mMaterial.mDensity == 2500.0);
    CHECK(glass.mMaterial.mTensileStrength == 50.0e6);
    CHECK(std::isinf(glass.mMaterial.mYieldStress));
    CHECK(glass.mMaterial.mFractureMode == EFractureMode::DetachGroup);
    CHECK(glass.mEdges.mAverageSectionWidth == glass.mEdges.mAverageSectionHeight); // square-ish shards

    // Wood: long thin planks, splinters on the horizontal (long) edges only.
    const PropMaterialPreset wood = MakePropMaterialPreset(EPropMaterial::Wood).Get();
    CHECK(wood.mMaterial.mYoungsModulus == 10.0e9);
    CHECK(wood.mMaterial.mDensity == 500.0);
    CHECK(wood.mMaterial.mTensileStrength == 40.0e6);
    CHECK(wood.mMaterial.mFractureMode == EFractureMode::CrackPlane);
    CHECK(wood.mEdges.mAverageSectionWidth >= 5.0 * wood.mEdges.mAverageSectionHeight);
    CHECK(wood.mEdges.mHorizontalEdgeFrequency > glass.mEdges.mHorizontalEdgeFrequency);
    CHECK(wood.mEdges.mHorizontalEdgeAmplitude > glass.mEdges.mHorizontalEdgeAmplitude);
    CHECK(wood.mEdges.mVerticalEdgeFrequency == 0.0);

    // Brick: brick faces, straight edges, weak mortar.
    const PropMaterialPreset brick = MakePropMaterialPreset(EPropMaterial::Brick).Get();
    CHECK(brick.mEdges.mAverageSectionWidth == 0.215);
    CHECK(brick.mEdges.mAverageSectionHeight == 0.065);
    CHECK(brick.mEdges.mHorizontalEdgeFrequency == 0.0);
    CHECK(brick.mEdges.mVerticalEdgeFrequency == 0.0);
    CHECK(brick.mMaterial.mTensileStrength == 1.5e6);
    CHECK(brick.mMaterial.mDensity == 1900.0);

    // Rubber: soft, nearly incompressible, no plasticity.
    const PropMaterialPreset rubber = MakePropMaterialPreset(EPropMaterial::Rubber).Get();
    CHECK(rubber.mMaterial.mYoungsModulus == 5.0e6);
    CHECK(rubber.mMaterial.mPoissonRatio == 0.49);
    CHECK(std::isinf(rubber.mMaterial.mYieldStress));

    // Steel S235: yields at 235 MPa, tears at 360 MPa.
    const PropMaterialPreset steel = MakePropMaterialPreset(EPropMaterial::Steel).Get();
    CHECK(steel.mMaterial.mYoungsModulus == 210.0e9);
    CHECK(steel.mMaterial.mPoissonRatio == 0.3);
    CHECK(steel.mMaterial.mDensity == 7850.0);
    CHECK(steel.mMaterial.mYieldStress == 235.0e6);
    CHECK(steel.mMaterial.mTensileStrength == 360.0e6);
    CHECK(steel.mMaterial.mMaxPlasticStrain == 0.25);
    CHECK(FemMaterial::Create(steel.mMaterial).Get().IsPlastic());
}

TEST_CASE("EPropMaterial names and unknown values", "[fem]")
{
    CHECK(std::string(ToString(EPropMaterial::Glass)) == "Glass");
    CHECK(std::string(ToString(EPropMaterial::Wood)) == "Wood");
    CHECK(std::string(ToString(EPropMaterial::Brick)) == "Brick");
    CHECK(std::string(ToString(EPropMaterial::Rubber)) == "Rubber");
    CHECK(std::string(ToString(EPropMaterial::Steel)) == "Steel");
    CHECK(std::string(ToString(static_cast<EPropMaterial>(17))) == "unknown");
    const Result<PropMaterialPreset> unknown = MakePropMaterialPreset(static_cast<EPropMaterial>(17));
    REQUIRE(unknown.HasError());
    CHECK(unknown.GetError().mMessage.find("17 is not an EPropMaterial") != std::string::npos);
}
