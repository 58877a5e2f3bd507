// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Fuzz target: tetgen's output files (ParseTetgenOutput, what Tetrahedralize reads back from the tetgen
// process). The input is the .node text, a NUL byte, then the .ele text.
#include <crumple/fem_import/TetgenOutput.h>

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* inData, std::size_t inSize)
{
    const std::string_view text(reinterpret_cast<const char*>(inData), inSize);
    const std::size_t split = text.find('\0');
    const std::string_view nodes = text.substr(0, split);
    const std::string_view elements = split == std::string_view::npos ? std::string_view() : text.substr(split + 1);
    (void)crumple::fem::ParseTetgenOutput(nodes, elements);
    return 0;
}
