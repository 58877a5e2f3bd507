// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/gpu/StorageBuffer.h>

#include "ComputeGlFunctions.h"

#include <utility>
#include <vector>

namespace crumple::gpu
{

Result<StorageBuffer> StorageBuffer::Create(std::shared_ptr<ComputeDevice> inDevice, std::size_t inBytes,
                                            const void* inData)
{
    if (!inDevice || inBytes == 0)
        return MakeError(EError::InvalidArgument, "StorageBuffer: needs a device and a size > 0");
    if (Status status = inDevice->MakeCurrent(); status.HasError())
        return status.GetError();
    const ComputeGlFunctions& gl = inDevice->GetGl();
    StorageBuffer buffer;
    buffer.mDevice = std::move(inDevice);
    buffer.mBytes = inBytes;
    gl.mGenBuffers(1, &buffer.mBuffer);
    gl.mBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer.mBuffer);
    gl.mGetError(); // clear earlier errors: the next check is about this allocation
    if (inData != nullptr)
        gl.mBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(inBytes), inData, GL_DYNAMIC_COPY);
    else
    {
        const std::vector<std::uint8_t> zeros(inBytes, 0);
        gl.mBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(inBytes), zeros.data(), GL_DYNAMIC_COPY);
    }
    if (gl.mGetError() == GL_OUT_OF_MEMORY)
        return MakeError(EError::IoError, "StorageBuffer: out of GPU memory for " + std::to_string(inBytes) + " bytes");
    return buffer;
}

StorageBuffer::~StorageBuffer()
{
    if (mBuffer != 0 && mDevice && mDevice->MakeCurrent().IsValid())
        mDevice->GetGl().mDeleteBuffers(1, &mBuffer);
}

StorageBuffer::StorageBuffer(StorageBuffer&& ioOther) noexcept
    : mDevice(std::move(ioOther.mDevice)), mBuffer(std::exchange(ioOther.mBuffer, 0)),
      mBytes(std::exchange(ioOther.mBytes, 0))
{
}

StorageBuffer& StorageBuffer::operator=(StorageBuffer&& ioOther) noexcept
{
    if (this != &ioOther)
    {
        if (mBuffer != 0 && mDevice && mDevice->MakeCurrent().IsValid())
            mDevice->GetGl().mDeleteBuffers(1, &mBuffer);
        mDevice = std::move(ioOther.mDevice);
        mBuffer = std::exchange(ioOther.mBuffer, 0);
        mBytes = std::exchange(ioOther.mBytes, 0);
    }
    return *this;
}

void StorageBuffer::Upload(std::size_t inOffset, std::size_t inBytes, const void* inData) const
{
    const ComputeGlFunctions& gl = mDevice->GetGl();
    gl.mBindBuffer(GL_SHADER_STORAGE_BUFFER, mBuffer);
    gl.mBufferSubData(GL_SHADER_STORAGE_BUFFER, static_cast<GLintptr>(inOffset), static_cast<GLsizeiptr>(inBytes),
                      inData);
}

void StorageBuffer::Download(std::size_t inOffset, std::size_t inBytes, void* outData) const
{
    const ComputeGlFunctions& gl = mDevice->GetGl();
    gl.mBindBuffer(GL_SHADER_STORAGE_BUFFER, mBuffer);
    gl.mGetBufferSubData(GL_SHADER_STORAGE_BUFFER, static_cast<GLintptr>(inOffset), static_cast<GLsizeiptr>(inBytes),
                         outData);
}

void StorageBuffer::CopyFrom(const StorageBuffer& inSource) const
{
    const ComputeGlFunctions& gl = mDevice->GetGl();
    gl.mBindBuffer(GL_COPY_READ_BUFFER, inSource.mBuffer);
    gl.mBindBuffer(GL_COPY_WRITE_BUFFER, mBuffer);
    gl.mCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 0, 0, static_cast<GLsizeiptr>(mBytes));
}

void StorageBuffer::Bind(std::uint32_t inBinding) const
{
    mDevice->GetGl().mBindBufferBase(GL_SHADER_STORAGE_BUFFER, inBinding, mBuffer);
}

} // namespace crumple::gpu
