// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// crumple-fuzz-seeds DIR: writes the seed corpus of each fuzz target with the project's own writers, into
// DIR/replay, DIR/prop_replay, DIR/damage_state, DIR/hex_compliance, DIR/tetgen_output and DIR/surface_mesh. (The scenario target's seeds are
// the shipped scenario files.)
#include "FuzzWorld.h"

#include <crumple/base/FileBytes.h>
#include <crumple/plugin/DamageRecorder.h>
#ifdef CRUMPLE_FUZZ_PROPS
#include <crumple/fem/TetGrid.h>
#include <crumple/props/HeldFemProp.h>
#include <crumple/props/PropWorld.h>
#endif
#ifdef CRUMPLE_FUZZ_FEM
#include <crumple/fem/HexComplianceFile.h>
#include <crumple/fem/HexCompliancePrecompute.h>
#include <crumple/fem/HexNodesInBox.h>
#include <crumple/fem/HexStaticPrecompute.h>
#include <crumple/fem/SurfaceFile.h>
#endif
#ifdef CRUMPLE_FUZZ_FEM_IMPORT
#include <crumple/fem_import/TetgenOutput.h>
#endif

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

using namespace crumple;

namespace
{

bool Write(const std::filesystem::path& inPath, std::span<const std::byte> inBytes)
{
    std::filesystem::create_directories(inPath.parent_path());
    return WriteFileAtomically(inPath, inBytes, "crumple-fuzz-seeds").IsValid();
}

#ifdef CRUMPLE_FUZZ_FEM
// A surface file with the target's extension byte in front (see FuzzSurfaceMesh.cpp).
#ifdef CRUMPLE_FUZZ_PROPS
// A recording with a brittle panel standing in for the wall, its FEM under inSettings: its setup, the hit,
// three prop steps, with inTakeLoose the loose pieces taken (a PLOS record), a fourth step, with inRemove the
// panel removed (a PREM record) and a fifth step. inSpread: the panel's contact spread radius (m; 0: none,
// and no SPRD tag).
bool WritePanelSeed(const std::filesystem::path& inPath, const fem::TetSolverSettings& inSettings,
                    bool inTakeLoose, double inSpread = 0.0, bool inRemove = false)
{
    fuzz::FuzzWorld world;
    Result<std::unique_ptr<plugin::DamageRecorder>> recorder =
        plugin::DamageRecorder::Create(inPath, world.Get());
    Result<std::unique_ptr<props::PropWorld>> prop_world = props::PropWorld::Create(world.Get());
    if (!recorder.IsValid() || !prop_world.IsValid())
        return false;
    fem::TetGridSettings grid;
    grid.mOrigin = Vec3(2.1, -1.0, -1.0);
    grid.mSize = Vec3(0.2, 2.0, 2.0);
    grid.mCellCount = {1, 4, 4};
    fem::FemMaterialSettings material;
    material.mTensileStrength = 2.0e5; // weak enough that the hit knocks pieces loose
    Result<props::FemProp> panel = props::FemProp::Create(nullptr, fem::TetGrid(grid).Get(), material,
                                                          inSettings, props::FemPropSettings{});
    bool ok = panel.IsValid() && (inSpread == 0.0 || panel.Get().SetContactSpread(inSpread).IsValid()) &&
              prop_world.Get()->AttachRecorder(recorder.Get().get()).IsValid() &&
              prop_world.Get()->AddProp(world.GetWall(), std::move(panel).Get()).IsValid();
    world.Dent();
    for (int step = 0; ok && step < 3; ++step)
        ok = prop_world.Get()->Step(1.0 / 60.0).IsValid();
    if (inTakeLoose)
        ok = ok && prop_world.Get()->TakeLooseFragments().IsValid();
    ok = ok && prop_world.Get()->Step(1.0 / 60.0).IsValid();
    if (inRemove)
        ok = ok && prop_world.Get()->RemoveProp(props::PropId{0}).IsValid() &&
             prop_world.Get()->Step(1.0 / 60.0).IsValid();
    return ok && prop_world.Get()->AttachRecorder(nullptr).IsValid() && recorder.Get()->Close().IsValid();
}
#endif

bool WriteSurfaceSeed(const std::filesystem::path& inFolder, const std::string& inName, std::uint8_t inExtension,
                      bool inPly)
{
    const std::filesystem::path plain = inFolder / (inName + (inPly ? ".ply" : ".obj"));
    const std::vector<Vec3> corners{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const std::vector<fem::TriangleIndices> faces{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    std::filesystem::create_directories(inFolder);
    if ((inPly ? fem::SaveSurfacePly(plain, corners, faces) : fem::SaveSurfaceObj(plain, corners, faces)).HasError())
        return false;
    std::ifstream in(plain, std::ios::binary);
    std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::filesystem::remove(plain);
    bytes.insert(bytes.begin(), static_cast<char>(inExtension));
    return Write(inFolder / inName, std::as_bytes(std::span(bytes.data(), bytes.size())));
}
#endif

} // namespace

int main(int argc, char** argv)
{
    if (argc != 2)
    {
        std::fprintf(stderr, "usage: crumple-fuzz-seeds DIR\n");
        return 2;
    }
    const std::filesystem::path out = argv[1];
    bool ok = true;

    // A recording of the box car's wall hit, and its damage before and after.
    {
        fuzz::FuzzWorld world;
        ok = ok && Write(out / "damage_state" / "undamaged", world.Get().SaveDamage());
        std::filesystem::create_directories(out / "replay");
        Result<std::unique_ptr<plugin::DamageRecorder>> recorder =
            plugin::DamageRecorder::Create(out / "replay" / "wall_hit.crumple", world.Get());
        ok = ok && recorder.IsValid();
        world.Dent();
        ok = ok && recorder.IsValid() && recorder.Get()->Close().IsValid();
        ok = ok && Write(out / "damage_state" / "dented", world.Get().SaveDamage());
    }

#ifdef CRUMPLE_FUZZ_PROPS
    // Recordings with a brittle panel standing in for the wall: the loose pieces taken (a PLOS record), and
    // under gravity on a ground at its foot (its record carries the ground's tag).
    std::filesystem::create_directories(out / "prop_replay");
    fem::TetSolverSettings weightless;
    weightless.mGravity = Vec3::Zero();
    ok = ok && WritePanelSeed(out / "prop_replay" / "panel_hit.crumple", weightless, true);
    fem::TetSolverSettings grounded;
    grounded.mGround = fem::GroundPlane{true, Vec3::UnitZ(), -1.0, 0.6};
    ok = ok && WritePanelSeed(out / "prop_replay" / "panel_on_ground.crumple", grounded, false);
    // A held prop's settings (the factored preconditioner refreshed by cost: an RCST tag) and a contact
    // spread (an SPRD tag): every optional setting's record but the ground's.
    ok = ok && WritePanelSeed(out / "prop_replay" / "held_panel_spread.crumple",
                              props::HeldPropSolverSettings(), true, 0.3);
    // The panel removed after its pieces were taken (a PREM record; PropWorld::RemoveProp).
    ok = ok && WritePanelSeed(out / "prop_replay" / "panel_removed.crumple", weightless, true, 0.0, true);
#endif

#ifdef CRUMPLE_FUZZ_FEM
    // The compliance of a small clamped steel bar's tip.
    {
        fem::HexMeshSettings settings;
        settings.mSize = Vec3(0.5, 0.1, 0.1);
        settings.mCellCount = {5, 2, 2};
        const fem::HexMesh mesh = fem::HexMesh::Create(settings).Get();
        const fem::HexMaterial steel = fem::HexMaterial::Create({}).Get();
        const std::vector<int> clamp = fem::HexNodesInBox(mesh, Vec3(0.0, -1.0, -1.0), Vec3(0.0, 1.0, 1.0));
        const fem::HexStaticData data = fem::HexStaticPrecompute(mesh, steel, clamp).Get();
        const std::vector<int> tip = fem::HexNodesInBox(mesh, Vec3(0.5, -1.0, -1.0), Vec3(0.5, 1.0, 1.0));
        const Result<std::vector<std::byte>> bytes = fem::EncodeHexCompliance(fem::HexCompliancePrecompute(data, tip, {}).Get());
        ok = ok && bytes.IsValid() && Write(out / "hex_compliance" / "steel_bar_tip", bytes.Get());
    }

    // A tetrahedron's surface as OBJ (extension byte 0) and PLY (1).
    ok = ok && WriteSurfaceSeed(out / "surface_mesh", "tetrahedron_obj", 0, false);
    ok = ok && WriteSurfaceSeed(out / "surface_mesh", "tetrahedron_ply", 1, true);
#endif

#ifdef CRUMPLE_FUZZ_FEM_IMPORT
    // tetgen's output for a unit cube split into five tetrahedra, numbered from 1 as tetgen does by default,
    // and the same from 0 (-z): .node text, a NUL, .ele text (see FuzzTetgenOutput.cpp).
    for (int base : {0, 1})
    {
        std::string text = "8 3 0 0\n";
        for (int i = 0; i < 8; ++i)
            text += std::to_string(i + base) + " " + std::to_string(i & 1) + " " + std::to_string((i >> 1) & 1) + " " +
                    std::to_string((i >> 2) & 1) + "\n";
        text.push_back('\0');
        const int tets[5][4] = {{0, 1, 3, 5}, {0, 3, 2, 6}, {0, 5, 4, 6}, {3, 5, 6, 7}, {0, 3, 5, 6}};
        text += "# five tetrahedra\n5 4 0\n";
        for (int t = 0; t < 5; ++t)
            text += std::to_string(t + base) + " " + std::to_string(tets[t][0] + base) + " " + std::to_string(tets[t][1] + base) +
                    " " + std::to_string(tets[t][2] + base) + " " + std::to_string(tets[t][3] + base) + "\n";
        // A seed the reader refuses would only fuzz its first error path.
        const std::size_t split = text.find('\0');
        ok = ok && fem::ParseTetgenOutput(std::string_view(text).substr(0, split), std::string_view(text).substr(split + 1)).IsValid();
        ok = ok && Write(out / "tetgen_output" / ("cube_from_" + std::to_string(base)),
                         std::as_bytes(std::span(text.data(), text.size())));
    }

#endif

    if (!ok)
    {
        std::fprintf(stderr, "crumple-fuzz-seeds: could not write the seeds into %s\n", out.string().c_str());
        return 1;
    }
    std::printf("crumple-fuzz-seeds: seeds written into %s\n", out.string().c_str());
    return 0;
}
