#version 430
// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Fracture, step 2: each element group's rest-volume-weighted mean stress and its largest principal stress
// with direction (fem::GroupPrincipalStress; a closed-form symmetric 3x3 eigen solution, Smith 1961, where
// the CPU uses Eigen's computeDirect: the same value to float precision, the direction up to sign).
layout(local_size_x = 64) in;

layout(std430, binding = 3) readonly buffer Rest { vec4 rest[]; };                 // rest[3e].w = V0
layout(std430, binding = 10) readonly buffer Stress { vec4 stress[]; };            // 2 per element
layout(std430, binding = 11) readonly buffer GroupOffsets { uint groupOffsets[]; }; // #G + 1
layout(std430, binding = 12) readonly buffer GroupElements { uint groupElements[]; };
layout(std430, binding = 13) writeonly buffer Principal { vec4 principal[]; };     // direction, value (Pa)

uniform uint uGroupCount;

// Unit eigenvector of symmetric a for eigenvalue inValue: the longest cross product of two rows of a - l I.
vec3 EigenVector(mat3 a, float inValue)
{
    mat3 m = a - inValue * mat3(1.0);
    vec3 r0 = vec3(m[0][0], m[1][0], m[2][0]), r1 = vec3(m[0][1], m[1][1], m[2][1]), r2 = vec3(m[0][2], m[1][2], m[2][2]);
    vec3 c01 = cross(r0, r1), c02 = cross(r0, r2), c12 = cross(r1, r2);
    float d01 = dot(c01, c01), d02 = dot(c02, c02), d12 = dot(c12, c12);
    vec3 best = d01 >= d02 && d01 >= d12 ? c01 : (d02 >= d12 ? c02 : c12);
    float length2 = max(d01, max(d02, d12));
    return length2 > 0.0 ? best * inversesqrt(length2) : vec3(1.0, 0.0, 0.0);
}

void main()
{
    uint group = gl_GlobalInvocationID.x;
    if (group >= uGroupCount)
        return;
    // Mean over the group's elements, element order.
    vec4 sum0 = vec4(0.0), sum1 = vec4(0.0);
    float volume = 0.0;
    for (uint entry = groupOffsets[group]; entry < groupOffsets[group + 1u]; ++entry)
    {
        uint element = groupElements[entry];
        float v = rest[3u * element].w;
        sum0 += v * stress[2u * element];
        sum1 += v * stress[2u * element + 1u];
        volume += v;
    }
    sum0 /= volume;
    sum1 /= volume;
    mat3 a = mat3(vec3(sum0.x, sum0.w, sum1.y), vec3(sum0.w, sum0.y, sum1.x), vec3(sum1.y, sum1.x, sum0.z));

    // Largest eigenvalue: q + 2 p cos(phi) with B = (A - q I) / p, phi = acos(det(B) / 2) / 3.
    float q = (a[0][0] + a[1][1] + a[2][2]) / 3.0;
    float p1 = a[1][0] * a[1][0] + a[2][0] * a[2][0] + a[2][1] * a[2][1];
    float p2 = (a[0][0] - q) * (a[0][0] - q) + (a[1][1] - q) * (a[1][1] - q) + (a[2][2] - q) * (a[2][2] - q) + 2.0 * p1;
    float p = sqrt(p2 / 6.0);
    if (!(p > 0.0))
    {
        principal[group] = vec4(1.0, 0.0, 0.0, q); // isotropic: every direction is principal
        return;
    }
    float r = clamp(determinant((a - q * mat3(1.0)) / p) / 2.0, -1.0, 1.0);
    float largest = q + 2.0 * p * cos(acos(r) / 3.0);
    principal[group] = vec4(EigenVector(a, largest), largest);
}
