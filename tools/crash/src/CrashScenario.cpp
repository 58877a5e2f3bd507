// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/crash/CrashScenario.h>

namespace crumple::crash
{

const char* ToString(EEngine inEngine)
{
    switch (inEngine)
    {
    case EEngine::Bullet:
        return "bullet";
    case EEngine::Ode:
        return "ode";
    }
    return "unknown";
}

const char* ToString(EQuantity inQuantity)
{
    switch (inQuantity)
    {
    case EQuantity::ResidualCrush:
        return "residual_crush_m";
    case EQuantity::DeltaV:
        return "delta_v_m_s";
    case EQuantity::TotalImpulse:
        return "total_impulse_N_s";
    case EQuantity::EnergyAbsorbed:
        return "energy_absorbed_J";
    case EQuantity::Collisions:
        return "collisions";
    case EQuantity::FoldedVertices:
        return "folded_vertices";
    case EQuantity::OutwardDisplacement:
        return "outward_displacement_m";
    case EQuantity::FoldedTriangles:
        return "folded_triangles";
    case EQuantity::CrushAverage:
        return "crush_average_m";
    case EQuantity::PeakDeceleration:
        return "peak_deceleration_m_s2";
    case EQuantity::TimeToZeroVelocity:
        return "time_to_zero_velocity_s";
    case EQuantity::WallGap:
        return "wall_gap_m";
    }
    return "unknown";
}

const char* ToString(EZone inZone)
{
    switch (inZone)
    {
    case EZone::Any:
        return "any";
    case EZone::Front:
        return "front";
    case EZone::Rear:
        return "rear";
    case EZone::Left:
        return "left";
    case EZone::Right:
        return "right";
    case EZone::Roof:
        return "roof";
    }
    return "unknown";
}

} // namespace crumple::crash
