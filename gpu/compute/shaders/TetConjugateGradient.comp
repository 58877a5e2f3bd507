#version 430
// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Node passes of the implicit step's preconditioned conjugate gradient (fem::ConjugateGradient from a zero
// guess, block-Jacobi preconditioned) and of its Newton update, one per uOperation. The scalars (alpha, beta)
// stay on the GPU, written by TetDot, so an iteration needs no readback:
//   0 start:     z = B r, p = 0, dv = 0 (with beta = 0 from TetDot's start, the first direction is z)
//   1 operator:  p = z + beta p, Ap = (1 + h alpha) m p + (h^2 + h beta_R) K p (K p gathered from the product
//                corners, which TetStiffnessProduct made from the same z + beta p)
//   2 update:    dv += alpha p, r -= alpha Ap, z = B r
//   4 advance:   v += dv, x = x0 + h v; a non-finite result raises the status flag
// Anchored nodes (1/m = 0) keep 0 in every vector and do not move.
layout(local_size_x = 64) in;

layout(std430, binding = 0) buffer Positions { vec4 positions[]; };              // xyz (m), w = 1/m (1/kg)
layout(std430, binding = 1) buffer Velocities { vec4 velocities[]; };            // m/s
layout(std430, binding = 7) readonly buffer Offsets { uint offsets[]; };
layout(std430, binding = 8) readonly buffer Incident { uint incident[]; };
layout(std430, binding = 9) buffer Status { uint status[]; };                    // [0]: 1 = non-finite state
layout(std430, binding = 18) readonly buffer StartPositions { vec4 startPositions[]; }; // x0 (m)
layout(std430, binding = 20) buffer Residual { vec4 residual[]; };
layout(std430, binding = 21) buffer Preconditioned { vec4 preconditioned[]; };
layout(std430, binding = 22) buffer Direction { vec4 direction[]; };
layout(std430, binding = 23) buffer Product { vec4 product[]; };
layout(std430, binding = 24) buffer Solution { vec4 solution[]; };
layout(std430, binding = 25) readonly buffer Blocks { vec4 blocks[]; };          // 3 per node
layout(std430, binding = 26) readonly buffer Products { vec4 products[]; };      // K p corners
layout(std430, binding = 27) readonly buffer Scalars { float scalars[]; };       // see TetDot

uniform uint uNodeCount;
uniform uint uOperation;
uniform float uDeltaTime;      // h (s)
uniform float uMassScale;      // 1 + h alpha
uniform float uStiffnessScale; // h^2 + h beta (s^2)

vec3 Precondition(uint node, vec3 r)
{
    return mat3(blocks[3u * node].xyz, blocks[3u * node + 1u].xyz, blocks[3u * node + 2u].xyz) * r;
}

void main()
{
    uint node = gl_GlobalInvocationID.x;
    if (node >= uNodeCount)
        return;
    float inverse_mass = positions[node].w;
    if (uOperation == 0u)
    {
        preconditioned[node] = vec4(Precondition(node, residual[node].xyz), 0.0);
        direction[node] = vec4(0.0);
        solution[node] = vec4(0.0);
    }
    else if (uOperation == 1u)
    {
        vec3 p = preconditioned[node].xyz + scalars[3] * direction[node].xyz;
        vec3 ap = vec3(0.0);
        if (inverse_mass != 0.0)
        {
            vec3 kp = vec3(0.0);
            for (uint entry = offsets[node]; entry < offsets[node + 1u]; ++entry)
                kp += products[incident[entry]].xyz;
            ap = uMassScale / inverse_mass * p + uStiffnessScale * kp;
        }
        direction[node] = vec4(p, 0.0);
        product[node] = vec4(ap, 0.0);
    }
    else if (uOperation == 2u)
    {
        float alpha = scalars[2];
        solution[node].xyz += alpha * direction[node].xyz;
        vec3 r = residual[node].xyz - alpha * product[node].xyz;
        residual[node] = vec4(r, 0.0);
        preconditioned[node] = vec4(Precondition(node, r), 0.0);
    }
    else if (inverse_mass != 0.0)
    {
        vec3 v = velocities[node].xyz + solution[node].xyz;
        vec3 x = startPositions[node].xyz + uDeltaTime * v;
        velocities[node] = vec4(v, 0.0);
        positions[node] = vec4(x, inverse_mass);
        if (any(isnan(x)) || any(isinf(x)) || any(isnan(v)) || any(isinf(v)))
            atomicOr(status[0], 1u);
    }
}
