// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/FileBytes.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <system_error>

namespace crumple
{

Result<std::vector<std::byte>> ReadFileBytes(const std::filesystem::path& inPath)
{
    // intent: a folder sized itself from tellg (bad_alloc) and a FIFO blocked the open: files only, checked
    // before opening
    std::error_code error;
    const std::filesystem::file_status status = std::filesystem::status(inPath, error);
    if (!std::filesystem::exists(status))
        return MakeError(EError::IoError, "cannot read " + inPath.string() + ": no such file");
    if (!std::filesystem::is_regular_file(status))
        return MakeError(EError::IoError, "cannot read " + inPath.string() + ": not a regular file");
    std::ifstream in(inPath, std::ios::binary);
    if (!in)
        return MakeError(EError::IoError, "cannot read " + inPath.string());
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    if (size < 0)
        return MakeError(EError::IoError, "cannot read " + inPath.string());
    in.seekg(0, std::ios::beg);
    std::vector<std::byte> bytes(static_cast<std::size_t>(size));
    if (!in.read(reinterpret_cast<char*>(bytes.data()), size))
        return MakeError(EError::IoError, "read failed: " + inPath.string());
    return bytes;
}

std::filesystem::path PartialFilePath(const std::filesystem::path& inPath)
{
    std::filesystem::path partial = inPath;
    partial += ".partial";
    return partial;
}

Status CommitPartialFile(const std::filesystem::path& inPath, std::string_view inCaller)
{
    // Rename over the destination: atomic within one file system.
    const std::filesystem::path partial = PartialFilePath(inPath);
    std::error_code error;
    std::filesystem::rename(partial, inPath, error);
    if (error)
        return MakeError(EError::IoError, std::string(inCaller) + ": cannot rename " + partial.string() +
                                              " to " + inPath.string() + ": " + error.message());
    return Status::Ok();
}

Status WriteFileAtomically(const std::filesystem::path& inPath, std::span<const std::byte> inBytes,
                           std::string_view inCaller)
{
    if (inPath.empty())
        return MakeError(EError::InvalidArgument, std::string(inCaller) + ": empty path");
    const std::filesystem::path partial = PartialFilePath(inPath);

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

    // Complete: rename it over the destination, or leave nothing behind.
    if (Status committed = CommitPartialFile(inPath, inCaller); !committed)
    {
        std::error_code ignored;
        std::filesystem::remove(partial, ignored);
        return committed;
    }
    return Status::Ok();
}

} // namespace crumple
