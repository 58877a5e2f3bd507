// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/render/WritePng.h>

#include <chrono>
#include <fstream>
#include <functional>
#include <string>
#include <system_error>
#include <thread>
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

/// A name beside inPath unlikely to collide with another writer (thread and clock in the name).
std::filesystem::path TemporaryPathFor(const std::filesystem::path& inPath)
{
    const std::size_t thread = std::hash<std::thread::id>{}(std::this_thread::get_id());
    const auto ticks = std::chrono::steady_clock::now().time_since_epoch().count();
    std::filesystem::path temporary = inPath;
    temporary += ".tmp-" + std::to_string(thread % 1000000) + "-" + std::to_string(ticks);
    return temporary;
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

    // Write a temporary file beside the destination, then rename it over the destination.
    const std::filesystem::path temporary = TemporaryPathFor(inPath);
    {
        std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
        if (file)
            file.write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
        if (file)
            file.close();
        if (!file)
        {
            std::error_code ignored;
            std::filesystem::remove(temporary, ignored);
            return MakeError(EError::IoError, "WritePng: cannot write " + temporary.string() +
                                                  " (does the directory exist and is it writable?)");
        }
    }
    std::error_code error;
    std::filesystem::rename(temporary, inPath, error);
    if (error)
    {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        return MakeError(EError::IoError, "WritePng: cannot rename " + temporary.string() + " to " +
                                              inPath.string() + ": " + error.message());
    }
    return Status::Ok();
}

} // namespace crumple::render
