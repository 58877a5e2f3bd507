// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/gpu/EglContext.h>

#include <GL/glcorearb.h>

#include <string>

namespace crumple::render
{

/// The GL entry points MeshRenderer uses, loaded through EglContext::GetProcAddress and owned by the
/// renderer (no globals, no GLEW/GLAD).
struct RenderGlFunctions
{
    PFNGLATTACHSHADERPROC mAttachShader = nullptr;
    PFNGLBINDBUFFERPROC mBindBuffer = nullptr;
    PFNGLBINDFRAMEBUFFERPROC mBindFramebuffer = nullptr;
    PFNGLBINDRENDERBUFFERPROC mBindRenderbuffer = nullptr;
    PFNGLBINDVERTEXARRAYPROC mBindVertexArray = nullptr;
    PFNGLBLITFRAMEBUFFERPROC mBlitFramebuffer = nullptr;
    PFNGLBUFFERDATAPROC mBufferData = nullptr;
    PFNGLCHECKFRAMEBUFFERSTATUSPROC mCheckFramebufferStatus = nullptr;
    PFNGLCLEARPROC mClear = nullptr;
    PFNGLCLEARCOLORPROC mClearColor = nullptr;
    PFNGLCLEARDEPTHPROC mClearDepth = nullptr;
    PFNGLCOMPILESHADERPROC mCompileShader = nullptr;
    PFNGLCREATEPROGRAMPROC mCreateProgram = nullptr;
    PFNGLCREATESHADERPROC mCreateShader = nullptr;
    PFNGLDELETEBUFFERSPROC mDeleteBuffers = nullptr;
    PFNGLDELETEFRAMEBUFFERSPROC mDeleteFramebuffers = nullptr;
    PFNGLDELETEPROGRAMPROC mDeleteProgram = nullptr;
    PFNGLDELETERENDERBUFFERSPROC mDeleteRenderbuffers = nullptr;
    PFNGLDELETESHADERPROC mDeleteShader = nullptr;
    PFNGLDELETEVERTEXARRAYSPROC mDeleteVertexArrays = nullptr;
    PFNGLDEPTHFUNCPROC mDepthFunc = nullptr;
    PFNGLDISABLEPROC mDisable = nullptr;
    PFNGLDISABLEVERTEXATTRIBARRAYPROC mDisableVertexAttribArray = nullptr;
    PFNGLDRAWELEMENTSPROC mDrawElements = nullptr;
    PFNGLENABLEPROC mEnable = nullptr;
    PFNGLENABLEVERTEXATTRIBARRAYPROC mEnableVertexAttribArray = nullptr;
    PFNGLFINISHPROC mFinish = nullptr;
    PFNGLFRAMEBUFFERRENDERBUFFERPROC mFramebufferRenderbuffer = nullptr;
    PFNGLGENBUFFERSPROC mGenBuffers = nullptr;
    PFNGLGENFRAMEBUFFERSPROC mGenFramebuffers = nullptr;
    PFNGLGENRENDERBUFFERSPROC mGenRenderbuffers = nullptr;
    PFNGLGENVERTEXARRAYSPROC mGenVertexArrays = nullptr;
    PFNGLGETERRORPROC mGetError = nullptr;
    PFNGLGETINTEGERVPROC mGetIntegerv = nullptr;
    PFNGLGETPROGRAMINFOLOGPROC mGetProgramInfoLog = nullptr;
    PFNGLGETPROGRAMIVPROC mGetProgramiv = nullptr;
    PFNGLGETSHADERINFOLOGPROC mGetShaderInfoLog = nullptr;
    PFNGLGETSHADERIVPROC mGetShaderiv = nullptr;
    PFNGLGETUNIFORMLOCATIONPROC mGetUniformLocation = nullptr;
    PFNGLLINKPROGRAMPROC mLinkProgram = nullptr;
    PFNGLPIXELSTOREIPROC mPixelStorei = nullptr;
    PFNGLREADBUFFERPROC mReadBuffer = nullptr;
    PFNGLREADPIXELSPROC mReadPixels = nullptr;
    PFNGLRENDERBUFFERSTORAGEMULTISAMPLEPROC mRenderbufferStorageMultisample = nullptr;
    PFNGLSHADERSOURCEPROC mShaderSource = nullptr;
    PFNGLUNIFORM1FPROC mUniform1f = nullptr;
    PFNGLUNIFORM1IPROC mUniform1i = nullptr;
    PFNGLUNIFORM3FPROC mUniform3f = nullptr;
    PFNGLUNIFORM3FVPROC mUniform3fv = nullptr;
    PFNGLUNIFORMMATRIX4FVPROC mUniformMatrix4fv = nullptr;
    PFNGLUSEPROGRAMPROC mUseProgram = nullptr;
    PFNGLVERTEXATTRIB1FPROC mVertexAttrib1f = nullptr;
    PFNGLVERTEXATTRIBPOINTERPROC mVertexAttribPointer = nullptr;
    PFNGLVIEWPORTPROC mViewport = nullptr;

    /// Loads every entry point from inContext (current on this thread). Returns the names that could not be
    /// loaded, space separated; empty on success.
    std::string Load(const gpu::EglContext& inContext);
};

} // namespace crumple::render
