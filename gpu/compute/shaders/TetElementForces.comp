#version 430
// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Element pass (the paper's "finite element update", section IV.A, in compute form): per tetrahedron the
// deformation gradient F = D_s D_m^-1, the corotated frame R (warm-started polar decomposition, the CPU's
// PolarRotation in float) or none (St. Venant-Kirchhoff), the first Piola-Kirchhoff stress of the elastic and
// viscous strain, and the four corner forces -V0 P D_m^-T, written per corner (no float atomics: the node
// pass gathers them in a fixed order).
layout(local_size_x = 64) in;

layout(std430, binding = 0) readonly buffer Positions { vec4 positions[]; };   // xyz (m), w = 1/m (1/kg)
layout(std430, binding = 1) readonly buffer Velocities { vec4 velocities[]; }; // xyz (m/s)
layout(std430, binding = 2) readonly buffer Elements { ivec4 elements[]; };    // current node indices
layout(std430, binding = 3) readonly buffer Rest { vec4 rest[]; };             // 3 per element: columns of
                                                                               // D_m^-1; rest[3e].w = V0 (m^3)
layout(std430, binding = 4) buffer Rotations { vec4 rotations[]; };            // unit quaternion (x, y, z, w)
layout(std430, binding = 5) writeonly buffer Corners { vec4 corners[]; };      // 4 per element: force (N)

uniform uint uElementCount;
uniform int uCorotated;   // 1: corotated linear, 0: St. Venant-Kirchhoff
uniform float uLambda;    // Lame lambda (Pa)
uniform float uMu;        // shear modulus (Pa)
uniform float uBeta;      // Rayleigh stiffness damping (s); 0 = none

mat3 RotationMatrix(vec4 q)
{
    float x = q.x, y = q.y, z = q.z, w = q.w;
    return mat3(vec3(1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y + z * w), 2.0 * (x * z - y * w)),
                vec3(2.0 * (x * y - z * w), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z + x * w)),
                vec3(2.0 * (x * z + y * w), 2.0 * (y * z - x * w), 1.0 - 2.0 * (x * x + y * y)));
}

vec4 QuatMultiply(vec4 a, vec4 b)
{
    return vec4(a.w * b.xyz + b.w * a.xyz + cross(a.xyz, b.xyz), a.w * b.w - dot(a.xyz, b.xyz));
}

// Newton iteration on tr(R^T F) over rotations, as fem::PolarRotation (float tolerances).
vec4 PolarRotation(mat3 f, vec4 q)
{
    q = normalize(q);
    for (int iteration = 0; iteration < 8; ++iteration)
    {
        mat3 b = transpose(RotationMatrix(q)) * f; // b[column][row]
        vec3 g = vec3(b[1][2] - b[2][1], b[2][0] - b[0][2], b[0][1] - b[1][0]);
        float trace = b[0][0] + b[1][1] + b[2][2];
        float h00 = trace - b[0][0], h11 = trace - b[1][1], h22 = trace - b[2][2];
        float h01 = -0.5 * (b[1][0] + b[0][1]), h02 = -0.5 * (b[2][0] + b[0][2]), h12 = -0.5 * (b[2][1] + b[1][2]);
        float c00 = h11 * h22 - h12 * h12, c01 = h02 * h12 - h01 * h22, c02 = h01 * h12 - h02 * h11;
        float c11 = h00 * h22 - h02 * h02, c12 = h01 * h02 - h00 * h12, c22 = h00 * h11 - h01 * h01;
        float det = h00 * c00 + h01 * c01 + h02 * c02;
        bool newton = h00 > 0.0 && c22 > 0.0 && det > 0.0;
        vec3 omega = newton ? vec3(c00 * g.x + c01 * g.y + c02 * g.z, c01 * g.x + c11 * g.y + c12 * g.z,
                                   c02 * g.x + c12 * g.y + c22 * g.z) / det
                            : g / (abs(trace) + 1.0e-9);
        float angle = length(omega);
        if (!(angle > 1.0e-7))
            break;
        q = normalize(QuatMultiply(q, vec4(0.5 * omega, 1.0)));
        if (newton && angle < 1.0e-4)
            break;
    }
    return q;
}

// Isotropic stress of a symmetric strain: lambda tr(e) I + 2 mu e (Pa).
mat3 Stress(mat3 e, float lambda, float mu)
{
    return lambda * (e[0][0] + e[1][1] + e[2][2]) * mat3(1.0) + 2.0 * mu * e;
}

void main()
{
    uint element = gl_GlobalInvocationID.x;
    if (element >= uElementCount)
        return;
    ivec4 n = elements[element];
    mat3 rest_inverse = mat3(rest[3u * element].xyz, rest[3u * element + 1u].xyz, rest[3u * element + 2u].xyz);
    float volume = rest[3u * element].w;

    // Deformation gradient and frame.
    vec3 x0 = positions[n.x].xyz;
    mat3 f = mat3(positions[n.y].xyz - x0, positions[n.z].xyz - x0, positions[n.w].xyz - x0) * rest_inverse;
    mat3 frame;
    mat3 strain;
    if (uCorotated != 0)
    {
        vec4 q = PolarRotation(f, rotations[element]);
        rotations[element] = q;
        frame = RotationMatrix(q);
        mat3 u = transpose(frame) * f;
        strain = 0.5 * (u + transpose(u)) - mat3(1.0);
    }
    else
    {
        frame = f;
        strain = 0.5 * (transpose(f) * f - mat3(1.0));
    }
    mat3 p = frame * Stress(strain, uLambda, uMu);

    // Kelvin-Voigt viscous stress beta C:strain_rate in the same frame.
    if (uBeta > 0.0)
    {
        vec3 v0 = velocities[n.x].xyz;
        mat3 f_dot = mat3(velocities[n.y].xyz - v0, velocities[n.z].xyz - v0, velocities[n.w].xyz - v0) * rest_inverse;
        mat3 local = transpose(frame) * f_dot;
        p += frame * (uBeta * Stress(0.5 * (local + transpose(local)), uLambda, uMu));
    }

    // Corner forces -V0 P D_m^-T: columns 1..3, corner 0 takes minus their sum.
    mat3 h = -volume * (p * transpose(rest_inverse));
    uint base = 4u * element;
    corners[base] = vec4(-(h[0] + h[1] + h[2]), 0.0);
    corners[base + 1u] = vec4(h[0], 0.0);
    corners[base + 2u] = vec4(h[1], 0.0);
    corners[base + 3u] = vec4(h[2], 0.0);
}
