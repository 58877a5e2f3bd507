// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Shared by the element passes (pasted in by EmbedShaders.cmake at an #include line): quaternions, the polar
// rotation of fem::PolarRotation in float, and the isotropic linear stress.

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
mat3 IsotropicStress(mat3 e, float lambda, float mu)
{
    return lambda * (e[0][0] + e[1][1] + e[2][2]) * mat3(1.0) + 2.0 * mu * e;
}

// The positive part of symmetric s (its eigenvalues clamped at 0, fem::TetElementPass's PositivePart) by
// cyclic Jacobi rotations (six sweeps: float round-off for a 3x3), so repeated eigenvalues need no care.
mat3 PositivePart(mat3 s)
{
    mat3 a = s;
    mat3 v = mat3(1.0);
    for (int sweep = 0; sweep < 6; ++sweep)
        for (int pair = 0; pair < 3; ++pair)
        {
            int p = pair == 2 ? 1 : 0;
            int q = pair == 0 ? 1 : 2;
            float apq = a[q][p];
            if (abs(apq) <= 1.0e-30 * (abs(a[p][p]) + abs(a[q][q])) || apq == 0.0)
                continue;
            float theta = (a[q][q] - a[p][p]) / (2.0 * apq);
            float t = sign(theta) / (abs(theta) + sqrt(theta * theta + 1.0));
            if (theta == 0.0)
                t = 1.0;
            float c = inversesqrt(t * t + 1.0);
            mat3 j = mat3(1.0);
            j[p][p] = c;
            j[q][q] = c;
            j[q][p] = t * c;
            j[p][q] = -t * c;
            a = transpose(j) * a * j;
            v = v * j;
        }
    return v * mat3(max(a[0][0], 0.0), 0.0, 0.0, 0.0, max(a[1][1], 0.0), 0.0, 0.0, 0.0, max(a[2][2], 0.0)) *
           transpose(v);
}
