// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include "RaceLog.h"
#include "ScenePainter.h"

#include <crumple/fem/GroundPlane.h>
#include <crumple/fem/TetFence.h>
#include <crumple/fem/TetGrid.h>

#include <crumple/plugin/DamageRecorder.h>
#include <crumple/plugin/DamageWorld.h>

#include <map>

#include <chrono>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace crumple::samples
{

/// The course every racing sample drives, whatever the engine: a straight along +x, three concrete
/// barriers angled 7 degrees into the road from the right (the car scrapes along them), and a parked car
/// further down. World frame: z up, metres.
struct RaceCourse
{
    static Vec3 Gravity() { return {0.0, 0.0, -9.81}; } ///< The world's gravity (m/s^2), z up
    /// The ground z = 0 as the props' FEM meets it (RaceProps): a part left hanging from a prop falls onto
    /// it and comes to rest; friction 0.6, wood or brick on asphalt
    static fem::GroundPlane PropGround() { return {true, Vec3::UnitZ(), 0.0, 0.6}; }
    static constexpr double cBarrierYaw = 0.122;                 ///< Barrier heading (rad)
    static Vec3 BarrierHalfExtents() { return {2.035, 0.405, 0.57}; } ///< A jersey barrier, 4.07 x 0.81 x 1.14 m
    static std::vector<Transform> Barriers();                   ///< Their poses
    static Vec3 ParkedHalfExtents() { return {2.1, 0.9, 0.7}; }   ///< The parked car's box
    /// Its pose, resting on the ground: 0.5 m left of the course line, so that the racing car (2.0 m wide)
    /// meets 1.4 m of its 1.8 m wide end on the line, and still meets it up to 1.4 m right or 2.4 m left of
    /// the line. The fence's pieces knock the car off the line by a chaotic amount: at 1.0 m left (before
    /// 2026-12-08) a change of rounding in the friction solve sent Bullet's default session 1.0 m right, past
    /// it.
    static Transform ParkedCar();
    static constexpr double cParkedMass = 1100.0;               ///< kg
    /// A wooden fence across the road between the barriers and the parked car: 4 m of 10 cm timbers, a post
    /// at each end, two rails (RaceProps)
    static fem::TetFenceSettings FenceSettings();
    static Transform Fence(); ///< Its frame: the fence's x along world y, its face at x = 45 m
    /// A low garden wall of bricks at the road's left edge before the barriers (RaceProps): 1.2 m long, 0.6 m
    /// high on a footing course 0.1 m deep in the ground, two bricks of 0.1 x 0.2 x 0.1 m thick (a grid cell
    /// each)
    static fem::TetGridSettings BrickWallSettings();
    /// Its frame: unturned, its face at x = 14 m, from y = 0.5 to 1.7 m (the car on the course line meets its
    /// first 0.4 m), its footing's base 0.1 m below the ground
    static Transform BrickWall();
    /// The driver's steering angle (rad, about the car's up axis, positive to the left, at most
    /// cMaxSteering): pure pursuit of the course line y = 0 (a point on it a look-ahead ahead of the car), so
    /// that a car knocked off its line by a barrier, the fence or a piece comes back to it instead of the
    /// course's later events depending on where the last knock sent it.
    /// @param inCarPose   the car's pose (its x forward, z up)
    /// @param inWheelBase between the front and rear axles (m, > 0)
    static double SteeringAngle(const Transform& inCarPose, double inWheelBase);
    static constexpr double cMaxSteering = 0.35; ///< rad
};

class RaceProps;

/// Command line of a racing sample.
struct RaceOptions
{
    std::filesystem::path mOut = "racing-output"; ///< Output folder
    double mDuration = 7.0;                       ///< Simulated time (s)
    double mSpeed = 20.0;                         ///< Target speed (m/s)
    bool mPictures = true;                        ///< PNG before/after and frames
    int mThreads = 1;                             ///< Threads of the game's job system handed to Crumple
    bool mDeferDents = false;                     ///< DamageWorldSettings::mDeferDents
    bool mDeferImpulses = false;                  ///< DamageWorldSettings::mDeferImpulses (sets mDeferDents)
    bool mPropsOffThread = false;                 ///< props::PropWorldSettings::mStepOffThread
};

/// Parses --out, --duration, --speed, --threads, --defer-dents, --defer-impulses, --props-off-thread,
/// --no-pictures, --help, --version. Returns -1 to go on, else an exit code.
int ParseRaceOptions(int inArgc, char** inArgv, const char* inProgram, const char* inDescription, RaceOptions& outOptions);

/// The racing car's body mesh: the shipped Toy Car when ../shared/data has it, else a procedural box.
ffd::TriangleMesh RaceCarMesh();

/// Everything a racing sample writes: the replay recording, a collision log, pictures and meshes.
class RaceSession
{
public:
    /// Creates the output folder, the recorder and (when pictures are wanted) the painter.
    static Result<std::unique_ptr<RaceSession>> Create(const RaceOptions& inOptions, plugin::DamageWorld& ioDamage,
                                                       std::map<plugin::BodyId, std::string> inNames);

    /// The racing car alone, coloured by dent depth, from an iso view.
    void PaintCar(const plugin::DeformableObject& inCar, const std::string& inName);
    /// A frame of the scene with a chase camera on the racing car: the course, both cars, the props and their
    /// flying pieces.
    void PaintFrame(const plugin::DeformableObject& inCar, const Transform& inCarPose,
                    const plugin::DeformableObject& inParked, const Transform& inParkedPose,
                    const RaceProps& inProps);
    /// Flushes, closes the recording, writes after.png, car.obj, parked.obj and the props' OBJs (fence.obj,
    /// brick_wall.obj), prints the summary.
    Status Finish(plugin::DamageWorld& ioDamage, const plugin::DeformableObject& inCar,
                  const plugin::DeformableObject& inParked, const RaceProps& inProps);

    /// The recording (for the props to record beside the collisions)
    plugin::DamageRecorder& GetRecorder() { return *mRecorder; }
    /// Stops the log listening to the world when Finish was not reached (a frame failed): the world, which
    /// outlives the session, would call it later (a deferred dent landing as the scene is torn down).
    ~RaceSession();
    /// Names bodies made during the run (the props' pieces) in the collision log, which counts their
    /// collisions without a line each
    void NamePieces(std::span<const plugin::BodyId> inBodies, const std::string& inName)
    {
        for (plugin::BodyId body : inBodies)
            mLog.SetName(body, inName, false);
    }

    /// Brackets one 60 Hz frame of physics (the engine's step with Crumple attached, the props' step, no painting): Finish
    /// prints the worst frame, the 99th percentile and the median, in wall time (what the game's thread
    /// waited, workers included) and in the game thread's CPU time, so that a damage hitch shows.
    void BeginFrame();
    /// inCrumpleMs: Crumple's share of the frame (RaceScene::GetLastFrameCrumpleMs)
    void EndFrame(double inCrumpleMs);

private:
    RaceSession(const RaceOptions& inOptions, plugin::DamageWorld& ioDamage, std::map<plugin::BodyId, std::string> inNames)
        : mOptions(inOptions), mDamage(&ioDamage), mLog(std::move(inNames)) {}

    RaceOptions mOptions;
    plugin::DamageWorld* mDamage = nullptr; ///< Where the painter finds bodies' poses; the log listens to it
    bool mListening = false;                ///< The log is the world's listener (until Finish or the destructor)
    RaceLog mLog;
    std::unique_ptr<plugin::DamageRecorder> mRecorder;
    std::unique_ptr<ScenePainter> mPainter;
    int mFrames = 0;
    double mFrameStartCpuMs = 0.0;
    std::chrono::steady_clock::time_point mFrameStart;
    std::vector<double> mFrameCrumpleMs; ///< Crumple's share of each frame (game-thread CPU, ms)
    std::vector<double> mFrameCpuMs;  ///< Thread CPU time of each physics frame on the game's thread (ms)
    std::vector<double> mFrameWallMs; ///< Wall time of each physics frame (ms): what the game's thread waited
};

} // namespace crumple::samples
