// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/gpu/ComputeProgram.h>

#include "ComputeGlFunctions.h"

#include <string>
#include <utility>
#include <vector>

namespace crumple::gpu
{

Result<ComputeProgram> ComputeProgram::Create(std::shared_ptr<ComputeDevice> inDevice, std::string_view inName,
                                              std::string_view inSource)
{
    if (!inDevice)
        return MakeError(EError::InvalidArgument, "ComputeProgram " + std::string(inName) + ": no device");
    if (Status status = inDevice->MakeCurrent(); status.HasError())
        return status.GetError();
    const ComputeGlFunctions& gl = inDevice->GetGl();

    // Compile; the log says where the GLSL is wrong.
    const GLuint shader = gl.mCreateShader(GL_COMPUTE_SHADER);
    const GLchar* source = inSource.data();
    const GLint length = static_cast<GLint>(inSource.size());
    gl.mShaderSource(shader, 1, &source, &length);
    gl.mCompileShader(shader);
    GLint ok = GL_FALSE;
    gl.mGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE)
    {
        GLint log_length = 0;
        gl.mGetShaderiv(shader, GL_INFO_LOG_LENGTH, &log_length);
        std::vector<char> log(static_cast<std::size_t>(std::max(log_length, 1)), '\0');
        gl.mGetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), nullptr, log.data());
        gl.mDeleteShader(shader);
        return MakeError(EError::InvalidArgument,
                         "ComputeProgram " + std::string(inName) + ": GLSL compile failed: " + log.data());
    }

    // Link.
    ComputeProgram program;
    program.mDevice = std::move(inDevice);
    program.mProgram = gl.mCreateProgram();
    gl.mAttachShader(program.mProgram, shader);
    gl.mLinkProgram(program.mProgram);
    gl.mDeleteShader(shader); // flagged; freed with the program
    gl.mGetProgramiv(program.mProgram, GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE)
    {
        GLint log_length = 0;
        gl.mGetProgramiv(program.mProgram, GL_INFO_LOG_LENGTH, &log_length);
        std::vector<char> log(static_cast<std::size_t>(std::max(log_length, 1)), '\0');
        gl.mGetProgramInfoLog(program.mProgram, static_cast<GLsizei>(log.size()), nullptr, log.data());
        return MakeError(EError::InvalidArgument,
                         "ComputeProgram " + std::string(inName) + ": GLSL link failed: " + log.data());
    }
    GLint size[3] = {1, 1, 1};
    gl.mGetProgramiv(program.mProgram, GL_COMPUTE_WORK_GROUP_SIZE, size);
    program.mLocalSize = static_cast<std::uint32_t>(size[0]);
    return program;
}

ComputeProgram::~ComputeProgram()
{
    if (mProgram != 0 && mDevice && mDevice->MakeCurrent().IsValid())
        mDevice->GetGl().mDeleteProgram(mProgram);
}

ComputeProgram::ComputeProgram(ComputeProgram&& ioOther) noexcept
    : mDevice(std::move(ioOther.mDevice)), mProgram(std::exchange(ioOther.mProgram, 0)),
      mLocalSize(ioOther.mLocalSize)
{
}

ComputeProgram& ComputeProgram::operator=(ComputeProgram&& ioOther) noexcept
{
    if (this != &ioOther)
    {
        if (mProgram != 0 && mDevice && mDevice->MakeCurrent().IsValid())
            mDevice->GetGl().mDeleteProgram(mProgram);
        mDevice = std::move(ioOther.mDevice);
        mProgram = std::exchange(ioOther.mProgram, 0);
        mLocalSize = ioOther.mLocalSize;
    }
    return *this;
}

void ComputeProgram::Use() const
{
    mDevice->GetGl().mUseProgram(mProgram);
}

void ComputeProgram::SetUInt(const char* inName, std::uint32_t inValue) const
{
    const ComputeGlFunctions& gl = mDevice->GetGl();
    gl.mUniform1ui(gl.mGetUniformLocation(mProgram, inName), inValue);
}

void ComputeProgram::SetInt(const char* inName, int inValue) const
{
    const ComputeGlFunctions& gl = mDevice->GetGl();
    gl.mUniform1i(gl.mGetUniformLocation(mProgram, inName), inValue);
}

void ComputeProgram::SetFloat(const char* inName, float inValue) const
{
    const ComputeGlFunctions& gl = mDevice->GetGl();
    gl.mUniform1f(gl.mGetUniformLocation(mProgram, inName), inValue);
}

void ComputeProgram::SetVec3(const char* inName, const Vec3& inValue) const
{
    const ComputeGlFunctions& gl = mDevice->GetGl();
    gl.mUniform3f(gl.mGetUniformLocation(mProgram, inName), static_cast<float>(inValue.x()),
                  static_cast<float>(inValue.y()), static_cast<float>(inValue.z()));
}

void ComputeProgram::Dispatch(std::uint32_t inInvocations) const
{
    const ComputeGlFunctions& gl = mDevice->GetGl();
    const std::uint32_t groups = (inInvocations + mLocalSize - 1) / mLocalSize;
    if (groups > 0)
        gl.mDispatchCompute(groups, 1, 1);
    gl.mMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

} // namespace crumple::gpu
