#version 430
// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The implicit step's dot products a . b over the nodes, and the conjugate-gradient scalars made from them,
// on the GPU: one work group, each invocation sums a strided slice, then a tree reduction in shared memory in
// a fixed order (deterministic, no float atomics); invocation 0 writes the scalars. Scalars:
//   [0] rz (current r . z), [1] the first r . z of the solve (the scale of its relative residual),
//   [2] alpha, [3] beta, [4] 1 once a direction had no positive curvature (the solve stops there).
// uMode 0: a solve starts (a . b = r . z): [0] = [1] = sum, [3] = 0 (the first direction is z), [4] = 0.
//       1: curvature p . Ap: alpha = rz / sum, or 0 and [4] = 1 when sum is not > 0.
//       2: new r . z: beta = sum / rz (0 when rz is 0), rz = sum.
layout(local_size_x = 256) in;

layout(std430, binding = 27) buffer Scalars { float scalars[]; };
layout(std430, binding = 29) readonly buffer A { vec4 a[]; };
layout(std430, binding = 30) readonly buffer B { vec4 b[]; };

uniform uint uNodeCount;
uniform uint uMode;

shared float partial[256];

void main()
{
    uint lane = gl_LocalInvocationID.x;
    float sum = 0.0;
    for (uint node = lane; node < uNodeCount; node += 256u)
        sum += dot(a[node].xyz, b[node].xyz);
    partial[lane] = sum;
    barrier();
    for (uint stride = 128u; stride > 0u; stride >>= 1u)
    {
        if (lane < stride)
            partial[lane] += partial[lane + stride];
        barrier();
    }
    if (lane != 0u)
        return;
    float total = partial[0];
    if (uMode == 0u)
    {
        scalars[0] = total;
        scalars[1] = total;
        scalars[3] = 0.0;
        scalars[4] = 0.0;
    }
    else if (uMode == 1u)
    {
        bool curved = total > 0.0;
        scalars[2] = curved ? scalars[0] / total : 0.0;
        if (!curved)
            scalars[4] = 1.0;
    }
    else
    {
        scalars[3] = scalars[0] > 0.0 ? total / scalars[0] : 0.0;
        scalars[0] = total;
    }
}
