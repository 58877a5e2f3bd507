#version 430
// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Fracture, step 1 (the paper's "fracture finite element update", section IV.B.1): the Cauchy stress of every
// element at the state after the node update, as fem::TetCauchyStress: R C:(eps - eps_p) R^T (corotated, the
// frame warm-started and stored back) or F S F^T / J (St. Venant-Kirchhoff; S when inverted).
layout(local_size_x = 64) in;

layout(std430, binding = 0) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = 2) readonly buffer Elements { ivec4 elements[]; };
layout(std430, binding = 3) readonly buffer Rest { vec4 rest[]; };
layout(std430, binding = 4) buffer Rotations { vec4 rotations[]; };
layout(std430, binding = 10) writeonly buffer Stress { vec4 stress[]; }; // 2 per element: xx yy zz xy, yz zx
layout(std430, binding = 31) readonly buffer PlasticStrains { vec4 plasticStrains[]; }; // 3 per element

uniform uint uElementCount;
uniform int uCorotated;
uniform float uLambda;
uniform float uMu;
uniform int uPlastic; // 1: the elastic strain is the model's less the element's plastic strain

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
    mat3 plastic = uPlastic != 0 ? mat3(plasticStrains[3u * element].xyz, plasticStrains[3u * element + 1u].xyz,
                                        plasticStrains[3u * element + 2u].xyz)
                                 : mat3(0.0);
    mat3 sigma;
    if (uCorotated != 0)
    {
        vec4 q = PolarRotation(f, rotations[element]);
        rotations[element] = q;
        mat3 r = RotationMatrix(q);
        mat3 u = transpose(r) * f;
        sigma = r * IsotropicStress(0.5 * (u + transpose(u)) - mat3(1.0) - plastic, uLambda, uMu) * transpose(r);
    }
    else
    {
        mat3 s = IsotropicStress(0.5 * (transpose(f) * f - mat3(1.0)) - plastic, uLambda, uMu);
        float j = determinant(f);
        sigma = j > 0.0 ? f * s * transpose(f) / j : s;
    }
    stress[2u * element] = vec4(sigma[0][0], sigma[1][1], sigma[2][2], 0.5 * (sigma[1][0] + sigma[0][1]));
    stress[2u * element + 1u] = vec4(0.5 * (sigma[2][1] + sigma[1][2]), 0.5 * (sigma[0][2] + sigma[2][0]), 0.0, 0.0);
}
