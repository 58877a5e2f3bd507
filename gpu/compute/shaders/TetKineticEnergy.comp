#version 430
// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Kinetic energy 1/2 sum m v^2 of the free nodes, for sleep: one work group, each invocation sums a strided
// slice, then a tree reduction in shared memory in a fixed order (deterministic, no float atomics). The
// result goes into status[2] as float bits, read back with the step's status.
layout(local_size_x = 256) in;

layout(std430, binding = 0) readonly buffer Positions { vec4 positions[]; };   // w = 1/m
layout(std430, binding = 1) readonly buffer Velocities { vec4 velocities[]; };
layout(std430, binding = 9) buffer Status { uint status[]; };                  // [2]: kinetic energy (J)

uniform uint uNodeCount;

shared float partial[256];

void main()
{
    uint lane = gl_LocalInvocationID.x;
    float sum = 0.0;
    for (uint node = lane; node < uNodeCount; node += 256u)
    {
        vec4 p = positions[node];
        if (p.w > 0.0)
        {
            vec3 v = velocities[node].xyz;
            sum += dot(v, v) / p.w;
        }
    }
    partial[lane] = sum;
    barrier();
    for (uint stride = 128u; stride > 0u; stride >>= 1u)
    {
        if (lane < stride)
            partial[lane] += partial[lane + stride];
        barrier();
    }
    if (lane == 0u)
        status[2] = floatBitsToUint(0.5 * partial[0]);
}
