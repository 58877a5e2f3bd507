#version 430
// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Plastic flow after a sub-step or implicit step, as fem::TetPlasticFlow (von Mises with a radial return,
// fem::PlasticFlow in float): with the elastic strain e = eps - eps_p of the model's strain eps (corotated:
// sym(R^T F) - I, the frame warm-started and stored back; St. Venant-Kirchhoff: (F^T F - I) / 2) and its
// deviatoric part e', the excess of sigma_vm = 2 mu sqrt(3/2 e':e') over the yield stress flows:
// eps_p += uCreepFraction (1 - sigma_y / sigma_vm) e', the equivalent plastic strain then clamped. An element
// whose four corners are anchored does not flow (the CPU skips it). Each element that flowed adds 1 to
// status[3] (an integer atomic: the count does not depend on order).
layout(local_size_x = 64) in;

layout(std430, binding = 0) readonly buffer Positions { vec4 positions[]; }; // w = 1/m, 0 = anchored
layout(std430, binding = 2) readonly buffer Elements { ivec4 elements[]; };
layout(std430, binding = 3) readonly buffer Rest { vec4 rest[]; };
layout(std430, binding = 4) buffer Rotations { vec4 rotations[]; };
layout(std430, binding = 9) buffer Status { uint status[]; };                 // [3]: elements that flowed
layout(std430, binding = 31) buffer PlasticStrains { vec4 plasticStrains[]; }; // 3 per element: columns

uniform uint uElementCount;
uniform int uCorotated;
uniform float uMu;                // shear modulus (Pa)
uniform float uYieldStress;       // sigma_y (Pa)
uniform float uCreepFraction;     // min(1, creep rate dt)
uniform float uMaxPlasticStrain;  // cap of the equivalent plastic strain

#include "TetMath.glsl"

float SquaredNorm(mat3 m)
{
    return dot(m[0], m[0]) + dot(m[1], m[1]) + dot(m[2], m[2]);
}

void main()
{
    uint element = gl_GlobalInvocationID.x;
    if (element >= uElementCount)
        return;
    ivec4 n = elements[element];
    if (positions[n.x].w == 0.0 && positions[n.y].w == 0.0 && positions[n.z].w == 0.0 && positions[n.w].w == 0.0)
        return;
    mat3 rest_inverse = mat3(rest[3u * element].xyz, rest[3u * element + 1u].xyz, rest[3u * element + 2u].xyz);
    vec3 x0 = positions[n.x].xyz;
    mat3 f = mat3(positions[n.y].xyz - x0, positions[n.z].xyz - x0, positions[n.w].xyz - x0) * rest_inverse;
    mat3 strain;
    if (uCorotated != 0)
    {
        vec4 q = PolarRotation(f, rotations[element]);
        rotations[element] = q;
        mat3 u = transpose(RotationMatrix(q)) * f;
        strain = 0.5 * (u + transpose(u)) - mat3(1.0);
    }
    else
        strain = 0.5 * (transpose(f) * f - mat3(1.0));

    mat3 before = mat3(plasticStrains[3u * element].xyz, plasticStrains[3u * element + 1u].xyz,
                       plasticStrains[3u * element + 2u].xyz);
    mat3 elastic = strain - before;
    mat3 deviatoric = elastic - (elastic[0][0] + elastic[1][1] + elastic[2][2]) / 3.0 * mat3(1.0);
    float von_mises = 2.0 * uMu * sqrt(1.5 * SquaredNorm(deviatoric));
    if (!(von_mises > uYieldStress))
        return;
    mat3 after = before + uCreepFraction * (1.0 - uYieldStress / von_mises) * deviatoric;
    after = 0.5 * (after + transpose(after));
    float equivalent = sqrt(2.0 / 3.0 * SquaredNorm(after));
    if (equivalent > uMaxPlasticStrain)
        after *= uMaxPlasticStrain / equivalent;
    if (after == before)
        return;
    plasticStrains[3u * element] = vec4(after[0], 0.0);
    plasticStrains[3u * element + 1u] = vec4(after[1], 0.0);
    plasticStrains[3u * element + 2u] = vec4(after[2], 0.0);
    atomicAdd(status[3], 1u);
}
