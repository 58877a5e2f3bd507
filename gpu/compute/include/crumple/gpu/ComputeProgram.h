// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Math.h>
#include <crumple/base/Result.h>
#include <crumple/gpu/ComputeDevice.h>

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

namespace crumple::gpu
{

/// A linked GLSL compute program. Move-only; deletes its program with the device current.
class CRUMPLE_API ComputeProgram
{
public:
    /// Compiles and links inSource (a complete "#version 430" compute shader). A compile or link failure
    /// returns the driver's GLSL log, prefixed with inName.
    static Result<ComputeProgram> Create(std::shared_ptr<ComputeDevice> inDevice, std::string_view inName,
                                         std::string_view inSource);
    ~ComputeProgram();
    ComputeProgram(ComputeProgram&& ioOther) noexcept;
    ComputeProgram& operator=(ComputeProgram&& ioOther) noexcept;
    ComputeProgram(const ComputeProgram&) = delete;
    ComputeProgram& operator=(const ComputeProgram&) = delete;

    /// Makes this program current (the device must be current).
    void Use() const;
    /// Sets a uniform of the current program; a name the shader does not use (optimised away) is ignored.
    void SetUInt(const char* inName, std::uint32_t inValue) const;
    void SetInt(const char* inName, int inValue) const;
    void SetFloat(const char* inName, float inValue) const;
    void SetVec3(const char* inName, const Vec3& inValue) const;
    /// Runs ceil(inInvocations / local size) work groups along x, then a shader-storage barrier so the next
    /// dispatch sees the writes.
    void Dispatch(std::uint32_t inInvocations) const;
    /// The local work-group size along x the shader declares
    std::uint32_t GetLocalSize() const { return mLocalSize; }

    /// An empty program (no GL object), to be assigned from Create().
    ComputeProgram() = default;

private:

    std::shared_ptr<ComputeDevice> mDevice;
    std::uint32_t mProgram = 0;
    std::uint32_t mLocalSize = 1;
};

} // namespace crumple::gpu
