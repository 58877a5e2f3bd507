#version 430
// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Element pass of the implicit St. Venant-Kirchhoff step, once per Newton iteration after its force pass: each
// element's deformation gradient F and S+, the positive part of the second Piola-Kirchhoff stress of its
// elastic strain, at the current positions. The stiffness product (every conjugate-gradient iteration) and the
// Jacobi blocks (every corner) read them instead of working them out again: the positions do not move within
// a Newton iteration, and S+ alone takes six Jacobi sweeps.
layout(local_size_x = 64) in;

layout(std430, binding = 0) readonly buffer Positions { vec4 positions[]; };           // x (m)
layout(std430, binding = 2) readonly buffer Elements { ivec4 elements[]; };             // current node indices
layout(std430, binding = 3) readonly buffer Rest { vec4 rest[]; };                      // 3 per element
layout(std430, binding = 29) writeonly buffer Linearization { vec4 linearization[]; };  // 6 per element: F, S+
layout(std430, binding = 31) readonly buffer PlasticStrains { vec4 plasticStrains[]; }; // 3 per element

uniform uint uElementCount;
uniform float uLambda; // Lame lambda (Pa)
uniform float uMu;     // shear modulus (Pa)
uniform int uPlastic;  // 1: the elastic strain is the model's less the element's plastic strain

#include "TetMath.glsl"

void main()
{
    uint element = gl_GlobalInvocationID.x;
    if (element >= uElementCount)
        return;
    ivec4 n = elements[element];
    mat3 rest_inverse = mat3(rest[3u * element].xyz, rest[3u * element + 1u].xyz, rest[3u * element + 2u].xyz);
    vec3 x0 = positions[n.x].xyz;
    mat3 f = mat3(positions[n.y].xyz - x0, positions[n.z].xyz - x0, positions[n.w].xyz - x0) * rest_inverse;
    mat3 strain = 0.5 * (transpose(f) * f - mat3(1.0));
    if (uPlastic != 0)
        strain -= mat3(plasticStrains[3u * element].xyz, plasticStrains[3u * element + 1u].xyz,
                       plasticStrains[3u * element + 2u].xyz);
    mat3 positive = PositivePart(IsotropicStress(strain, uLambda, uMu));
    uint base = 6u * element;
    for (int column = 0; column < 3; ++column)
    {
        linearization[base + uint(column)] = vec4(f[column], 0.0);
        linearization[base + 3u + uint(column)] = vec4(positive[column], 0.0);
    }
}
