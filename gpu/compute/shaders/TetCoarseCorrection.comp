#version 430
// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The coarse correction of the implicit step's preconditioner (fem::TetCoarseSpace): after the block-Jacobi
// z = D^-1 r, z += P (P^T A0 P)^-1 P^T r, P the rigid modes of the node aggregates. One pass per uOperation:
//   0 restrict: per aggregate, c = R^T sum over its nodes of (r, d x r), d the node's offset from the
//               aggregate's centre as the aggregate is turned now, R that turn (its nodes in ascending order:
//               a fixed sum order, no atomics)
//   1 solve:    per coarse unknown i, y_i = sum_j inverse(i, j) c_j
//   2 prolong:  per node of an aggregate, z += R y_t + (R y_w) x d
// The space was built with the aggregates unturned (GpuImplicitStep::TurnCoarseSpace turns them): a rigidly
// turned aggregate's modes and system are its rest ones turned by R.
// Anchored nodes belong to no aggregate (w = -1) and keep z = 0.
layout(local_size_x = 64) in;

layout(std430, binding = 20) readonly buffer Residual { vec4 residual[]; };
layout(std430, binding = 21) buffer Preconditioned { vec4 preconditioned[]; };
layout(std430, binding = 28) readonly buffer NodeModes { vec4 nodeModes[]; }; // #N: d (m), w = aggregate or -1
layout(std430, binding = 29) readonly buffer Members { uint members[]; };     // A + 1 offsets (from the start
                                                                              // of the buffer), then the nodes
layout(std430, binding = 30) buffer Coarse { float coarse[]; };               // c (6A), y (6A), the inverse
                                                                              // (6A x 6A, row-major), then
                                                                              // each aggregate's R (9, columns)

uniform uint uOperation;
uniform uint uCount;      // aggregates (0), coarse unknowns (1) or nodes (2)
uniform uint uUnknowns;   // 6A

mat3 Turn(uint aggregate)
{
    uint base = 2u * uUnknowns + uUnknowns * uUnknowns + 9u * aggregate;
    return mat3(coarse[base], coarse[base + 1u], coarse[base + 2u], coarse[base + 3u], coarse[base + 4u],
                coarse[base + 5u], coarse[base + 6u], coarse[base + 7u], coarse[base + 8u]);
}

void main()
{
    uint index = gl_GlobalInvocationID.x;
    if (index >= uCount)
        return;
    if (uOperation == 0u)
    {
        vec3 force = vec3(0.0), moment = vec3(0.0);
        for (uint entry = members[index]; entry < members[index + 1u]; ++entry)
        {
            uint node = members[entry];
            vec3 r = residual[node].xyz;
            force += r;
            moment += cross(nodeModes[node].xyz, r);
        }
        mat3 turn_back = transpose(Turn(index));
        force = turn_back * force;
        moment = turn_back * moment;
        for (uint k = 0u; k < 3u; ++k)
        {
            coarse[6u * index + k] = force[k];
            coarse[6u * index + 3u + k] = moment[k];
        }
    }
    else if (uOperation == 1u)
    {
        uint row = 2u * uUnknowns + index * uUnknowns;
        float sum = 0.0;
        for (uint j = 0u; j < uUnknowns; ++j)
            sum += coarse[row + j] * coarse[j];
        coarse[uUnknowns + index] = sum;
    }
    else
    {
        vec4 modes = nodeModes[index];
        if (modes.w < 0.0)
            return;
        uint aggregate = uint(modes.w);
        uint base = uUnknowns + 6u * aggregate;
        mat3 turn = Turn(aggregate);
        vec3 translation = turn * vec3(coarse[base], coarse[base + 1u], coarse[base + 2u]);
        vec3 rotation = turn * vec3(coarse[base + 3u], coarse[base + 4u], coarse[base + 5u]);
        preconditioned[index].xyz += translation + cross(rotation, modes.xyz);
    }
}
