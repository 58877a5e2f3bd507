#version 430
// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Fracture, step 3 (the paper's "fracture update"): fem::OpenCracks per link. A link opens when one of its
// groups' largest principal stress exceeds the tensile strength and (CrackPlane) the link's face, taken as it
// is now, is within the crack angle of that group's principal direction, or (DetachGroup) always. Newly
// opened links are counted with an integer atomic (order-independent); node duplication follows on the CPU.
layout(local_size_x = 64) in;

layout(std430, binding = 0) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = 2) readonly buffer Elements { ivec4 elements[]; };
layout(std430, binding = 9) buffer Status { uint status[]; };                        // [1]: links opened
layout(std430, binding = 13) readonly buffer Principal { vec4 principal[]; };
layout(std430, binding = 14) readonly buffer Links { ivec4 links[]; };                // group a, b, faces
layout(std430, binding = 15) readonly buffer LinkFaces { ivec4 linkFaces[]; };       // element, 3 corners
layout(std430, binding = 16) readonly buffer LinkNormals { vec4 linkNormals[]; };    // rest normal a -> b
layout(std430, binding = 17) buffer Broken { uint broken[]; };

uniform uint uLinkCount;
uniform float uStrength;      // Pa
uniform int uDetachGroup;     // 1: EFractureMode::DetachGroup
uniform float uCrackCosine;   // cCrackFaceCosine

bool Opens(vec4 inPrincipal, vec3 inNormal)
{
    return inPrincipal.w > uStrength && (uDetachGroup != 0 || abs(dot(inNormal, inPrincipal.xyz)) >= uCrackCosine);
}

void main()
{
    uint link = gl_GlobalInvocationID.x;
    if (link >= uLinkCount || broken[link] != 0u)
        return;
    ivec4 l = links[link];
    vec4 a = principal[l.x], b = principal[l.y];
    if (!(a.w > uStrength) && !(b.w > uStrength))
        return;
    // The shared face now: area-weighted normal of its triangles through the current connectivity.
    vec3 normal = vec3(0.0);
    for (int face = l.z; face < l.w; ++face)
    {
        ivec4 t = linkFaces[face];
        ivec4 n = elements[t.x];
        vec3 x0 = positions[n[t.y]].xyz;
        normal += cross(positions[n[t.z]].xyz - x0, positions[n[t.w]].xyz - x0);
    }
    float length2 = dot(normal, normal);
    normal = length2 > 0.0 && !isinf(length2) ? normal * inversesqrt(length2) : linkNormals[link].xyz;
    if (Opens(a, normal) || Opens(b, normal))
    {
        broken[link] = 1u;
        atomicAdd(status[1], 1u);
    }
}
