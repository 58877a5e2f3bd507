// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Fuzz target: a surface mesh file for a destructible prop (LoadSurfaceMesh, through assimp). The first
// byte picks the file's extension (assimp chooses its reader by it), the rest is the file.
#include "ScratchDirectory.h"

#include <crumple/fem_import/LoadSurfaceMesh.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* inData, std::size_t inSize)
{
    if (inSize < 1)
        return 0;
    static const std::array<const char*, 6> extensions{".obj", ".ply", ".off", ".stl", ".gltf", ".glb"};
    // intent: a folder of this process, removed when it exits (each corpus run left one behind before)
    static const std::filesystem::path folder = crumple::common::ScratchDirectory();
    const std::filesystem::path file =
        folder / (std::string("input") + extensions[inData[0] % extensions.size()]);
    {
        std::ofstream out(file, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(inData + 1), static_cast<std::streamsize>(inSize - 1));
    }
    // Stopped well inside libFuzzer's -timeout (10 s in the fuzz tests): a parse that loops is refused, not a hang.
    (void)crumple::fem::LoadSurfaceMesh(file, 3.0);
    std::filesystem::remove(file);
    return 0;
}
