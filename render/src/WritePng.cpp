// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/FileBytes.h>
#include <crumple/render/WritePng.h>

#include <string>
#include <vector>

// The one place stb_image_write is compiled; static so a host that also uses stb sees no duplicate symbols.
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

namespace crumple::render
{

namespace
{

/// stb_image_write callback: appends the encoded bytes to a std::vector<unsigned char>.
void AppendBytes(void* ioContext, void* inData, int inSize)
{
    auto& bytes = *static_cast<std::vector<unsigned char>*>(ioContext);
    const auto* data = static_cast<const unsigned char*>(inData);
    bytes.insert(bytes.end(), data, data + inSize);
}

} // namespace

Status WritePng(const std::filesystem::path& inPath, int inWidth, int inHeight,
                std::span<const std::uint8_t> inRgba)
{
    // Size checks before any file is touched.
    if (inWidth < 1 || inHeight < 1)
        return MakeError(EError::InvalidArgument, "WritePng: size " + std::to_string(inWidth) + " x " +
                                                      std::to_string(inHeight) + " is empty");
    const std::size_t expected = 4 * static_cast<std::size_t>(inWidth) * static_cast<std::size_t>(inHeight);
    if (inRgba.size() != expected)
        return MakeError(EError::InvalidArgument, "WritePng: " + std::to_string(inRgba.size()) +
                                                      " bytes for " + std::to_string(inWidth) + " x " +
                                                      std::to_string(inHeight) + " RGBA pixels (" +
                                                      std::to_string(expected) + " expected)");
    if (inPath.empty())
        return MakeError(EError::InvalidArgument, "WritePng: empty path");

    // Encode in memory.
    std::vector<unsigned char> png;
    if (stbi_write_png_to_func(&AppendBytes, &png, inWidth, inHeight, 4, inRgba.data(), 4 * inWidth) == 0)
        return MakeError(EError::IoError, "WritePng: PNG encoding failed for " + inPath.string());

    // Through "<inPath>.partial" and a rename, so inPath never holds a partial picture.
    return WriteFileAtomically(inPath, std::as_bytes(std::span(png)), "WritePng");
}

} // namespace crumple::render
