#version 430
// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Element pass of the implicit step: the linearised stiffness (the CPU's TetStiffnessProduct) applied to a
// direction d, written per corner (the node passes gather them in a fixed order): dF = dD_s D_m^-1, corner
// products V0 dP D_m^-T (K = -df/dx) with dP = R C:sym(R^T dF) (corotated, the frames the last force pass
// left) or dP = F C:sym(F^T dF) + dF S+ (St. Venant-Kirchhoff at the current positions, S+ the positive part
// of the second Piola-Kirchhoff stress of the elastic strain, so the system stays positive definite; F and S+
// as TetStvkLinearization left them for this Newton iteration).
layout(local_size_x = 64) in;

layout(std430, binding = 2) readonly buffer Elements { ivec4 elements[]; };        // current node indices
layout(std430, binding = 3) readonly buffer Rest { vec4 rest[]; };                 // 3 per element: columns
                                                                                   // of D_m^-1, w = V0 (m^3)
layout(std430, binding = 4) readonly buffer Rotations { vec4 rotations[]; };       // unit quaternions
layout(std430, binding = 26) writeonly buffer Products { vec4 products[]; };       // 4 per element (N or N/s)
layout(std430, binding = 28) readonly buffer Direction { vec4 direction[]; };      // #N (m or m/s)
layout(std430, binding = 21) readonly buffer Preconditioned { vec4 preconditioned[]; }; // z, #N
layout(std430, binding = 27) readonly buffer Scalars { float scalars[]; };         // [3]: beta
layout(std430, binding = 29) readonly buffer Linearization { vec4 linearization[]; }; // StVK: 6 per element,
                                                                                      // F and S+ (TetStvkLinearization)

uniform uint uElementCount;
uniform float uLambda;     // Lame lambda (Pa)
uniform float uMu;         // shear modulus (Pa)
uniform int uNewDirection; // 1: the direction is the conjugate gradient's next, z + beta p (p bound as d)
uniform int uCorotated;    // 1: corotated, 0: St. Venant-Kirchhoff

// The direction at a node: d, or the next conjugate direction z + beta p (TetConjugateGradient's operator
// pass stores the same value: one dispatch per iteration saved).
vec3 DirectionAt(int node)
{
    return uNewDirection != 0 ? preconditioned[node].xyz + scalars[3] * direction[node].xyz : direction[node].xyz;
}

#include "TetMath.glsl"

void main()
{
    uint element = gl_GlobalInvocationID.x;
    if (element >= uElementCount)
        return;
    ivec4 n = elements[element];
    mat3 rest_inverse = mat3(rest[3u * element].xyz, rest[3u * element + 1u].xyz, rest[3u * element + 2u].xyz);
    float volume = rest[3u * element].w;
    vec3 d0 = DirectionAt(n.x);
    mat3 d_f = mat3(DirectionAt(n.y) - d0, DirectionAt(n.z) - d0, DirectionAt(n.w) - d0) * rest_inverse;
    mat3 d_p;
    if (uCorotated != 0)
    {
        mat3 frame = RotationMatrix(rotations[element]);
        mat3 local = transpose(frame) * d_f;
        d_p = frame * IsotropicStress(0.5 * (local + transpose(local)), uLambda, uMu);
    }
    else
    {
        uint base = 6u * element;
        mat3 f = mat3(linearization[base].xyz, linearization[base + 1u].xyz, linearization[base + 2u].xyz);
        mat3 positive = mat3(linearization[base + 3u].xyz, linearization[base + 4u].xyz, linearization[base + 5u].xyz);
        mat3 local = transpose(f) * d_f;
        d_p = f * IsotropicStress(0.5 * (local + transpose(local)), uLambda, uMu) + d_f * positive;
    }
    mat3 h = volume * (d_p * transpose(rest_inverse));
    uint base = 4u * element;
    products[base] = vec4(-(h[0] + h[1] + h[2]), 0.0);
    products[base + 1u] = vec4(h[0], 0.0);
    products[base + 2u] = vec4(h[1], 0.0);
    products[base + 3u] = vec4(h[2], 0.0);
}
