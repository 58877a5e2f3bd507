#version 430
// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Node pass of the implicit step: each free node's block-Jacobi preconditioner, the inverse of its 3x3
// diagonal block of A = (1 + h alpha) M + (h^2 + h beta) K, K the linearised stiffness of TetStiffnessProduct.
// A corner with shape gradient g (a row of D_m^-1, or minus their sum for corner 0) adds K_aa of an isotropic
// element to its node's block: V0 [(lambda + mu) (R g)(R g)^T + mu |g|^2 I] (corotated, the frames of the last
// force pass) or V0 [(lambda + mu) (F g)(F g)^T + mu |g|^2 F F^T + (g . S+ g) I] (St. Venant-Kirchhoff).
// Gathered in element order; anchored nodes get 0.
layout(local_size_x = 64) in;

layout(std430, binding = 0) readonly buffer Positions { vec4 positions[]; };     // w = 1/m (1/kg)
layout(std430, binding = 3) readonly buffer Rest { vec4 rest[]; };               // 3 per element
layout(std430, binding = 4) readonly buffer Rotations { vec4 rotations[]; };     // unit quaternions
layout(std430, binding = 7) readonly buffer Offsets { uint offsets[]; };
layout(std430, binding = 8) readonly buffer Incident { uint incident[]; };
layout(std430, binding = 25) writeonly buffer Blocks { vec4 blocks[]; };         // 3 per node: columns of the
                                                                                 // inverse block (1/kg)
layout(std430, binding = 29) readonly buffer Linearization { vec4 linearization[]; }; // StVK: 6 per element,
                                                                                      // F and S+ (TetStvkLinearization)

uniform uint uNodeCount;
uniform float uMassScale;      // 1 + h alpha
uniform float uStiffnessScale; // h^2 + h beta (s^2)
uniform float uLambda;         // Pa
uniform float uMu;             // Pa
uniform int uCorotated;        // 1: corotated, 0: St. Venant-Kirchhoff

#include "TetMath.glsl"

void main()
{
    uint node = gl_GlobalInvocationID.x;
    if (node >= uNodeCount)
        return;
    float inverse_mass = positions[node].w;
    if (inverse_mass == 0.0)
    {
        blocks[3u * node] = vec4(0.0);
        blocks[3u * node + 1u] = vec4(0.0);
        blocks[3u * node + 2u] = vec4(0.0);
        return;
    }
    mat3 stiffness = mat3(0.0);
    for (uint entry = offsets[node]; entry < offsets[node + 1u]; ++entry)
    {
        uint element = incident[entry] >> 2u, corner = incident[entry] & 3u;
        mat3 rest_inverse = mat3(rest[3u * element].xyz, rest[3u * element + 1u].xyz, rest[3u * element + 2u].xyz);
        mat3 rows = transpose(rest_inverse); // rows[i] = row i of D_m^-1
        vec3 g = corner == 0u ? -(rows[0] + rows[1] + rows[2]) : rows[corner - 1u];
        float volume = rest[3u * element].w;
        if (uCorotated != 0)
        {
            vec3 h = RotationMatrix(rotations[element]) * g;
            stiffness += volume * ((uLambda + uMu) * outerProduct(h, h) + uMu * dot(g, g) * mat3(1.0));
            continue;
        }
        uint base = 6u * element;
        mat3 f = mat3(linearization[base].xyz, linearization[base + 1u].xyz, linearization[base + 2u].xyz);
        mat3 positive = mat3(linearization[base + 3u].xyz, linearization[base + 4u].xyz, linearization[base + 5u].xyz);
        vec3 h = f * g;
        stiffness += volume * ((uLambda + uMu) * outerProduct(h, h) + uMu * dot(g, g) * f * transpose(f) +
                               dot(g, positive * g) * mat3(1.0));
    }
    mat3 block = uMassScale / inverse_mass * mat3(1.0) + uStiffnessScale * stiffness;
    mat3 inverse_block = inverse(block);
    blocks[3u * node] = vec4(inverse_block[0], 0.0);
    blocks[3u * node + 1u] = vec4(inverse_block[1], 0.0);
    blocks[3u * node + 2u] = vec4(inverse_block[2], 0.0);
}
