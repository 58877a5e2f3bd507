// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/plugin/ContactReduction.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace crumple::plugin
{

std::vector<CollisionContact> ReduceContacts(const std::vector<CollisionContact>& inContacts, std::size_t inMaxContacts)
{
    const std::size_t n = inContacts.size();
    if (n <= inMaxContacts || inMaxContacts < 9)
        return inContacts;

    // The contact plane: the mean normal and two tangents.
    Vec3 normal = Vec3::Zero();
    for (const CollisionContact& c : inContacts)
        normal += c.mNormal;
    normal = normal.norm() > 0.0 ? Vec3(normal.normalized()) : inContacts.front().mNormal;
    Eigen::Index least = 0;
    normal.cwiseAbs().minCoeff(&least);
    const Vec3 u = normal.cross(Vec3::Unit(least)).normalized();
    const Vec3 v = normal.cross(u);
    std::vector<Vec3> plane(n); // (u, v, 0): distances in the plane only
    for (std::size_t i = 0; i < n; ++i)
    {
        const Vec3 p = 0.5 * (inContacts[i].mPointOnA + inContacts[i].mPointOnB);
        plane[i] = Vec3(u.dot(p), v.dot(p), 0.0);
    }

    std::vector<std::uint8_t> kept(n, 0);
    std::size_t count = 0;
    auto keep = [&](std::size_t inIndex) {
        if (kept[inIndex] == 0)
        {
            kept[inIndex] = 1;
            ++count;
        }
    };
    // The extremes along 8 directions and the deepest contact (first index on ties).
    const double r = std::sqrt(0.5);
    const std::array<Vec3, 8> directions{Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0),
                                         Vec3(r, r, 0), Vec3(-r, -r, 0), Vec3(r, -r, 0), Vec3(-r, r, 0)};
    for (const Vec3& direction : directions)
    {
        std::size_t best = 0;
        for (std::size_t i = 1; i < n; ++i)
            if (plane[i].dot(direction) > plane[best].dot(direction))
                best = i;
        keep(best);
    }
    std::size_t deepest = 0;
    for (std::size_t i = 1; i < n; ++i)
        if (inContacts[i].mPenetrationDepth > inContacts[deepest].mPenetrationDepth)
            deepest = i;
    keep(deepest);

    // Farthest-point samples: each next contact is the one farthest (in the plane) from every kept one.
    std::vector<double> distance(n, std::numeric_limits<double>::infinity());
    auto update = [&](std::size_t inFrom) {
        for (std::size_t i = 0; i < n; ++i)
            distance[i] = std::min(distance[i], (plane[i] - plane[inFrom]).squaredNorm());
    };
    for (std::size_t i = 0; i < n; ++i)
        if (kept[i] != 0)
            update(i);
    while (count < inMaxContacts)
    {
        std::size_t farthest = n;
        for (std::size_t i = 0; i < n; ++i)
            if (kept[i] == 0 && (farthest == n || distance[i] > distance[farthest]))
                farthest = i;
        if (farthest == n || !(distance[farthest] > 0.0))
            break; // the rest coincide with kept contacts
        keep(farthest);
        update(farthest);
    }

    std::vector<CollisionContact> out;
    out.reserve(count);
    for (std::size_t i = 0; i < n; ++i)
        if (kept[i] != 0)
            out.push_back(inContacts[i]);
    return out;
}

} // namespace crumple::plugin
