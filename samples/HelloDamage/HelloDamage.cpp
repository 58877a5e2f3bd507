// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The smallest use of Crumple: a car body, a wall, one contact, one dent. No engine, no GUI.
#include <crumple/plugin/DamageWorld.h>

#include <cstdint>
#include <cstdio>
#include <utility>

using namespace crumple;
using namespace crumple::plugin;

int main()
{
    std::unique_ptr<DamageWorld> world_owner = std::move(DamageWorld::Create().Get());
    DamageWorld& world = *world_owner;

    // A static wall and a 1,000 kg car driving at 10 m/s along +x (body frame at its centre of mass).
    BodyState wall_state;
    wall_state.mMotionType = EMotionType::Static;
    const BodyId wall = world.CreateBody(wall_state).Get();
    BodyState car_state;
    car_state.mMass = 1000.0;
    car_state.mInverseInertiaWorld = Mat3::Identity() / 800.0;
    car_state.mLinearVelocity = Vec3(10.0, 0.0, 0.0);
    const BodyId car = world.CreateBody(car_state).Get();

    // Its render mesh: a 2 m wide, 1 m tall front panel, a grid of 21 x 11 vertices 0.1 m apart at x = 2 m,
    // and one vertex 1 m behind it so that the deformation zone fitted to the mesh has depth (a real game
    // passes its car's mesh).
    DeformableObjectSettings settings;
    constexpr int cColumns = 21, cRows = 11;
    for (int row = 0; row < cRows; ++row)
        for (int column = 0; column < cColumns; ++column)
            settings.mMesh.mPositions.push_back(Vec3(2.0, -1.0 + 0.1 * column, -0.5 + 0.1 * row));
    for (std::uint32_t row = 0; row + 1 < cRows; ++row)
        for (std::uint32_t column = 0; column + 1 < cColumns; ++column)
        {
            const std::uint32_t corner = row * cColumns + column;
            settings.mMesh.mTriangles.push_back({corner, corner + 1, corner + cColumns + 1});
            settings.mMesh.mTriangles.push_back({corner, corner + cColumns + 1, corner + cColumns});
        }
    const std::uint32_t back = static_cast<std::uint32_t>(settings.mMesh.mPositions.size());
    settings.mMesh.mPositions.push_back(Vec3(1.0, 0.0, 0.0));
    settings.mMesh.mTriangles.push_back({0u, back, 1u});
    const ObjectId body = world.CreateDeformableObject(car, settings).Get();

    // The engine reports the front panel's centre touching the wall (normal from the wall to the car).
    ContactEvent contact;
    contact.mBodyA = car;
    contact.mBodyB = wall;
    contact.mPointOnA = contact.mPointOnB = Vec3(2.0, 0.0, 0.0);
    contact.mNormal = Vec3(-1.0, 0.0, 0.0);
    contact.mTime = 0.0;
    if (Status status = world.SubmitContacts({&contact, 1}); !status)
    {
        std::fprintf(stderr, "refused: %s\n", status.GetError().mMessage.c_str());
        return 2;
    }

    // 50 ms later the collision's window closes and the dent is applied.
    const UpdateReport report = world.Update(0.05);
    const ffd::FfdDeformer& deformer = world.GetObject(body)->GetDeformer();
    std::printf("%d collision dispatched, %u vertices moved\n", report.mCollisionsDispatched,
                static_cast<unsigned>(report.mVerticesMoved));
    // The vertex at the hit is pushed back; the panel's corner, 1.1 m away, is not.
    const std::size_t hit = (cRows / 2) * cColumns + cColumns / 2; // (2, 0, 0)
    const std::size_t corner = 0;                                  // (2, -1, -0.5)
    for (const auto& [name, vertex] : {std::pair{"at the hit", hit}, std::pair{"panel corner", corner}})
        std::printf("%-12s (%.1f, %.1f, %.1f): x %.4f m -> %.4f m\n", name, deformer.GetRestMesh().mPositions[vertex].x(),
                    deformer.GetRestMesh().mPositions[vertex].y(), deformer.GetRestMesh().mPositions[vertex].z(),
                    deformer.GetRestMesh().mPositions[vertex].x(), deformer.GetPositions()[vertex].x());
    const bool dented = deformer.GetPositions()[hit].x() < deformer.GetRestMesh().mPositions[hit].x();
    return report.mCollisionsDispatched == 1 && dented ? 0 : 1;
}
