#version 430
// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Node pass of the implicit step: the backward-Euler residual of fem::TetSolver::StepImplicit at the current
// iterate v (positions x0 + h v),
//   r = h (f(x) + f_ext + m g - alpha m v - uKvScale K v) - m (v - v0),
// f gathered from the force pass's corners and K v from the stiffness product's (uKvScale = h + beta on the
// first Newton iteration, which linearises at x0; beta after it), both in element order. 0 on anchored nodes.
layout(local_size_x = 64) in;

layout(std430, binding = 0) readonly buffer Positions { vec4 positions[]; };          // w = 1/m (1/kg)
layout(std430, binding = 1) readonly buffer Velocities { vec4 velocities[]; };        // v (m/s)
layout(std430, binding = 5) readonly buffer Corners { vec4 corners[]; };              // elastic forces (N)
layout(std430, binding = 6) readonly buffer ExternalForces { vec4 externalForces[]; };
layout(std430, binding = 7) readonly buffer Offsets { uint offsets[]; };
layout(std430, binding = 8) readonly buffer Incident { uint incident[]; };
layout(std430, binding = 19) readonly buffer StartVelocities { vec4 startVelocities[]; }; // v0 (m/s)
layout(std430, binding = 20) writeonly buffer Residual { vec4 residual[]; };             // r (N s)
layout(std430, binding = 26) readonly buffer Products { vec4 products[]; };              // K v corners (N/s)

uniform uint uNodeCount;
uniform float uDeltaTime;   // h (s)
uniform float uMassDamping; // alpha (1/s)
uniform float uKvScale;     // s; 0: no K v term this iteration (the products are not read)
uniform vec3 uGravity;      // m/s^2

void main()
{
    uint node = gl_GlobalInvocationID.x;
    if (node >= uNodeCount)
        return;
    float inverse_mass = positions[node].w;
    if (inverse_mass == 0.0)
    {
        residual[node] = vec4(0.0);
        return;
    }
    float mass = 1.0 / inverse_mass;
    vec3 force = vec3(0.0), kv = vec3(0.0);
    for (uint entry = offsets[node]; entry < offsets[node + 1u]; ++entry)
    {
        force += corners[incident[entry]].xyz;
        if (uKvScale != 0.0)
            kv += products[incident[entry]].xyz;
    }
    vec3 v = velocities[node].xyz;
    vec3 load = force + externalForces[node].xyz + mass * uGravity;
    vec3 r = uDeltaTime * (load - uMassDamping * mass * v - uKvScale * kv) - mass * (v - startVelocities[node].xyz);
    residual[node] = vec4(r, 0.0);
}
