// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

namespace crumple::render
{

/// Vertex shader: positions arrive relative to the eye (world axes), so only the view rotation and the
/// projection remain; normals stay in the world frame for lighting.
inline constexpr const char* cMeshVertexShader = R"(#version 330 core
layout(location = 0) in vec3 aPosition; // eye-relative position, world axes (m)
layout(location = 1) in vec3 aNormal;   // vertex normal, world frame
layout(location = 2) in float aScalar;  // scalar mapped to [0, 1]
uniform mat4 uViewProjection;
out vec3 vPosition;
out vec3 vNormal;
out float vScalar;
void main()
{
    vPosition = aPosition;
    vNormal = aNormal;
    vScalar = aScalar;
    gl_Position = uViewProjection * vec4(aPosition, 1.0);
}
)";

/// Fragment shader: Lambert key light + headlight + ambient, two-sided, albedo from the base colour or the
/// colour map interpolated per pixel (so colours between table entries are the map's, not a vertex blend).
inline constexpr const char* cMeshFragmentShader = R"(#version 330 core
in vec3 vPosition;
in vec3 vNormal;
in float vScalar;
uniform vec3 uBaseColor;
uniform vec3 uKeyDirection; // unit, towards the key light, world frame
uniform float uAmbient;
uniform float uKeyIntensity;
uniform float uHeadlightIntensity;
uniform int uUseScalars;
uniform int uColorCount;
uniform vec3 uColors[16];
out vec4 oColor;

vec3 ColorMap(float inT)
{
    float x = clamp(inT, 0.0, 1.0) * float(uColorCount - 1);
    int i = min(int(floor(x)), uColorCount - 2);
    return mix(uColors[i], uColors[i + 1], x - float(i));
}

void main()
{
    vec3 to_eye = normalize(-vPosition);
    float length_n = length(vNormal);
    vec3 n = length_n > 1e-12 ? vNormal / length_n : to_eye;
    if (dot(n, to_eye) < 0.0)
        n = -n;
    float light = uAmbient + uKeyIntensity * max(dot(n, uKeyDirection), 0.0)
                + uHeadlightIntensity * max(dot(n, to_eye), 0.0);
    vec3 albedo = uUseScalars != 0 ? ColorMap(vScalar) : uBaseColor;
    oColor = vec4(min(albedo * light, vec3(1.0)), 1.0);
}
)";

} // namespace crumple::render
