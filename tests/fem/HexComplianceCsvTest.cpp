// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "ScratchDirectory.h"

#include <crumple/fem/HexComplianceCsv.h>
#include <crumple/fem/HexCompliancePrecompute.h>
#include <crumple/fem/HexNodesInBox.h>
#include <crumple/fem/HexStaticPrecompute.h>

#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>

using namespace crumple;
using namespace crumple::fem;

namespace
{

// A small clamped steel bar and the compliance of its tip face onto every node.
HexCompliance TipCompliance()
{
    HexMeshSettings settings;
    settings.mSize = Vec3(0.5, 0.1, 0.1);
    settings.mCellCount = {5, 2, 2};
    const HexMesh mesh = HexMesh::Create(settings).Get();
    const HexMaterial steel = HexMaterial::Create({}).Get();
    const std::vector<int> clamp = HexNodesInBox(mesh, Vec3(0.0, -1.0, -1.0), Vec3(0.0, 1.0, 1.0));
    const HexStaticData data = HexStaticPrecompute(mesh, steel, clamp).Get();
    const std::vector<int> tip = HexNodesInBox(mesh, Vec3(0.5, -1.0, -1.0), Vec3(0.5, 1.0, 1.0));
    return HexCompliancePrecompute(data, tip, {}).Get();
}

} // namespace

TEST_CASE("Hex compliance CSV lists every entry with its nodes and axes", "[fem][hex]")
{
    const HexCompliance compliance = TipCompliance();
    const std::filesystem::path path = common::ScratchDirectory() / "hex_compliance.csv";
    REQUIRE(WriteHexComplianceCsv(path, compliance));
    std::ifstream in(path);
    std::string line;
    REQUIRE(std::getline(in, line));
    CHECK(line == "output_node,output_axis,load_node,load_axis,compliance_m_per_n");
    std::size_t count = 0;
    bool found = false;
    // Load 4 is the tip-centre node 29; its own z compliance (row 3 * 29 + 2, column 3 * 4 + 2) reads back exactly.
    const int tip_node = compliance.mLoadNodes[4];
    REQUIRE(tip_node == 29);
    const double expected = compliance.mMatrix(3 * 29 + 2, 3 * 4 + 2);
    while (std::getline(in, line))
    {
        ++count;
        std::istringstream fields(line);
        std::string output_node, output_axis, load_node, load_axis, value;
        std::getline(fields, output_node, ',');
        std::getline(fields, output_axis, ',');
        std::getline(fields, load_node, ',');
        std::getline(fields, load_axis, ',');
        std::getline(fields, value);
        if (output_node == "29" && output_axis == "z" && load_node == std::to_string(tip_node) && load_axis == "z")
        {
            found = true;
            CHECK(std::stod(value) == expected);
        }
    }
    CHECK(count == 27 * 162);
    CHECK(found);
    // The tip of a 0.5 m steel bar, Timoshenko: L^3 / (3 E I) + L / (kappa G A) = 2.565e-8 m/N; the coarse
    // 5 x 2 x 2 mesh with its clamped root is 4.5 % stiffer.
    const double beam = 0.125 / (3.0 * 200.0e9 * 1.0e-4 / 12.0) + 0.5 / (5.0 / 6.0 * 200.0e9 / 2.6 * 0.01);
    CHECK(expected == Approx(beam).epsilon(0.06));
}

TEST_CASE("Hex compliance CSV refuses an inconsistent compliance and leaves the old file", "[fem][hex]")
{
    const HexCompliance compliance = TipCompliance();
    const std::filesystem::path path = common::ScratchDirectory() / "hex_compliance_kept.csv";
    REQUIRE(WriteHexComplianceCsv(path, compliance));
    const auto size = std::filesystem::file_size(path);
    HexCompliance broken = compliance;
    broken.mOutputNodes.pop_back();
    CHECK(WriteHexComplianceCsv(path, broken).GetError().mCode == EError::InvalidArgument);
    CHECK(WriteHexComplianceCsv("", compliance).GetError().mCode == EError::InvalidArgument);
    CHECK(WriteHexComplianceCsv(common::ScratchDirectory() / "no_such_dir" / "x.csv", compliance).GetError().mCode ==
          EError::IoError);
    CHECK(std::filesystem::file_size(path) == size);
}
