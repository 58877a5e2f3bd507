#version 430
// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The implicit step's energy scale, summed at its start over the free nodes (one work group, fixed-order tree
// reduction as TetDot): kinetic energy 1/2 m v^2, momentum m v, and the energy of the load's impulse over
// the step 1/2 m |h (f_ext / m + g)|^2. Written to the scalars [5] (J), [6..8] (kg m/s), [9] (J); the host
// takes the kinetic energy relative to the free centre of mass when nothing is anchored, as the CPU does.
layout(local_size_x = 256) in;

layout(std430, binding = 0) readonly buffer Positions { vec4 positions[]; };          // w = 1/m (1/kg)
layout(std430, binding = 1) readonly buffer Velocities { vec4 velocities[]; };        // m/s
layout(std430, binding = 6) readonly buffer ExternalForces { vec4 externalForces[]; }; // N
layout(std430, binding = 27) buffer Scalars { float scalars[]; };

uniform uint uNodeCount;
uniform float uDeltaTime; // h (s)
uniform vec3 uGravity;    // m/s^2

shared vec4 motion[256]; // kinetic energy, momentum
shared float load[256];

void main()
{
    uint lane = gl_LocalInvocationID.x;
    vec4 moving = vec4(0.0);
    float loaded = 0.0;
    for (uint node = lane; node < uNodeCount; node += 256u)
    {
        float inverse_mass = positions[node].w;
        if (inverse_mass == 0.0)
            continue;
        float mass = 1.0 / inverse_mass;
        vec3 v = velocities[node].xyz;
        vec3 kick = uDeltaTime * (inverse_mass * externalForces[node].xyz + uGravity);
        moving += vec4(0.5 * mass * dot(v, v), mass * v);
        loaded += 0.5 * mass * dot(kick, kick);
    }
    motion[lane] = moving;
    load[lane] = loaded;
    barrier();
    for (uint stride = 128u; stride > 0u; stride >>= 1u)
    {
        if (lane < stride)
        {
            motion[lane] += motion[lane + stride];
            load[lane] += load[lane + stride];
        }
        barrier();
    }
    if (lane == 0u)
    {
        scalars[5] = motion[0].x;
        scalars[6] = motion[0].y;
        scalars[7] = motion[0].z;
        scalars[8] = motion[0].w;
        scalars[9] = load[0];
    }
}
