#version 430
// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Node pass (the paper's "node update"): each node gathers its elements' corner forces through an adjacency
// list in a fixed order (deterministic, no float atomics), then symplectic Euler: v += dt (f/m + g), mass
// damping applied implicitly (v /= 1 + alpha dt), x += dt v. Anchored nodes (1/m = 0) do not move. A
// non-finite result raises the status flag (an integer atomic: order-independent).
layout(local_size_x = 64) in;

layout(std430, binding = 0) buffer Positions { vec4 positions[]; };            // xyz (m), w = 1/m (1/kg)
layout(std430, binding = 1) buffer Velocities { vec4 velocities[]; };          // xyz (m/s)
layout(std430, binding = 5) readonly buffer Corners { vec4 corners[]; };       // 4 per element (N)
layout(std430, binding = 6) readonly buffer ExternalForces { vec4 externalForces[]; };     // xyz force (N)
layout(std430, binding = 7) readonly buffer Offsets { uint offsets[]; };       // #N + 1
layout(std430, binding = 8) readonly buffer Incident { uint incident[]; };     // 4 element + corner
layout(std430, binding = 9) buffer Status { uint status[]; };                  // [0]: 1 = non-finite state

uniform uint uNodeCount;
uniform float uDeltaTime;      // s
uniform float uDampingScale;   // 1 / (1 + alpha dt)
uniform vec3 uGravity;         // m/s^2

void main()
{
    uint node = gl_GlobalInvocationID.x;
    if (node >= uNodeCount)
        return;
    vec4 p = positions[node];
    if (p.w == 0.0)
        return;
    vec3 force = vec3(0.0);
    for (uint entry = offsets[node]; entry < offsets[node + 1u]; ++entry)
        force += corners[incident[entry]].xyz;
    vec3 acceleration = p.w * (force + externalForces[node].xyz) + uGravity;
    vec3 v = (velocities[node].xyz + uDeltaTime * acceleration) * uDampingScale;
    p.xyz += uDeltaTime * v;
    velocities[node] = vec4(v, 0.0);
    positions[node] = p;
    if (any(isnan(p.xyz)) || any(isinf(p.xyz)) || any(isnan(v)) || any(isinf(v)))
        atomicOr(status[0], 1u);
}
