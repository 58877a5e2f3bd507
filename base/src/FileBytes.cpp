// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/FileBytes.h>

#include <fstream>

namespace crumple
{

Result<std::vector<std::byte>> ReadFileBytes(const std::filesystem::path& inPath)
{
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

} // namespace crumple
