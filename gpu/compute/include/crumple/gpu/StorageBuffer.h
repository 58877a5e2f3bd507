// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/gpu/ComputeDevice.h>

#include <cstddef>
#include <cstdint>
#include <memory>

namespace crumple::gpu
{

/// A shader storage buffer on a ComputeDevice (std430 layout is the shader's business). Move-only; freed
/// with the device current. Sizes in bytes.
class CRUMPLE_API StorageBuffer
{
public:
    /// Allocates inBytes (> 0) and fills them from inData, or leaves them zero when inData is nullptr.
    static Result<StorageBuffer> Create(std::shared_ptr<ComputeDevice> inDevice, std::size_t inBytes,
                                        const void* inData = nullptr);
    StorageBuffer() = default;
    ~StorageBuffer();
    StorageBuffer(StorageBuffer&& ioOther) noexcept;
    StorageBuffer& operator=(StorageBuffer&& ioOther) noexcept;
    StorageBuffer(const StorageBuffer&) = delete;
    StorageBuffer& operator=(const StorageBuffer&) = delete;

    /// Writes inBytes at inOffset (the range must lie inside the buffer; the device must be current).
    void Upload(std::size_t inOffset, std::size_t inBytes, const void* inData) const;
    /// Reads inBytes at inOffset into outData (waits for the GPU; the device must be current).
    void Download(std::size_t inOffset, std::size_t inBytes, void* outData) const;
    /// Copies all of inSource (same size) into this buffer on the GPU.
    void CopyFrom(const StorageBuffer& inSource) const;
    /// Binds the buffer to shader storage binding point inBinding.
    void Bind(std::uint32_t inBinding) const;
    /// Size in bytes
    std::size_t GetSize() const { return mBytes; }

private:
    std::shared_ptr<ComputeDevice> mDevice;
    std::uint32_t mBuffer = 0;
    std::size_t mBytes = 0;
};

} // namespace crumple::gpu
