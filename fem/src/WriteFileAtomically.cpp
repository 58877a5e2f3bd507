// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "WriteFileAtomically.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>

namespace crumple::fem
{

Status WriteFileAtomically(const std::filesystem::path& inPath, std::span<const std::byte> inBytes,
                           std::string_view inCaller)
{
    if (inPath.empty())
        return MakeError(EError::InvalidArgument, std::string(inCaller) + ": empty path");
    std::filesystem::path partial = inPath;
    partial += ".partial";

    // Write and close the partial file; errno says why fopen, fwrite or fclose failed.
    std::FILE* file = std::fopen(partial.c_str(), "wb");
    if (file == nullptr)
        return MakeError(EError::IoError, std::string(inCaller) + ": cannot create " + partial.string() +
                                              ": " + std::strerror(errno));
    const bool written = std::fwrite(inBytes.data(), 1, inBytes.size(), file) == inBytes.size();
    const int write_error = errno;
    const bool closed = std::fclose(file) == 0;
    const int close_error = errno;
    if (!written || !closed)
    {
        std::error_code ignored;
        std::filesystem::remove(partial, ignored);
        return MakeError(EError::IoError, std::string(inCaller) + ": cannot write " + partial.string() +
                                              ": " + std::strerror(written ? close_error : write_error));
    }

    // Rename over the destination: atomic within one file system.
    std::error_code error;
    std::filesystem::rename(partial, inPath, error);
    if (error)
    {
        std::error_code ignored;
        std::filesystem::remove(partial, ignored);
        return MakeError(EError::IoError, std::string(inCaller) + ": cannot rename " + partial.string() +
                                              " to " + inPath.string() + ": " + error.message());
    }
    return Status::Ok();
}

} // namespace crumple::fem
