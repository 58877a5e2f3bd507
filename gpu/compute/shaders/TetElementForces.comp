#version 430
// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Element pass (the paper's "finite element update", section IV.A, in compute form): per tetrahedron the
// deformation gradient F = D_s D_m^-1, the corotated frame R (warm-started polar decomposition, the CPU's
// PolarRotation in float) or none (St. Venant-Kirchhoff), the first Piola-Kirchhoff stress of the elastic
// (less the plastic) and viscous strain, and the four corner forces -V0 P D_m^-T, written per corner (no float atomics: the node
// pass gathers them in a fixed order).
layout(local_size_x = 64) in;

layout(std430, binding = 0) readonly buffer Positions { vec4 positions[]; };   // xyz (m), w = 1/m (1/kg)
layout(std430, binding = 1) readonly buffer Velocities { vec4 velocities[]; }; // xyz (m/s)
layout(std430, binding = 2) readonly buffer Elements { ivec4 elements[]; };    // current node indices
layout(std430, binding = 3) readonly buffer Rest { vec4 rest[]; };             // 3 per element: columns of
                                                                               // D_m^-1; rest[3e].w = V0 (m^3)
layout(std430, binding = 4) buffer Rotations { vec4 rotations[]; };            // unit quaternion (x, y, z, w)
layout(std430, binding = 5) writeonly buffer Corners { vec4 corners[]; };      // 4 per element: force (N)
layout(std430, binding = 31) readonly buffer PlasticStrains { vec4 plasticStrains[]; }; // 3 per element

uniform uint uElementCount;
uniform int uCorotated;   // 1: corotated linear, 0: St. Venant-Kirchhoff
uniform float uLambda;    // Lame lambda (Pa)
uniform float uMu;        // shear modulus (Pa)
uniform float uBeta;      // Rayleigh stiffness damping (s); 0 = none
uniform int uPlastic;     // 1: subtract each element's plastic strain (in the model's frame)

#include "TetMath.glsl"

void main()
{
    uint element = gl_GlobalInvocationID.x;
    if (element >= uElementCount)
        return;
    ivec4 n = elements[element];
    mat3 rest_inverse = mat3(rest[3u * element].xyz, rest[3u * element + 1u].xyz, rest[3u * element + 2u].xyz);
    float volume = rest[3u * element].w;

    // Deformation gradient and frame.
    vec3 x0 = positions[n.x].xyz;
    mat3 f = mat3(positions[n.y].xyz - x0, positions[n.z].xyz - x0, positions[n.w].xyz - x0) * rest_inverse;
    mat3 frame;
    mat3 strain;
    if (uCorotated != 0)
    {
        vec4 q = PolarRotation(f, rotations[element]);
        rotations[element] = q;
        frame = RotationMatrix(q);
        mat3 u = transpose(frame) * f;
        strain = 0.5 * (u + transpose(u)) - mat3(1.0);
    }
    else
    {
        frame = f;
        strain = 0.5 * (transpose(f) * f - mat3(1.0));
    }
    if (uPlastic != 0)
        strain -= mat3(plasticStrains[3u * element].xyz, plasticStrains[3u * element + 1u].xyz,
                       plasticStrains[3u * element + 2u].xyz);
    mat3 p = frame * IsotropicStress(strain, uLambda, uMu);

    // Kelvin-Voigt viscous stress beta C:strain_rate in the same frame.
    if (uBeta > 0.0)
    {
        vec3 v0 = velocities[n.x].xyz;
        mat3 f_dot = mat3(velocities[n.y].xyz - v0, velocities[n.z].xyz - v0, velocities[n.w].xyz - v0) * rest_inverse;
        mat3 local = transpose(frame) * f_dot;
        p += frame * (uBeta * IsotropicStress(0.5 * (local + transpose(local)), uLambda, uMu));
    }

    // Corner forces -V0 P D_m^-T: columns 1..3, corner 0 takes minus their sum.
    mat3 h = -volume * (p * transpose(rest_inverse));
    uint base = 4u * element;
    corners[base] = vec4(-(h[0] + h[1] + h[2]), 0.0);
    corners[base + 1u] = vec4(h[0], 0.0);
    corners[base + 2u] = vec4(h[1], 0.0);
    corners[base + 3u] = vec4(h[2], 0.0);
}
