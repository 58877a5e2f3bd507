// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/crash/ScenarioFile.h>

#include <ScratchDirectory.h>

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

using namespace crumple;
using namespace crumple::crash;

namespace
{

/// Writes inText to inPath (creating its folder) and returns inPath.
std::filesystem::path WriteText(const std::filesystem::path& inPath, const std::string& inText)
{
    std::filesystem::create_directories(inPath.parent_path());
    std::ofstream(inPath, std::ios::binary) << inText;
    return inPath;
}

/// A folder of its own under this process's scratch folder (/tmp/crumple-test-<pid>).
std::filesystem::path TestFolder(const std::string& inName)
{
    const std::filesystem::path folder = common::ScratchDirectory() / ("scenario-" + inName);
    std::filesystem::create_directories(folder);
    return folder;
}

/// inText as a JSON string (quotes and backslashes escaped).
std::string JsonString(const std::string& inText)
{
    std::string quoted = "\"";
    for (const char c : inText)
    {
        if (c == '"' || c == '\\')
            quoted += '\\';
        quoted += c;
    }
    return quoted + "\"";
}

bool StartsWith(const std::string& inText, const std::string& inPrefix)
{
    return inText.compare(0, inPrefix.size(), inPrefix) == 0;
}

/// The smallest valid scenario, with inVehicle / inImpact / inExtra spliced in for the refusal cases.
std::string Minimal(const std::string& inVehicle = R"("mass_kg": 1200)",
                    const std::string& inImpact = R"("speed_km_h": 56)", const std::string& inExtra = "")
{
    return R"({"name": "t", "vehicle": {)" + inVehicle + R"(}, "impact": {)" + inImpact + "}" +
           (inExtra.empty() ? "" : ", " + inExtra) + "}";
}

const char* cFullScenario = R"({
    "name": "frontal 56 km/h rigid barrier",
    "engine": "ode",
    "duration_s": 0.25,
    "time_step_s": 0.004,
    "vehicle": {
        "mesh": "meshes/car.glb",
        "mesh_length_m": 4.5,
        "box_size_m": [4.5, 1.75, 1.5],
        "mass_kg": 1325,
        "inertia_kg_m2": [500, 2000, 2200],
        "control_count": [12, 8, 6],
        "material": {"deformation_factor_m_per_N_s": 3e-5, "min_deformation_m": 0.002, "max_deformation_m": 0.4}
    },
    "target": {"type": "rigid_wall", "angle_deg": -30},
    "impact": {"speed_m_s": 15.5, "heading_deg": 5, "offset_m": -0.25},
    "expectations": [
        {"quantity": "residual_crush_m", "zone": "front", "min": 0.2, "max": 0.6},
        {"quantity": "residual_crush_m", "zone": "roof", "max": 0.0},
        {"quantity": "delta_v_km_h", "min": 54, "max": 72},
        {"quantity": "delta_v_m_s", "min": 15},
        {"quantity": "total_impulse_N_s", "min": 1e4, "max": 3e4},
        {"quantity": "energy_absorbed_J", "min": 1.2e5},
        {"quantity": "collisions", "min": 1},
        {"quantity": "folded_vertices", "max": 0}
    ],
    "outputs": {"pictures": false}
})";

} // namespace

TEST_CASE("ScenarioFile: a full scenario parses to exact SI values", "[crash]")
{
    const std::filesystem::path folder = TestFolder("full");
    const std::filesystem::path mesh = WriteText(folder / "meshes" / "car.glb", "glTF");

    const Result<CrashScenario> result = ParseCrashScenario(cFullScenario, folder);
    INFO((result ? std::string() : result.GetError().mMessage));
    REQUIRE(result.IsValid());
    const CrashScenario& scenario = result.Get();

    CHECK(scenario.mName == "frontal 56 km/h rigid barrier");
    CHECK(scenario.mEngine == EEngine::Ode);
    CHECK(scenario.mDuration == 0.25);
    CHECK(scenario.mTimeStep == 0.004);

    const VehicleSpec& vehicle = scenario.mVehicle;
    CHECK(std::filesystem::equivalent(vehicle.mMesh, mesh));
    CHECK(vehicle.mMesh.is_absolute() == folder.is_absolute());
    CHECK(vehicle.mMeshLength == 4.5);
    CHECK(vehicle.mBoxSize == Vec3(4.5, 1.75, 1.5));
    CHECK(vehicle.mMass == 1325.0);
    REQUIRE(vehicle.mInertia.has_value());
    CHECK(*vehicle.mInertia == Vec3(500.0, 2000.0, 2200.0));
    CHECK(vehicle.mControlCount == std::array<int, 3>{{12, 8, 6}});
    CHECK(vehicle.mMaterial.mDeformationFactor == 3e-5);
    CHECK(vehicle.mMaterial.mMinDeformation == 0.002);
    CHECK(vehicle.mMaterial.mMaxInstantDeformation == 0.4);

    CHECK(scenario.mTarget.mType == ETarget::RigidWall);
    CHECK(scenario.mTarget.mAngleDegrees == -30.0);
    CHECK(scenario.mImpact.mSpeed == 15.5);
    CHECK(scenario.mImpact.mHeadingDegrees == 5.0);
    CHECK(scenario.mImpact.mOffset == -0.25);
    CHECK_FALSE(scenario.mPictures);

    constexpr double inf = std::numeric_limits<double>::infinity();
    const std::vector<Expectation>& list = scenario.mExpectations;
    REQUIRE(list.size() == 8);
    CHECK(list[0].mQuantity == EQuantity::ResidualCrush);
    CHECK(list[0].mZone == EZone::Front);
    CHECK(list[0].mMin == 0.2);
    CHECK(list[0].mMax == 0.6);
    CHECK(list[0].mText == "residual_crush_m(front) in [0.2, 0.6]");
    CHECK(list[1].mZone == EZone::Roof);
    CHECK(list[1].mMin == -inf);
    CHECK(list[1].mMax == 0.0);
    CHECK(list[1].mText == "residual_crush_m(roof) <= 0");
    CHECK(list[2].mQuantity == EQuantity::DeltaV);
    CHECK(list[2].mZone == EZone::Any);
    CHECK(list[2].mMin == 15.0); // 54 km/h
    CHECK(list[2].mMax == 20.0); // 72 km/h
    CHECK(list[2].mText == "delta_v_km_h in [54, 72]");
    CHECK(list[3].mQuantity == EQuantity::DeltaV);
    CHECK(list[3].mMin == 15.0);
    CHECK(list[3].mMax == inf);
    CHECK(list[3].mText == "delta_v_m_s >= 15");
    CHECK(list[4].mQuantity == EQuantity::TotalImpulse);
    CHECK(list[4].mMin == 1e4);
    CHECK(list[4].mMax == 3e4);
    CHECK(list[5].mQuantity == EQuantity::EnergyAbsorbed);
    CHECK(list[5].mMin == 1.2e5);
    CHECK(list[6].mQuantity == EQuantity::Collisions);
    CHECK(list[6].mText == "collisions >= 1");
    CHECK(list[7].mQuantity == EQuantity::FoldedVertices);
    CHECK(list[7].mMax == 0.0);
    CHECK(list[7].mText == "folded_vertices <= 0");
}

TEST_CASE("ScenarioFile: defaults apply to keys left out", "[crash]")
{
    const Result<CrashScenario> result = ParseCrashScenario(Minimal(), {});
    REQUIRE(result.IsValid());
    const CrashScenario& scenario = result.Get();
    const CrashScenario defaults;

    CHECK(scenario.mName == "t");
    CHECK(scenario.mEngine == EEngine::Bullet);
    CHECK(scenario.mDuration == defaults.mDuration);
    CHECK(scenario.mTimeStep == defaults.mTimeStep);
    CHECK(scenario.mVehicle.mMesh.empty());
    CHECK(scenario.mVehicle.mMeshLength == defaults.mVehicle.mMeshLength);
    CHECK(scenario.mVehicle.mBoxSize == defaults.mVehicle.mBoxSize);
    CHECK(scenario.mVehicle.mMass == 1200.0);
    CHECK_FALSE(scenario.mVehicle.mInertia.has_value());
    CHECK(scenario.mVehicle.mControlCount == defaults.mVehicle.mControlCount);
    CHECK(scenario.mVehicle.mMaterial.mDeformationFactor == defaults.mVehicle.mMaterial.mDeformationFactor);
    CHECK(scenario.mVehicle.mMaterial.mMinDeformation == defaults.mVehicle.mMaterial.mMinDeformation);
    CHECK(scenario.mVehicle.mMaterial.mMaxInstantDeformation ==
          defaults.mVehicle.mMaterial.mMaxInstantDeformation);
    CHECK(scenario.mTarget.mType == ETarget::RigidWall);
    CHECK(scenario.mTarget.mAngleDegrees == 0.0);
    CHECK(scenario.mImpact.mHeadingDegrees == 0.0);
    CHECK(scenario.mImpact.mOffset == 0.0);
    CHECK(scenario.mExpectations.empty());
    CHECK(scenario.mPictures);
    CHECK(scenario.mVehicle.mMeshRigidParts == std::vector<std::string>{"wheel", "tire", "tyre"});

    // Rigid parts named, or none
    const std::filesystem::path body = WriteText(TestFolder("rigid-parts") / "body.obj", "v 0 0 0\n");
    const std::string with_mesh = R"("mass_kg": 900, "mesh": )" + JsonString(body.string()) + ", ";
    const Result<CrashScenario> hubs = ParseCrashScenario(Minimal(with_mesh + R"("mesh_rigid_parts": ["Hub", "rim"])"), {});
    REQUIRE(hubs.IsValid());
    CHECK(hubs.Get().mVehicle.mMeshRigidParts == std::vector<std::string>{"Hub", "rim"});
    const Result<CrashScenario> none = ParseCrashScenario(Minimal(with_mesh + R"("mesh_rigid_parts": [])"), {});
    REQUIRE(none.IsValid());
    CHECK(none.Get().mVehicle.mMeshRigidParts.empty());
    // Without a mesh, a mesh key would be ignored: refused, named
    const Result<CrashScenario> orphan = ParseCrashScenario(Minimal(R"("mass_kg": 900, "mesh_rigid_parts": ["Hub"])"), {});
    REQUIRE(orphan.HasError());
    CHECK(orphan.GetError().mMessage == "/vehicle/mesh_rigid_parts: needs a mesh (the procedural box has none)");

    // A material with some keys keeps the defaults of the others
    const Result<CrashScenario> partial =
        ParseCrashScenario(Minimal(R"("mass_kg": 900, "material": {"max_deformation_m": 0.5})"), {});
    REQUIRE(partial.IsValid());
    CHECK(partial.Get().mVehicle.mMaterial.mMaxInstantDeformation == 0.5);
    CHECK(partial.Get().mVehicle.mMaterial.mCrushZoneFraction == defaults.mVehicle.mMaterial.mCrushZoneFraction);
    const Result<CrashScenario> zone =
        ParseCrashScenario(Minimal(R"("mass_kg": 900, "material": {"crush_zone_fraction": 0.3})"), {});
    REQUIRE(zone.IsValid());
    CHECK(zone.Get().mVehicle.mMaterial.mCrushZoneFraction == 0.3);
    // The sides' own stiffness: off unless all three keys are given
    CHECK_FALSE(partial.Get().mVehicle.mMaterial.mHasSideStiffness);
    const Result<CrashScenario> side = ParseCrashScenario(
        Minimal(
            R"("mass_kg": 900, "material": {"side_crush_A_N_per_m": 20000, "side_crush_B_N_per_m2": 150000, "side_crush_G_J_per_m": 1333})"),
        {});
    REQUIRE(side.IsValid());
    CHECK(side.Get().mVehicle.mMaterial.mHasSideStiffness);
    CHECK(side.Get().mVehicle.mMaterial.mSideCrushA == 20000.0);
    CHECK(side.Get().mVehicle.mMaterial.mSideCrushB == 150000.0);
    CHECK(side.Get().mVehicle.mMaterial.mSideCrushG == 1333.0);
    CHECK(side.Get().mVehicle.mMaterial.mCrushB == defaults.mVehicle.mMaterial.mCrushB); // the ends' kept
    // The rear's own stiffness alike
    CHECK_FALSE(partial.Get().mVehicle.mMaterial.mHasRearStiffness);
    const Result<CrashScenario> rear = ParseCrashScenario(
        Minimal(
            R"("mass_kg": 900, "material": {"rear_crush_A_N_per_m": 30000, "rear_crush_B_N_per_m2": 250000, "rear_crush_G_J_per_m": 1800})"),
        {});
    REQUIRE(rear.IsValid());
    CHECK(rear.Get().mVehicle.mMaterial.mHasRearStiffness);
    CHECK(rear.Get().mVehicle.mMaterial.mRearCrushA == 30000.0);
    CHECK(rear.Get().mVehicle.mMaterial.mRearCrushB == 250000.0);
    CHECK(rear.Get().mVehicle.mMaterial.mRearCrushG == 1800.0);
    CHECK_FALSE(rear.Get().mVehicle.mMaterial.mHasSideStiffness);
    const Result<CrashScenario> rear_partial =
        ParseCrashScenario(Minimal(R"("mass_kg": 900, "material": {"rear_crush_B_N_per_m2": 250000})"), {});
    REQUIRE(rear_partial.HasError());
    CHECK(rear_partial.GetError().mMessage.find("go together") != std::string::npos);
    CHECK(partial.Get().mVehicle.mMaterial.mDeformationFactor ==
          defaults.mVehicle.mMaterial.mDeformationFactor);
}

TEST_CASE("ScenarioFile: km/h is converted to m/s exactly", "[crash]")
{
    const Result<CrashScenario> result =
        ParseCrashScenario(Minimal(R"("mass_kg": 1200)", R"("speed_km_h": 56)",
                                   R"("expectations": [{"quantity": "delta_v_km_h", "min": 36, "max": 56}])"),
                           {});
    REQUIRE(result.IsValid());
    // 56 km/h = 140/9 m/s = 15.5555... m/s: the double nearest it, as one division gives it
    CHECK(result.Get().mImpact.mSpeed == 140.0 / 9.0);
    CHECK(result.Get().mExpectations[0].mMin == 10.0);
    CHECK(result.Get().mExpectations[0].mMax == 140.0 / 9.0);
    CHECK(result.Get().mExpectations[0].mText == "delta_v_km_h in [36, 56]");

    const Result<CrashScenario> metres =
        ParseCrashScenario(Minimal(R"("mass_kg": 1200)", R"("speed_m_s": 7.25)"), {});
    REQUIRE(metres.IsValid());
    CHECK(metres.Get().mImpact.mSpeed == 7.25);
}

TEST_CASE("ScenarioFile: each malformed scenario is refused with its JSON pointer", "[crash]")
{
    struct Case
    {
        std::string mJson;
        EError mCode;
        std::string mMessage; ///< The message must start with this
    };
    const std::string mass = R"("mass_kg": 1200)";
    const std::string speed = R"("speed_km_h": 56)";
    const std::vector<Case> cases = {
        // Unknown keys, with the known ones and unit hints
        {Minimal(R"("mass_lb": 2600)"), EError::InvalidArgument,
         "/vehicle/mass_lb: unknown key; masses are mass_kg (known: mesh, mesh_name, mesh_length_m, "
         "mesh_unit_m, "
         "mesh_forward_axis, mesh_up_axis, mesh_max_edge_m, mesh_flip_deviation_m, mesh_rigid_parts, "
         "box_size_m, mass_kg, "
         "inertia_kg_m2, inertia_from, control_count, control_spacing_m, zones, material)"},
        {Minimal(R"("mass_kg": 1200, "zones": [{"min_m": [0, 0, 0], "max_m": [1, 0, 1]}])"),
         EError::InvalidArgument,
         "/vehicle/zones/0/max_m: must exceed min_m by at least 0.001 m on every axis"},
        {Minimal(R"("mass_kg": 1200, "zones": [{"max_m": [1, 1, 1]}])"), EError::InvalidArgument,
         "/vehicle/zones/0/min_m: required"},
        {Minimal(R"("mass_kg": 1200, "inertia_from": "mesh_shell")"), EError::InvalidArgument,
         "/vehicle/inertia_from: \"mesh_shell\" needs a mesh"},
        {Minimal(mass, R"("speed_mph": 35)"), EError::InvalidArgument,
         "/impact/speed_mph: unknown key; speeds are speed_km_h or speed_m_s"},
        {Minimal(mass, speed, R"("duration_ms": 600)"), EError::InvalidArgument,
         "/duration_ms: unknown key; durations are duration_s"},
        {Minimal(mass, speed, R"("colour": "red")"), EError::InvalidArgument,
         "/colour: unknown key (known: name, engine, duration_s, time_step_s, vehicle, target, impact, "
         "expectations, outputs)"},
        {Minimal(mass, speed, R"("target": {"angle_rad": 0.5})"), EError::InvalidArgument,
         "/target/angle_rad: unknown key; angles are angle_deg"},
        {Minimal(mass, speed, R"("expectations": [{"quantity": "collisions", "min": 1, "mean": 2}])"),
         EError::InvalidArgument, "/expectations/0/mean: unknown key (known: quantity, zone, min, max)"},
        // A quantity the target does not have
        {Minimal(mass, speed,
                 R"("target": {"type": "pole"}, "expectations": [{"quantity": "collisions", "min": 1}, )"
                 R"({"quantity": "wall_gap_m", "max": 0.1}])"),
         EError::InvalidArgument,
         "/expectations/1/quantity: wall_gap_m needs a rigid_wall or offset_wall target (a flat wall)"},
        // Wrong types
        {Minimal(mass, speed, R"("duration_s": "0.6")"), EError::InvalidArgument,
         "/duration_s: must be a number, got string"},
        {Minimal(mass, speed, R"("duration_s": "nan")"), EError::InvalidArgument,
         "/duration_s: must be a number, got string"},
        {Minimal(mass, speed, R"("time_step_s": null)"), EError::InvalidArgument,
         "/time_step_s: must be a number, got null"},
        {Minimal(R"("mass_kg": 1200, "mesh_rigid_parts": "wheel")"), EError::InvalidArgument,
         "/vehicle/mesh_rigid_parts: must be an array of strings (name fragments), got string"},
        {Minimal(R"("mass_kg": 1200, "mesh_rigid_parts": ["wheel", ""])"), EError::InvalidArgument,
         "/vehicle/mesh_rigid_parts/1: must be a non-empty string, got string"},
        {Minimal(R"("mass_kg": 1200, "box_size_m": [4, 2])"), EError::InvalidArgument,
         "/vehicle/box_size_m: must be an array of 3 numbers, got an array of 2"},
        {Minimal(R"("mass_kg": 1200, "control_count": [10, 6.5, 6])"), EError::InvalidArgument,
         "/vehicle/control_count/1: must be an integer, got 6.5"},
        {Minimal(mass, speed, R"("outputs": {"pictures": "yes"})"), EError::InvalidArgument,
         "/outputs/pictures: must be true or false, got string"},
        {Minimal(mass, speed, R"("expectations": {"quantity": "collisions"})"), EError::InvalidArgument,
         "/expectations: must be an array, got object"},
        {"[1, 2]", EError::InvalidArgument, "/: must be an object, got array"},
        {R"({"name": 5, "vehicle": {"mass_kg": 1}, "impact": {"speed_m_s": 1}})", EError::InvalidArgument,
         "/name: must be a string, got number"},
        // Missing required keys
        {Minimal(R"("mesh_length_m": 4)"), EError::InvalidArgument, "/vehicle/mass_kg: required"},
        {R"({"vehicle": {"mass_kg": 1}, "impact": {"speed_m_s": 1}})", EError::InvalidArgument,
         "/name: required"},
        {R"({"name": "t", "impact": {"speed_m_s": 1}})", EError::InvalidArgument, "/vehicle: required"},
        {Minimal(mass, R"("heading_deg": 0)"), EError::InvalidArgument,
         "/impact/speed_km_h: required (or speed_m_s)"},
        {Minimal(mass, R"("speed_km_h": 56, "speed_m_s": 15)"), EError::InvalidArgument,
         "/impact/speed_m_s: give speed_km_h or speed_m_s, not both"},
        {Minimal(mass, speed, R"("expectations": [{"min": 1}])"), EError::InvalidArgument,
         "/expectations/0/quantity: required"},
        {Minimal(mass, speed, R"("expectations": [{"quantity": "collisions"}])"), EError::InvalidArgument,
         "/expectations/0: needs min, max or both"},
        // Numbers out of range or not finite
        {Minimal(R"("mass_kg": -5)"), EError::InvalidArgument,
         "/vehicle/mass_kg: must be in (0, 1e+12], got -5"},
        // Past the core's ranges: refused with the key, not met by an abort in the scene
        {Minimal(R"("mass_kg": 1e13)"), EError::InvalidArgument,
         "/vehicle/mass_kg: must be in (0, 1e+12], got 1e+13"},
        {Minimal(mass, speed, R"("duration_s": 1e999)"), EError::InvalidArgument,
         "/duration_s: must be finite; number overflow parsing '1e999'"},
        {Minimal(R"("mass_kg": 1200, "box_size_m": [4, -1e999, 1])"), EError::InvalidArgument,
         "/vehicle/box_size_m/1: must be finite; number overflow parsing '-1e999'"},
        {Minimal(mass, speed, R"("time_step_s": 0.1)"), EError::InvalidArgument,
         "/time_step_s: must be in [1e-06, 0.05], got 0.1"},
        {Minimal(mass, speed, R"("duration_s": 3000, "time_step_s": 1e-5)"), EError::InvalidArgument,
         "/duration_s: takes more than 1e7 steps of time_step_s"},
        {Minimal(mass, R"("speed_km_h": 56, "heading_deg": 1e100)"), EError::InvalidArgument,
         "/impact/heading_deg: must be in [-360, 360], got 1e+100"},
        {Minimal(mass, speed, R"("duration_s": 0.01, "time_step_s": 0.02)"), EError::InvalidArgument,
         "/time_step_s: must be <= duration_s (0.01), got 0.02"},
        {Minimal(mass, R"("speed_km_h": 0)"), EError::InvalidArgument,
         "/impact/speed_km_h: must be in (0, 3600], got 0"},
        {Minimal(R"("mass_kg": 1200, "box_size_m": [4, 0, 1])"), EError::InvalidArgument,
         "/vehicle/box_size_m/1: must be in [0.1, 1000], got 0"},
        {Minimal(R"("mass_kg": 1200, "box_size_m": [4, 1.8, 0.05])"), EError::InvalidArgument,
         "/vehicle/box_size_m/2: must be in [0.1, 1000], got 0.05"},
        {Minimal(R"("mass_kg": 1200, "inertia_kg_m2": [1, 1, -1])"), EError::InvalidArgument,
         "/vehicle/inertia_kg_m2/2: must be > 0, got -1"},
        {Minimal(R"("mass_kg": 1200, "inertia_kg_m2": [100, 100, 300])"), EError::InvalidArgument,
         "/vehicle/inertia_kg_m2/2: must be <= the sum of the other two moments (200), got 300"},
        {Minimal(R"("mass_kg": 1200, "control_count": [10, 3, 6])"), EError::InvalidArgument,
         "/vehicle/control_count/1: must be in [4, 256], got 3"},
        {Minimal(R"("mass_kg": 1, "material": {"min_deformation_m": 0.1, "max_deformation_m": 0.05})"),
         EError::InvalidArgument,
         "/vehicle/material/max_deformation_m: must be >= min_deformation_m (0.1), got 0.05"},
        {Minimal(R"("mass_kg": 1, "material": {"deformation_factor_m_per_N_s": -1e-5})"),
         EError::InvalidArgument, "/vehicle/material/deformation_factor_m_per_N_s: must be >= 0, got -1e-05"},
        {Minimal(R"("mass_kg": 1, "material": {"crush_zone_fraction": 0.6})"), EError::InvalidArgument,
         "/vehicle/material/crush_zone_fraction: must be in (0, 0.5], got 0.6"},
        {Minimal(R"("mass_kg": 1, "material": {"crush_zone_fraction": 0})"), EError::InvalidArgument,
         "/vehicle/material/crush_zone_fraction: must be in (0, 0.5], got 0"},
        {Minimal(R"("mass_kg": 1, "material": {"side_crush_A_N_per_m": 1, "side_crush_B_N_per_m2": 2})"),
         EError::InvalidArgument,
         "/vehicle/material/side_crush_A_N_per_m: side_crush_A_N_per_m, side_crush_B_N_per_m2 and "
         "side_crush_G_J_per_m go "
         "together: give all three or none"},
        {Minimal(
             R"("mass_kg": 1, "material": {"side_crush_A_N_per_m": 1, "side_crush_B_N_per_m2": 0, "side_crush_G_J_per_m": 0})"),
         EError::InvalidArgument, "/vehicle/material/side_crush_B_N_per_m2: must be in (0, 1e+12], got 0"},
        {Minimal(mass, speed, R"("target": {"angle_deg": 90})"), EError::InvalidArgument,
         "/target/angle_deg: must be in (-90, 90), got 90"},
        {Minimal(mass, speed, R"("expectations": [{"quantity": "collisions", "min": 3, "max": 1}])"),
         EError::InvalidArgument, "/expectations/0/max: must be >= min (3), got 1"},
        // Unknown enumeration values
        {Minimal(mass, speed, R"("engine": "havok")"), EError::InvalidArgument,
         R"(/engine: must be "bullet" or "ode", got "havok")"},
        {Minimal(mass, speed, R"("target": {"type": "tree"})"), EError::InvalidArgument,
         R"(/target/type: must be one of "rigid_wall", "pole", "offset_wall", "vehicle" or "fem_barrier", got "tree")"},
        {Minimal(mass, speed, R"("target": {"type": "fem_barrier", "material": "cheese"})"),
         EError::InvalidArgument, "/target/material: must be one of"},
        {Minimal(mass, speed,
                 R"("target": {"type": "fem_barrier", "size_m": [0.2, 3, 1.2], "cell_m": 0.001})"),
         EError::InvalidArgument, "/target/cell_m: makes more than 200 cells"},
        {Minimal(mass, speed, R"("target": {"type": "rigid_wall", "mass_kg": 900})"), EError::InvalidArgument,
         "/target/mass_kg: does not apply to this target type"},
        {Minimal(mass, speed, R"("target": {"type": "vehicle", "speed_km_h": -5})"), EError::InvalidArgument,
         "/target/speed_km_h: must be in [0, 3600], got -5"},
        {Minimal(mass, speed, R"("target": {"type": "pole", "angle_deg": 10})"), EError::InvalidArgument,
         "/target/angle_deg: does not apply to this target type"},
        {Minimal(mass, speed, R"("target": {"type": "offset_wall", "overlap_percent": 0})"),
         EError::InvalidArgument, "/target/overlap_percent: must be in (0, 100]"},
        {Minimal(mass, speed,
                 R"("expectations": [{"quantity": "residual_crush_m", "zone": "top", "max": 0}])"),
         EError::InvalidArgument,
         R"(/expectations/0/zone: must be one of "any", "front", "rear", "left", "right" or "roof", got "top")"},
        {Minimal(mass, speed, R"("expectations": [{"quantity": "delta_v_mph", "max": 30}])"),
         EError::InvalidArgument, "/expectations/0/quantity: must be one of "},
        {Minimal(mass, speed, R"("expectations": [{"quantity": "collisions", "zone": "front", "max": 3}])"),
         EError::InvalidArgument, "/expectations/0/zone: only residual_crush_m has a zone"},
        // A key given twice
        {Minimal(R"("mass_kg": 1200, "mass_kg": 900)"), EError::InvalidArgument,
         "/vehicle/mass_kg: duplicate key"},
        {Minimal(mass, speed,
                 R"("expectations": [{"quantity": "collisions", "min": 1}, {"min": 1, "min": 2}])"),
         EError::InvalidArgument, "/expectations/1/min: duplicate key"},
        // The mesh must exist
        {Minimal(R"("mass_kg": 1200, "mesh": "no/such/car.glb")"), EError::IoError,
         "/vehicle/mesh: file not found: "},
        {Minimal(R"("mass_kg": 1200, "mesh": "")"), EError::InvalidArgument,
         "/vehicle/mesh: must not be empty"},
        // Not JSON
        {"", EError::CorruptData, "line 1, column 1: "},
        {R"({"name": "t", "duration_s": nan})", EError::CorruptData, "line 1, column 30: "},
        {"{\n  \"name\": \"t\",\n}", EError::CorruptData, "line 3, column 1: "},
    };
    REQUIRE(cases.size() >= 12);

    const std::filesystem::path folder = TestFolder("refusals");
    for (const Case& test : cases)
    {
        INFO(test.mJson);
        Result<CrashScenario> result(Error{});
        REQUIRE_NOTHROW(result = ParseCrashScenario(test.mJson, folder));
        REQUIRE(result.HasError());
        INFO(result.GetError().mMessage);
        CHECK(result.GetError().mCode == test.mCode);
        CHECK(StartsWith(result.GetError().mMessage, test.mMessage));
    }
}

TEST_CASE("ScenarioFile: hints name the accepted units", "[crash]")
{
    const Result<CrashScenario> quantity =
        ParseCrashScenario(Minimal(R"("mass_kg": 1)", R"("speed_m_s": 1)",
                                   R"("expectations": [{"quantity": "delta_v_mph", "max": 30}])"),
                           {});
    REQUIRE(quantity.HasError());
    CHECK_THAT(quantity.GetError().mMessage, Catch::Contains("delta-v is delta_v_m_s or delta_v_km_h"));
    CHECK_THAT(quantity.GetError().mMessage, Catch::Contains(R"(got "delta_v_mph")"));
}

TEST_CASE("ScenarioFile: a relative mesh path is resolved against the base folder", "[crash]")
{
    const std::filesystem::path folder = TestFolder("mesh");
    const std::filesystem::path mesh = WriteText(folder / "cars" / "hatch.obj", "v 0 0 0\n");
    const std::filesystem::path scenarios = folder / "scenarios";
    std::filesystem::create_directories(scenarios);

    // Relative to the base folder, through ".."
    const Result<CrashScenario> relative =
        ParseCrashScenario(Minimal(R"("mass_kg": 1200, "mesh": "../cars/hatch.obj")"), scenarios);
    INFO((relative ? std::string() : relative.GetError().mMessage));
    REQUIRE(relative.IsValid());
    CHECK(relative.Get().mVehicle.mMesh == (folder / "cars" / "hatch.obj").lexically_normal());
    CHECK(std::filesystem::equivalent(relative.Get().mVehicle.mMesh, mesh));

    // An absolute path is kept
    const Result<CrashScenario> absolute =
        ParseCrashScenario(Minimal(R"("mass_kg": 1200, "mesh": )" + JsonString(mesh.string())), scenarios);
    REQUIRE(absolute.IsValid());
    CHECK(absolute.Get().mVehicle.mMesh == mesh);

    // Missing: the message names the resolved path
    const Result<CrashScenario> missing =
        ParseCrashScenario(Minimal(R"("mass_kg": 1200, "mesh": "hatch.obj")"), scenarios);
    REQUIRE(missing.HasError());
    CHECK(missing.GetError().mCode == EError::IoError);
    CHECK(missing.GetError().mMessage ==
          "/vehicle/mesh: file not found: " + (scenarios / "hatch.obj").string());

    // A folder is not a mesh
    const Result<CrashScenario> folder_mesh =
        ParseCrashScenario(Minimal(R"("mass_kg": 1200, "mesh": "../cars")"), scenarios);
    REQUIRE(folder_mesh.HasError());
    CHECK(folder_mesh.GetError().mCode == EError::IoError);
}

TEST_CASE("ScenarioFile: a scenario file on disk loads", "[crash]")
{
    const std::filesystem::path folder = TestFolder("load");
    WriteText(folder / "meshes" / "car.glb", "glTF");
    const std::filesystem::path file = WriteText(folder / "frontal.json", cFullScenario);

    const Result<CrashScenario> loaded = LoadCrashScenario(file);
    INFO((loaded ? std::string() : loaded.GetError().mMessage));
    REQUIRE(loaded.IsValid());
    CHECK(loaded.Get().mName == "frontal 56 km/h rigid barrier");
    CHECK(std::filesystem::equivalent(loaded.Get().mVehicle.mMesh, folder / "meshes" / "car.glb"));
    CHECK(loaded.Get().mExpectations.size() == 8);

    // Missing file, a folder: IoError naming the path
    const Result<CrashScenario> missing = LoadCrashScenario(folder / "absent.json");
    REQUIRE(missing.HasError());
    CHECK(missing.GetError().mCode == EError::IoError);
    CHECK_THAT(missing.GetError().mMessage, Catch::Contains((folder / "absent.json").string()));
    const Result<CrashScenario> directory = LoadCrashScenario(folder);
    REQUIRE(directory.HasError());
    CHECK(directory.GetError().mCode == EError::IoError);
    CHECK_THAT(directory.GetError().mMessage, Catch::Contains(folder.string()));

    // Empty, or not JSON: CorruptData with line and column, after the path
    const std::filesystem::path empty = WriteText(folder / "empty.json", "");
    const Result<CrashScenario> empty_result = LoadCrashScenario(empty);
    REQUIRE(empty_result.HasError());
    CHECK(empty_result.GetError().mCode == EError::CorruptData);
    CHECK(StartsWith(empty_result.GetError().mMessage, empty.string() + ": line 1, column 1: "));
    const std::filesystem::path text = WriteText(folder / "notes.json", "name: frontal\n");
    const Result<CrashScenario> text_result = LoadCrashScenario(text);
    REQUIRE(text_result.HasError());
    CHECK(text_result.GetError().mCode == EError::CorruptData);
    CHECK(StartsWith(text_result.GetError().mMessage, text.string() + ": line 1, column "));

    // A refusal of the content keeps its pointer after the path
    const std::filesystem::path bad = WriteText(folder / "bad.json", Minimal(R"("mass_kg": -5)"));
    const Result<CrashScenario> bad_result = LoadCrashScenario(bad);
    REQUIRE(bad_result.HasError());
    CHECK(bad_result.GetError().mMessage == bad.string() + ": /vehicle/mass_kg: must be in (0, 1e+12], got -5");
}

TEST_CASE("ScenarioFile: garbage never throws", "[crash]")
{
    const std::vector<std::string> inputs = {
        std::string("\0\xff\xfe", 3),
        "{\"name\": \"\xc3\x28\"}",
        "[[[[[[[[[[",
        "{\"a\":",
        "123",
        "\"text\"",
        "null",
        "{\"name\": \"t\", \"vehicle\": [], \"impact\": 3}",
        std::string(10000, '['),
    };
    for (const std::string& input : inputs)
    {
        Result<CrashScenario> result(Error{});
        REQUIRE_NOTHROW(result = ParseCrashScenario(input, {}));
        CHECK(result.HasError());
    }
}
