// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/crash/ScenarioFile.h>

#include <crumple/base/FileBytes.h>
#include <crumple/ffd/FfdLatticeSettings.h>
#include <crumple/plugin/BodyState.h>
#include <crumple/plugin/DeformableObjectSettings.h>

#include <nlohmann/json.hpp>

#include <array>
#include <charconv>
#include <cmath>
#include <exception>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

namespace crumple::crash
{

namespace
{

using Json = nlohmann::json;

/// km/h to m/s as (v 1000) / 3600: for whole km/h both steps are exact but the last, so 56 km/h gives the
/// double nearest 140/9 m/s.
double KilometresPerHourToMetresPerSecond(double inKilometresPerHour)
{
    return inKilometresPerHour * 1000.0 / 3600.0;
}

/// Shortest text that reads back as the same double ("0.2", "-5", "1e+300", "inf").
std::string FormatNumber(double inValue)
{
    std::array<char, 32> buffer{};
    const auto [end, error] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), inValue);
    if (error != std::errc())
        return "?";
    return std::string(buffer.data(), end);
}

/// One reference token of a JSON pointer (RFC 6901: "~" as "~0", "/" as "~1").
std::string EscapePointerToken(std::string_view inToken)
{
    std::string escaped;
    for (const char c : inToken)
    {
        if (c == '~')
            escaped += "~0";
        else if (c == '/')
            escaped += "~1";
        else
            escaped += c;
    }
    return escaped;
}

/// The pointer as shown in messages: the root ("") as "/".
std::string ShowPointer(const std::string& inPointer)
{
    return inPointer.empty() ? std::string("/") : inPointer;
}

/// A JSON string quoted and escaped as JSON writes it.
std::string Quote(std::string_view inText)
{
    return Json(std::string(inText)).dump(-1, ' ', false, Json::error_handler_t::replace);
}

/// "a", "b" or "c" (each quoted as a JSON string).
std::string JoinAlternatives(std::initializer_list<std::string_view> inNames)
{
    std::string joined;
    std::size_t index = 0;
    for (const std::string_view name : inNames)
    {
        if (index > 0)
            joined += index + 1 == inNames.size() ? " or " : ", ";
        joined += Quote(name);
        ++index;
    }
    return joined;
}

/// An accepted range of a number: each end open, closed, or absent (infinite).
struct NumberRange
{
    double mLow = -std::numeric_limits<double>::infinity();
    bool mLowOpen = false; ///< True: the value must be > mLow; false: >= mLow
    double mHigh = std::numeric_limits<double>::infinity();
    bool mHighOpen = false; ///< True: the value must be < mHigh; false: <= mHigh

    static NumberRange Any() { return {}; }
    static NumberRange Positive() { return {0.0, true}; }
    static NumberRange NonNegative() { return {0.0, false}; }

    bool Contains(double inValue) const
    {
        const bool above = mLowOpen ? inValue > mLow : inValue >= mLow;
        const bool below = mHighOpen ? inValue < mHigh : inValue <= mHigh;
        return above && below;
    }

    /// "> 0", ">= 4", "in (0, 0.05]"
    std::string Describe() const
    {
        const bool has_low = std::isfinite(mLow);
        const bool has_high = std::isfinite(mHigh);
        if (has_low && has_high)
            return std::string("in ") + (mLowOpen ? "(" : "[") + FormatNumber(mLow) + ", " +
                   FormatNumber(mHigh) + (mHighOpen ? ")" : "]");
        if (has_low)
            return std::string(mLowOpen ? "> " : ">= ") + FormatNumber(mLow);
        if (has_high)
            return std::string(mHighOpen ? "< " : "<= ") + FormatNumber(mHigh);
        return "finite";
    }
};

// Bounds past which a value is no crash test but an overflow in the engines or the core (BodyState's ranges):
// refused with the key's name rather than met by an abort in the scene.
constexpr double cMaxDuration = 3600.0; // s
constexpr double cMinTimeStep = 1.0e-6; // s
constexpr double cMaxSteps = 1.0e7;
NumberRange BodyMass() { return {0.0, true, plugin::cMaxBodyMass, false}; }  // kg
NumberRange BodySize()
{
    return {cMinMeshLength, false, cMaxMeshLength, false};
} // m, each side
NumberRange MeshLength() { return {cMinMeshLength, false, cMaxMeshLength, false}; } // m, a car body's length
NumberRange Heading() { return {-360.0, false, 360.0, false}; }              // degrees

/// A hint for an unknown key that carries a unit we do not accept: a key starting with mStem + "_" (or equal
/// to mStem) gets mHint, e.g. "speed_mph" -> "speeds are speed_km_h or speed_m_s".
struct UnitHint
{
    std::string_view mStem;
    std::string_view mHint;
};

/// The keys one object accepts, with the hints for its unit-carrying ones.
struct ObjectKeys
{
    std::initializer_list<std::string_view> mKnown;
    std::initializer_list<UnitHint> mHints;
};

/// Records the first duplicate key met while parsing (nlohmann keeps the last silently), with its pointer.
class DuplicateKeyFinder
{
  public:
    /// The parser callback: tracks the pointer of the value being read from the parse events.
    bool OnEvent(Json::parse_event_t inEvent, const Json& inParsed)
    {
        switch (inEvent)
        {
        case Json::parse_event_t::object_start:
            mFrames.emplace_back(false);
            break;
        case Json::parse_event_t::array_start:
            mFrames.emplace_back(true);
            break;
        case Json::parse_event_t::key:
            if (!mFrames.empty() && inParsed.is_string())
            {
                Frame& frame = mFrames.back();
                frame.mKey = inParsed.get<std::string>();
                if (!frame.mKeys.insert(frame.mKey).second && !mDuplicate)
                    mDuplicate = Pointer();
            }
            break;
        case Json::parse_event_t::object_end:
        case Json::parse_event_t::array_end:
            // A finished container is one finished element of its parent
            if (!mFrames.empty())
                mFrames.pop_back();
            NextElement();
            break;
        case Json::parse_event_t::value:
            NextElement();
            break;
        }
        return true;
    }

    /// The pointer of the first duplicate key, if any
    const std::optional<std::string>& GetDuplicate() const { return mDuplicate; }

    /// The pointer of the value being read (where a parse stopped)
    std::string Pointer() const
    {
        std::string pointer;
        for (const Frame& frame : mFrames)
        {
            pointer += '/';
            pointer += frame.mArray ? std::to_string(frame.mIndex) : EscapePointerToken(frame.mKey);
        }
        return pointer;
    }

  private:
    struct Frame
    {
        explicit Frame(bool inArray) : mArray(inArray) {}

        bool mArray = false;
        std::size_t mIndex = 0;      ///< Array: index of the element being read
        std::string mKey;            ///< Object: key of the value being read
        std::set<std::string> mKeys; ///< Object: keys seen so far
    };

    void NextElement()
    {
        if (!mFrames.empty() && mFrames.back().mArray)
            ++mFrames.back().mIndex;
    }

    std::vector<Frame> mFrames;
    std::optional<std::string> mDuplicate;
};

/// Reads a parsed document into a CrashScenario, stopping at the first refusal (kept in mError). Each Read*
/// returns false once it has refused; absent optional keys leave the struct's defaults.
class ScenarioReader
{
  public:
    explicit ScenarioReader(const std::filesystem::path& inBaseFolder) : mBaseFolder(inBaseFolder) {}

    Result<CrashScenario> Read(const Json& inRoot)
    {
        CrashScenario scenario;
        if (!ReadRoot(inRoot, scenario))
            return *mError;
        return scenario;
    }

  private:
    /// Records a refusal of the value at inPointer; returns false for `return Fail(...)`.
    bool Fail(EError inCode, const std::string& inPointer, const std::string& inWhat)
    {
        mError = MakeError(inCode, ShowPointer(inPointer) + ": " + inWhat);
        return false;
    }

    static std::string Child(const std::string& inPointer, std::string_view inKey)
    {
        return inPointer + "/" + EscapePointerToken(inKey);
    }

    /// "must be a number, got string"
    bool FailType(const std::string& inPointer, std::string_view inExpected, const Json& inValue)
    {
        return Fail(EError::InvalidArgument, inPointer,
                    "must be " + std::string(inExpected) + ", got " + std::string(inValue.type_name()));
    }

    bool ExpectObject(const Json& inValue, const std::string& inPointer)
    {
        return inValue.is_object() || FailType(inPointer, "an object", inValue);
    }

    /// Refuses the first key of inObject that inKeys does not know, naming the known ones.
    bool CheckKeys(const Json& inObject, const std::string& inPointer, const ObjectKeys& inKeys)
    {
        for (const auto& [key, value] : inObject.items())
        {
            bool is_known = false;
            for (const std::string_view name : inKeys.mKnown)
                is_known = is_known || key == name;
            if (is_known)
                continue;

            // A known quantity with a unit we do not accept gets a hint
            std::string what = "unknown key";
            for (const UnitHint& hint : inKeys.mHints)
            {
                const bool same_stem =
                    key == hint.mStem ||
                    (key.size() > hint.mStem.size() && key.compare(0, hint.mStem.size(), hint.mStem) == 0 &&
                     key[hint.mStem.size()] == '_');
                if (same_stem)
                {
                    what += "; " + std::string(hint.mHint);
                    break;
                }
            }
            std::string known;
            for (const std::string_view name : inKeys.mKnown)
                known += (known.empty() ? "" : ", ") + std::string(name);
            return Fail(EError::InvalidArgument, Child(inPointer, key), what + " (known: " + known + ")");
        }
        return true;
    }

    /// A finite number in inRange at inPointer.
    bool ReadNumberValue(const Json& inValue, const std::string& inPointer, const NumberRange& inRange,
                         double& outValue)
    {
        if (!inValue.is_number())
            return FailType(inPointer, "a number", inValue);
        const double value = inValue.get<double>();
        if (!std::isfinite(value))
            return Fail(EError::InvalidArgument, inPointer, "must be finite, got " + FormatNumber(value));
        if (!inRange.Contains(value))
            return Fail(EError::InvalidArgument, inPointer,
                        "must be " + inRange.Describe() + ", got " + FormatNumber(value));
        outValue = value;
        return true;
    }

    /// inObject[inKey] as a number in inRange; absent: refused when inRequired, else ioValue is kept.
    bool ReadNumber(const Json& inObject, const std::string& inPointer, std::string_view inKey,
                    const NumberRange& inRange, bool inRequired, double& ioValue)
    {
        const std::string pointer = Child(inPointer, inKey);
        const auto it = inObject.find(inKey);
        if (it == inObject.end())
            return !inRequired || Fail(EError::InvalidArgument, pointer, "required");
        return ReadNumberValue(*it, pointer, inRange, ioValue);
    }

    /// inObject[inKey] as an array of 3 numbers, each in inRange; absent: ioValue is kept.
    bool ReadVec3(const Json& inObject, const std::string& inPointer, std::string_view inKey,
                  const NumberRange& inRange, Vec3& ioValue)
    {
        const std::string pointer = Child(inPointer, inKey);
        const auto it = inObject.find(inKey);
        if (it == inObject.end())
            return true;
        if (!it->is_array() || it->size() != 3)
            return Fail(EError::InvalidArgument, pointer,
                        "must be an array of 3 numbers, got " +
                            (it->is_array() ? "an array of " + std::to_string(it->size())
                                            : std::string(it->type_name())));
        Vec3 value;
        for (int i = 0; i < 3; ++i)
            if (!ReadNumberValue((*it)[static_cast<std::size_t>(i)], pointer + "/" + std::to_string(i),
                                 inRange, value[i]))
                return false;
        ioValue = value;
        return true;
    }

    /// inObject[inKey] as a boolean; absent: ioValue is kept.
    bool ReadBool(const Json& inObject, const std::string& inPointer, std::string_view inKey, bool& ioValue)
    {
        const auto it = inObject.find(inKey);
        if (it == inObject.end())
            return true;
        if (!it->is_boolean())
            return FailType(Child(inPointer, inKey), "true or false", *it);
        ioValue = it->get<bool>();
        return true;
    }

    /// inObject[inKey] as one of inNames (its index in outIndex); absent: refused when inRequired, else
    /// outIndex is kept. inHints as for keys: a value starting with a hint's stem gets its hint.
    bool ReadEnum(const Json& inObject, const std::string& inPointer, std::string_view inKey,
                  std::initializer_list<std::string_view> inNames, std::initializer_list<UnitHint> inHints,
                  bool inRequired, std::size_t& outIndex)
    {
        const std::string pointer = Child(inPointer, inKey);
        const auto it = inObject.find(inKey);
        if (it == inObject.end())
            return !inRequired || Fail(EError::InvalidArgument, pointer, "required");
        const std::string expected =
            inNames.size() > 2 ? "one of " + JoinAlternatives(inNames) : JoinAlternatives(inNames);
        if (!it->is_string())
            return FailType(pointer, expected, *it);
        const std::string& value = it->get_ref<const std::string&>();
        std::size_t index = 0;
        for (const std::string_view name : inNames)
        {
            if (value == name)
            {
                outIndex = index;
                return true;
            }
            ++index;
        }
        std::string what = "must be " + expected + ", got " + Quote(value);
        for (const UnitHint& hint : inHints)
            if (value.compare(0, hint.mStem.size(), hint.mStem) == 0)
            {
                what += "; " + std::string(hint.mHint);
                break;
            }
        return Fail(EError::InvalidArgument, pointer, what);
    }

    bool ReadRoot(const Json& inRoot, CrashScenario& ioScenario)
    {
        const std::string pointer;
        if (!ExpectObject(inRoot, pointer) ||
            !CheckKeys(
                inRoot, pointer,
                {{"name", "engine", "duration_s", "time_step_s", "vehicle", "target", "impact",
                  "expectations", "outputs"},
                 {{"duration", "durations are duration_s"}, {"time_step", "time steps are time_step_s"}}}))
            return false;

        // Name: required, not empty
        const auto name = inRoot.find("name");
        if (name == inRoot.end())
            return Fail(EError::InvalidArgument, "/name", "required");
        if (!name->is_string())
            return FailType("/name", "a string", *name);
        if (name->get_ref<const std::string&>().empty())
            return Fail(EError::InvalidArgument, "/name", "must not be empty");
        ioScenario.mName = name->get<std::string>();

        std::size_t engine = static_cast<std::size_t>(ioScenario.mEngine);
        if (!ReadEnum(inRoot, pointer, "engine", {"bullet", "ode"}, {}, false, engine))
            return false;
        ioScenario.mEngine = static_cast<EEngine>(engine);

        // Duration, then a step that fits in it
        if (!ReadNumber(inRoot, pointer, "duration_s", NumberRange{0.0, true, cMaxDuration, false}, false,
                        ioScenario.mDuration) ||
            !ReadNumber(inRoot, pointer, "time_step_s", NumberRange{cMinTimeStep, false, 0.05, false}, false,
                        ioScenario.mTimeStep))
            return false;
        // intent: the run's step count fits an int and its memory (1e9 s of 0.05 s steps aborted in a reserve)
        if (ioScenario.mDuration / ioScenario.mTimeStep > cMaxSteps)
            return Fail(EError::InvalidArgument, "/duration_s", "takes more than 1e7 steps of time_step_s");
        if (ioScenario.mTimeStep > ioScenario.mDuration)
            return Fail(EError::InvalidArgument, "/time_step_s",
                        "must be <= duration_s (" + FormatNumber(ioScenario.mDuration) + "), got " +
                            FormatNumber(ioScenario.mTimeStep));

        // Required sections, then optional ones
        const auto vehicle = inRoot.find("vehicle");
        if (vehicle == inRoot.end())
            return Fail(EError::InvalidArgument, "/vehicle", "required");
        if (!ReadVehicle(*vehicle, "/vehicle", ioScenario.mVehicle))
            return false;
        if (const auto target = inRoot.find("target");
            target != inRoot.end() && !ReadTarget(*target, "/target", ioScenario.mTarget))
            return false;
        const auto impact = inRoot.find("impact");
        if (impact == inRoot.end())
            return Fail(EError::InvalidArgument, "/impact", "required");
        if (!ReadImpact(*impact, "/impact", ioScenario.mImpact))
            return false;
        if (const auto expectations = inRoot.find("expectations");
            expectations != inRoot.end() &&
            !ReadExpectations(*expectations, "/expectations", ioScenario.mExpectations))
            return false;
        // intent: a quantity the run cannot measure for this target is refused now, not failed as NaN later
        for (std::size_t i = 0; i < ioScenario.mExpectations.size(); ++i)
            if (ioScenario.mExpectations[i].mQuantity == EQuantity::WallGap &&
                ioScenario.mTarget.mType != ETarget::RigidWall &&
                ioScenario.mTarget.mType != ETarget::OffsetWall)
                return Fail(EError::InvalidArgument, "/expectations/" + std::to_string(i) + "/quantity",
                            "wall_gap_m needs a rigid_wall or offset_wall target (a flat wall)");
        if (const auto outputs = inRoot.find("outputs"); outputs != inRoot.end())
        {
            if (!ExpectObject(*outputs, "/outputs") || !CheckKeys(*outputs, "/outputs", {{"pictures"}, {}}) ||
                !ReadBool(*outputs, "/outputs", "pictures", ioScenario.mPictures))
                return false;
        }
        return true;
    }

    bool ReadVehicle(const Json& inVehicle, const std::string& inPointer, VehicleSpec& ioVehicle)
    {
        if (!ExpectObject(inVehicle, inPointer) ||
            !CheckKeys(inVehicle, inPointer,
                       {{"mesh", "mesh_name", "mesh_length_m", "mesh_unit_m", "mesh_forward_axis", "mesh_up_axis",
                         "mesh_max_edge_m", "mesh_flip_deviation_m", "mesh_rigid_parts", "box_size_m", "mass_kg", "inertia_kg_m2",
                         "inertia_from", "control_count", "control_spacing_m", "zones", "material"},
                        {{"mesh_length", "mesh lengths are mesh_length_m"},
                         {"box_size", "box sizes are box_size_m"},
                         {"mass", "masses are mass_kg"},
                         {"inertia", "moments of inertia are inertia_kg_m2"}}}))
            return false;

        // Mesh: resolved against the scenario's folder, and it must be there
        if (const auto mesh = inVehicle.find("mesh"); mesh != inVehicle.end())
        {
            const std::string pointer = Child(inPointer, "mesh");
            if (!mesh->is_string())
                return FailType(pointer, "a string (a file path)", *mesh);
            const std::filesystem::path file = mesh->get<std::string>();
            if (file.empty())
                return Fail(EError::InvalidArgument, pointer,
                            "must not be empty (leave the key out for a procedural box)");
            const std::filesystem::path resolved =
                (file.is_absolute() ? file : mBaseFolder / file).lexically_normal();
            std::error_code error;
            if (!std::filesystem::is_regular_file(resolved, error))
                return Fail(EError::IoError, pointer,
                            std::string(std::filesystem::exists(resolved, error)
                                            ? "not a regular file (a folder, a "
                                              "device or a pipe): "
                                            : "file not found: ") +
                                resolved.string());
            if (!std::ifstream(resolved, std::ios::binary))
                return Fail(EError::IoError, pointer, "cannot read: " + resolved.string());
            ioVehicle.mMesh = resolved;
        }

        // Mesh name: only the file's meshes whose name contains it
        if (const auto name = inVehicle.find("mesh_name"); name != inVehicle.end())
        {
            if (!name->is_string())
                return FailType(Child(inPointer, "mesh_name"), "a string", *name);
            ioVehicle.mMeshName = name->get<std::string>();
        }
        // Rigid parts: an array of name fragments ([] for none)
        if (const auto parts = inVehicle.find("mesh_rigid_parts"); parts != inVehicle.end())
        {
            const std::string pointer = Child(inPointer, "mesh_rigid_parts");
            if (!parts->is_array())
                return FailType(pointer, "an array of strings (name fragments)", *parts);
            ioVehicle.mMeshRigidParts.clear();
            ioVehicle.mMeshRigidPartsGiven = true;
            for (std::size_t index = 0; index < parts->size(); ++index)
            {
                const Json& part = (*parts)[index];
                if (!part.is_string() || part.get<std::string>().empty())
                    return FailType(pointer + "/" + std::to_string(index), "a non-empty string", part);
                ioVehicle.mMeshRigidParts.push_back(part.get<std::string>());
            }
        }

        if (inVehicle.contains("mesh_unit_m") && inVehicle.contains("mesh_length_m"))
            return Fail(EError::InvalidArgument, Child(inPointer, "mesh_unit_m"),
                        "give either mesh_unit_m (the file's unit) or mesh_length_m (a length to scale to), not both");
        for (const auto& [key, axis] : {std::pair<std::string_view, int*>{"mesh_forward_axis", &ioVehicle.mMeshForwardAxis},
                                        std::pair<std::string_view, int*>{"mesh_up_axis", &ioVehicle.mMeshUpAxis}})
        {
            if (!inVehicle.contains(key))
                continue;
            std::size_t index = 0;
            if (!ReadEnum(inVehicle, inPointer, key, {"+x", "-x", "+y", "-y", "+z", "-z"}, {}, true, index))
                return false;
            *axis = static_cast<int>(index);
        }
        if ((ioVehicle.mMeshForwardAxis >= 0) != (ioVehicle.mMeshUpAxis >= 0))
            return Fail(EError::InvalidArgument, Child(inPointer, ioVehicle.mMeshUpAxis >= 0 ? "mesh_up_axis" : "mesh_forward_axis"),
                        "needs mesh_forward_axis and mesh_up_axis together");
        if (ioVehicle.mMeshForwardAxis >= 0 && ioVehicle.mMeshForwardAxis / 2 == ioVehicle.mMeshUpAxis / 2)
            return Fail(EError::InvalidArgument, Child(inPointer, "mesh_up_axis"),
                        "must be another axis than mesh_forward_axis");
        if (!ReadNumber(inVehicle, inPointer, "mesh_unit_m", NumberRange::Positive(), false, ioVehicle.mMeshUnit) ||
            !ReadNumber(inVehicle, inPointer, "mesh_length_m", MeshLength(), false,
                        ioVehicle.mMeshLength) ||
            !ReadNumber(inVehicle, inPointer, "mesh_max_edge_m", NumberRange::NonNegative(), false,
                        ioVehicle.mMeshMaxEdge) ||
            !ReadNumber(inVehicle, inPointer, "mesh_flip_deviation_m", NumberRange::NonNegative(), false,
                        ioVehicle.mMeshFlipDeviation) ||
            !ReadVec3(inVehicle, inPointer, "box_size_m", BodySize(), ioVehicle.mBoxSize) ||
            !ReadNumber(inVehicle, inPointer, "mass_kg", BodyMass(), true, ioVehicle.mMass))
            return false;

        // Inertia: principal moments, each > 0, and each at most the sum of the other two (a real body)
        if (inVehicle.contains("inertia_kg_m2"))
        {
            Vec3 inertia = Vec3::Zero();
            if (!ReadVec3(inVehicle, inPointer, "inertia_kg_m2", NumberRange::Positive(), inertia))
                return false;
            for (int i = 0; i < 3; ++i)
                if (inertia[i] > inertia[(i + 1) % 3] + inertia[(i + 2) % 3])
                    return Fail(EError::InvalidArgument,
                                Child(inPointer, "inertia_kg_m2") + "/" + std::to_string(i),
                                "must be <= the sum of the other two moments (" +
                                    FormatNumber(inertia[(i + 1) % 3] + inertia[(i + 2) % 3]) + "), got " +
                                    FormatNumber(inertia[i]));
            ioVehicle.mInertia = inertia;
        }

        // Inertia source when no moments are given: the collision box or the mesh's surface.
        if (const auto from = inVehicle.find("inertia_from"); from != inVehicle.end())
        {
            std::size_t choice = ioVehicle.mInertiaFromMesh ? 1 : 0;
            if (!ReadEnum(inVehicle, inPointer, "inertia_from", {"box", "mesh_shell"}, {}, false, choice))
                return false;
            if (choice == 1 && ioVehicle.mMesh.empty())
                return Fail(EError::InvalidArgument, Child(inPointer, "inertia_from"), "\"mesh_shell\" needs a mesh");
            if (inVehicle.contains("inertia_kg_m2"))
                return Fail(EError::InvalidArgument, Child(inPointer, "inertia_from"),
                            "give inertia_kg_m2 or inertia_from, not both");
            ioVehicle.mInertiaFromMesh = choice == 1;
        }
        // intent: with a control count every zone has its controls, and the spacing would be ignored unsaid
        if (inVehicle.contains("control_count") && inVehicle.contains("control_spacing_m"))
            return Fail(EError::InvalidArgument, Child(inPointer, "control_spacing_m"),
                        "give control_count (controls per axis) or control_spacing_m (a spacing for them), not both");
        if (!ReadControlCount(inVehicle, inPointer, ioVehicle.mControlCount) ||
            !ReadNumber(inVehicle, inPointer, "control_spacing_m", NumberRange::Positive(), false,
                        ioVehicle.mControlSpacing))
            return false;
        ioVehicle.mControlSpacingGiven = inVehicle.contains("control_spacing_m");
        // Zones: [{"min_m": [x, y, z], "max_m": [x, y, z], "control_count": [...], "max_total_deformation_m": d}]
        if (const auto zones = inVehicle.find("zones"); zones != inVehicle.end())
        {
            // intent: a spacing that no zone falls back to would be ignored unsaid
            bool spacing_used = false;
            const std::string pointer = Child(inPointer, "zones");
            if (!zones->is_array() || zones->empty())
                return Fail(EError::InvalidArgument, pointer, "must be a non-empty array of zone objects");
            for (std::size_t index = 0; index < zones->size(); ++index)
            {
                const Json& zone = (*zones)[index];
                const std::string at = pointer + "/" + std::to_string(index);
                if (!ExpectObject(zone, at) ||
                    !CheckKeys(zone, at, {{"min_m", "max_m", "control_count", "max_total_deformation_m"}, {}}))
                    return false;
                Vec3 low = Vec3::Zero(), high = Vec3::Zero();
                ffd::FfdZoneSettings settings;
                settings.mMaxTotalDeformation = -1.0; // the vehicle's, once its material is read
                settings.mLattice.mControlCount = ioVehicle.mControlCount;
                if (!zone.contains("min_m"))
                    return Fail(EError::InvalidArgument, Child(at, "min_m"), "required");
                if (!zone.contains("max_m"))
                    return Fail(EError::InvalidArgument, Child(at, "max_m"), "required");
                // A zone is a part of a vehicle: within 1 km of its frame's origin, at least 1 mm thick.
                const NumberRange within{-1000.0, false, 1000.0, false};
                if (!ReadVec3(zone, at, "min_m", within, low) || !ReadVec3(zone, at, "max_m", within, high) ||
                    !ReadControlCount(zone, at, settings.mLattice.mControlCount) ||
                    !ReadNumber(zone, at, "max_total_deformation_m", NumberRange::NonNegative(), false,
                                settings.mMaxTotalDeformation))
                    return false;
                if (!((high - low).minCoeff() >= 1.0e-3))
                    return Fail(EError::InvalidArgument, Child(at, "max_m"),
                                "must exceed min_m by at least 0.001 m on every axis");
                settings.mLattice.mOrigin = low;
                settings.mLattice.mSize = high - low;
                if (settings.mLattice.mControlCount == std::array<int, 3>{0, 0, 0})
                {
                    settings.mLattice.mControlCount = plugin::ControlCountForSpacing(settings.mLattice.mSize,
                                                                                     ioVehicle.mControlSpacing);
                    spacing_used = true;
                }
                ioVehicle.mZones.push_back(settings);
            }
            if (inVehicle.contains("control_spacing_m") && !spacing_used)
                return Fail(EError::InvalidArgument, Child(inPointer, "control_spacing_m"),
                            "every zone gives its own control_count, so no zone uses the spacing: drop one or the other");
        }
        if (const auto material = inVehicle.find("material"); material != inVehicle.end())
            if (!ReadMaterial(*material, Child(inPointer, "material"), ioVehicle, true))
                return false;
        for (ffd::FfdZoneSettings& zone : ioVehicle.mZones)
            if (zone.mMaxTotalDeformation < 0.0)
                zone.mMaxTotalDeformation = ioVehicle.mMaxTotalDeformation;
        // intent: a well-formed mesh key without a mesh would be ignored without a word (target keys for
        // another target type are refused likewise); checked last, so a malformed one is named for its form
        if (!inVehicle.contains("mesh"))
            for (const auto& [key, value] : inVehicle.items())
                if (key.starts_with("mesh_"))
                    return Fail(EError::InvalidArgument, Child(inPointer, key), "needs a mesh (the procedural box has none)");
        return true;
    }

    // A material preset file (crumple-crash --calibrate writes them): {"preset", "source", "campbell_b0_m_s",
    // "campbell_b1_per_s", "mass_kg", "material": {...}}; its material is read like a scenario's.
    bool ReadPresetFile(const Json& inValue, const std::string& inPointer, VehicleSpec& ioVehicle)
    {
        if (!inValue.is_string())
            return FailType(inPointer, "a string (a file path)", inValue);
        const std::filesystem::path file = inValue.get<std::string>();
        const std::filesystem::path resolved = (file.is_absolute() ? file : mBaseFolder / file).lexically_normal();
        // A regular file only: a FIFO or a terminal would block the parser forever.
        std::error_code error;
        if (!std::filesystem::is_regular_file(resolved, error))
            return Fail(EError::IoError, inPointer, "file not found (or not a regular file): " + resolved.string());
        std::ifstream stream(resolved, std::ios::binary);
        if (!stream)
            return Fail(EError::IoError, inPointer, "cannot read: " + resolved.string());
        Json preset;
        // intent: a preset is held to the scenario's rules: a key given twice is refused (the last one won)
        DuplicateKeyFinder duplicates;
        try
        {
            preset = Json::parse(
                stream, [&duplicates](int, Json::parse_event_t inEvent, Json& inParsed) { return duplicates.OnEvent(inEvent, inParsed); },
                true, false);
        }
        catch (const Json::exception& inError)
        {
            return Fail(EError::CorruptData, inPointer, resolved.string() + ": " + inError.what());
        }
        const std::string pointer = inPointer + "(" + resolved.filename().string() + ")";
        if (duplicates.GetDuplicate())
            return Fail(EError::InvalidArgument, pointer + *duplicates.GetDuplicate(), "duplicate key");
        if (!ExpectObject(preset, pointer) ||
            !CheckKeys(preset, pointer,
                       {{"preset", "source", "campbell_b0_m_s", "campbell_b1_per_s", "mass_kg", "material"}, {}}))
            return false;
        // The informative keys are not read, but must have their types
        for (const char* key : {"preset", "source"})
            if (const auto it = preset.find(key); it != preset.end() && !it->is_string())
                return FailType(Child(pointer, key), "a string", *it);
        for (const char* key : {"campbell_b0_m_s", "campbell_b1_per_s", "mass_kg"})
            if (const auto it = preset.find(key); it != preset.end() && !it->is_number())
                return FailType(Child(pointer, key), "a number", *it);
        const auto material = preset.find("material");
        if (material == preset.end())
            return Fail(EError::InvalidArgument, pointer + "/material", "required");
        return ReadMaterial(*material, pointer + "/material", ioVehicle, false);
    }

    bool ReadControlCount(const Json& inVehicle, const std::string& inPointer, std::array<int, 3>& ioCount)
    {
        const std::string pointer = Child(inPointer, "control_count");
        const auto it = inVehicle.find("control_count");
        if (it == inVehicle.end())
            return true;
        if (!it->is_array() || it->size() != 3)
            return Fail(EError::InvalidArgument, pointer,
                        "must be an array of 3 integers, got " +
                            (it->is_array() ? "an array of " + std::to_string(it->size())
                                            : std::string(it->type_name())));
        std::array<int, 3> count{};
        constexpr int max_count = ffd::FfdLatticeSettings::cMaxControlsPerAxis;
        for (std::size_t i = 0; i < 3; ++i)
        {
            const std::string element = pointer + "/" + std::to_string(i);
            double value = 0.0;
            if (!ReadNumberValue((*it)[i], element, NumberRange::Any(), value))
                return false;
            if (value != std::floor(value))
                return Fail(EError::InvalidArgument, element,
                            "must be an integer, got " + FormatNumber(value));
            if (!NumberRange{4.0, false, static_cast<double>(max_count), false}.Contains(value))
                return Fail(EError::InvalidArgument, element,
                            "must be in [4, " + std::to_string(max_count) + "], got " + FormatNumber(value));
            count[i] = static_cast<int>(value);
        }
        ioCount = count;
        return true;
    }

    bool ReadMaterial(const Json& inMaterial, const std::string& inPointer, VehicleSpec& ioVehicle,
                      bool inAllowPreset)
    {
        plugin::DamageMaterial& material = ioVehicle.mMaterial;
        if (!ExpectObject(inMaterial, inPointer))
            return false;
        // Scenario files may name a preset file; preset files may not (no chains).
        const auto hints = {UnitHint{"deformation_factor", "deformation factors are deformation_factor_m_per_N_s"},
                            UnitHint{"min_deformation", "depths are min_deformation_m"},
                            UnitHint{"max_deformation", "depths are max_deformation_m"},
                            UnitHint{"impulse_threshold", "impulses are impulse_threshold_N_s"},
                            UnitHint{"max_total_deformation", "depths are max_total_deformation_m"},
                            UnitHint{"crush_A", "Campbell's A is crush_A_N_per_m"},
                            UnitHint{"crush_B", "Campbell's B is crush_B_N_per_m2"},
                            UnitHint{"crush_G", "Campbell's G is crush_G_J_per_m"},
                            UnitHint{"min_crush_width", "widths are min_crush_width_m"}};
        const bool keys_ok =
            inAllowPreset
                ? CheckKeys(
                      inMaterial, inPointer,
                      {{"deformation_factor_m_per_N_s", "min_deformation_m", "max_deformation_m",
                        "impulse_threshold_N_s", "max_total_deformation_m", "crush_model", "crush_A_N_per_m",
                        "crush_B_N_per_m2", "crush_G_J_per_m", "side_crush_A_N_per_m",
                        "side_crush_B_N_per_m2", "side_crush_G_J_per_m", "rear_crush_A_N_per_m",
                        "rear_crush_B_N_per_m2", "rear_crush_G_J_per_m", "min_crush_width_m",
                        "crushed_length_fraction", "crush_zone_fraction", "preset_file"},
                       hints})
                : CheckKeys(inMaterial, inPointer,
                            {{"deformation_factor_m_per_N_s", "min_deformation_m", "max_deformation_m",
                              "impulse_threshold_N_s", "max_total_deformation_m", "crush_model",
                              "crush_A_N_per_m", "crush_B_N_per_m2", "crush_G_J_per_m",
                              "side_crush_A_N_per_m", "side_crush_B_N_per_m2", "side_crush_G_J_per_m",
                              "rear_crush_A_N_per_m", "rear_crush_B_N_per_m2", "rear_crush_G_J_per_m",
                              "min_crush_width_m", "crushed_length_fraction", "crush_zone_fraction"},
                             hints});
        if (!keys_ok)
            return false;
        // A preset first; the keys given beside it override its values.
        if (const auto preset = inMaterial.find("preset_file"); inAllowPreset && preset != inMaterial.end())
            if (!ReadPresetFile(*preset, Child(inPointer, "preset_file"), ioVehicle))
                return false;
        if (!ReadNumber(inMaterial, inPointer, "deformation_factor_m_per_N_s", NumberRange::NonNegative(), false,
                        material.mDeformationFactor) ||
            !ReadNumber(inMaterial, inPointer, "min_deformation_m", NumberRange::NonNegative(), false,
                        material.mMinDeformation) ||
            !ReadNumber(inMaterial, inPointer, "max_deformation_m", NumberRange::NonNegative(), false,
                        material.mMaxInstantDeformation) ||
            !ReadNumber(inMaterial, inPointer, "impulse_threshold_N_s", NumberRange::NonNegative(), false,
                        material.mImpulseThreshold) ||
            !ReadNumber(inMaterial, inPointer, "max_total_deformation_m", NumberRange::NonNegative(), false,
                        ioVehicle.mMaxTotalDeformation) ||
            !ReadNumber(inMaterial, inPointer, "crush_A_N_per_m", NumberRange{0.0, false, 1.0e12, false}, false, material.mCrushA) ||
            !ReadNumber(inMaterial, inPointer, "crush_B_N_per_m2", NumberRange{0.0, true, 1.0e12, false}, false, material.mCrushB) ||
            !ReadNumber(inMaterial, inPointer, "crush_G_J_per_m", NumberRange{0.0, false, 1.0e12, false}, false, material.mCrushG) ||
            !ReadNumber(inMaterial, inPointer, "min_crush_width_m", NumberRange::Positive(), false,
                        material.mMinCrushWidth) ||
            !ReadNumber(inMaterial, inPointer, "crushed_length_fraction", NumberRange{0.0, false, 1.0, true}, false,
                        material.mCrushedLengthFraction) ||
            !ReadNumber(inMaterial, inPointer, "crush_zone_fraction", NumberRange{0.0, true, 0.5, false}, false,
                        material.mCrushZoneFraction))
            return false;
        // A zone's own stiffness (the sides', the rear's): all three keys or none (a preset's set stays
        // unless all three replace it).
        const auto read_zone =
            [&](const std::string& inZone, bool& outHas, double& outA, double& outB, double& outG)
        {
            const std::string a = inZone + "_crush_A_N_per_m", b = inZone + "_crush_B_N_per_m2",
                              g = inZone + "_crush_G_J_per_m";
            const int keys = static_cast<int>(inMaterial.contains(a)) +
                             static_cast<int>(inMaterial.contains(b)) +
                             static_cast<int>(inMaterial.contains(g));
            if (keys != 0 && keys != 3)
                return Fail(EError::InvalidArgument, Child(inPointer, a),
                            a + ", " + b + " and " + g + " go together: give all three or none");
            if (keys == 0)
                return true;
            if (!ReadNumber(inMaterial, inPointer, a, NumberRange{0.0, false, 1.0e12, false}, true, outA) ||
                !ReadNumber(inMaterial, inPointer, b, NumberRange{0.0, true, 1.0e12, false}, true, outB) ||
                !ReadNumber(inMaterial, inPointer, g, NumberRange{0.0, false, 1.0e12, false}, true, outG))
                return false;
            outHas = true;
            return true;
        };
        if (!read_zone("side", material.mHasSideStiffness, material.mSideCrushA, material.mSideCrushB,
                       material.mSideCrushG) ||
            !read_zone("rear", material.mHasRearStiffness, material.mRearCrushA, material.mRearCrushB,
                       material.mRearCrushG))
            return false;
        std::size_t model = static_cast<std::size_t>(material.mModel);
        if (!ReadEnum(inMaterial, inPointer, "crush_model", {"impulse_factor", "campbell"}, {}, false, model))
            return false;
        material.mModel = static_cast<plugin::ECrushModel>(model);
        if (material.mMaxInstantDeformation < material.mMinDeformation)
            return Fail(EError::InvalidArgument, Child(inPointer, "max_deformation_m"),
                        "must be >= min_deformation_m (" + FormatNumber(material.mMinDeformation) + "), got " +
                            FormatNumber(material.mMaxInstantDeformation));
        return true;
    }

    bool ReadTarget(const Json& inTarget, const std::string& inPointer, TargetSpec& ioTarget)
    {
        std::size_t type = static_cast<std::size_t>(ioTarget.mType);
        double speed_km_h = ioTarget.mVehicleSpeed * 3.6;
        if (!ExpectObject(inTarget, inPointer) ||
            !CheckKeys(inTarget, inPointer,
                       {{"type", "angle_deg", "radius_m", "overlap_percent", "mass_kg", "box_size_m", "heading_deg",
                         "speed_km_h", "offset_m", "size_m", "material", "cell_m"},
                        {{"angle", "angles are angle_deg"},
                         {"radius", "radii are radius_m"},
                         {"overlap", "overlaps are overlap_percent"},
                         {"mass", "masses are mass_kg"},
                         {"box_size", "box sizes are box_size_m"},
                         {"heading", "headings are heading_deg"},
                         {"speed", "target speeds are speed_km_h"},
                         {"offset", "offsets are offset_m"}}}) ||
            !ReadEnum(inTarget, inPointer, "type", {"rigid_wall", "pole", "offset_wall", "vehicle", "fem_barrier"}, {},
                      false, type) ||
            !ReadVec3(inTarget, inPointer, "size_m", NumberRange::Positive(), ioTarget.mBarrierSize) ||
            !ReadNumber(inTarget, inPointer, "cell_m", NumberRange::Positive(), false, ioTarget.mBarrierCell) ||
            !ReadNumber(inTarget, inPointer, "angle_deg", NumberRange{-90.0, true, 90.0, true}, false,
                        ioTarget.mAngleDegrees) ||
            !ReadNumber(inTarget, inPointer, "radius_m", NumberRange{0.0, true, 100.0, false}, false, ioTarget.mPoleRadius) ||
            !ReadNumber(inTarget, inPointer, "overlap_percent", NumberRange{0.0, true, 100.0, false}, false,
                        ioTarget.mOverlapPercent) ||
            !ReadNumber(inTarget, inPointer, "mass_kg", BodyMass(), false, ioTarget.mVehicleMass) ||
            !ReadVec3(inTarget, inPointer, "box_size_m", BodySize(), ioTarget.mVehicleSize) ||
            !ReadNumber(inTarget, inPointer, "heading_deg", Heading(), false, ioTarget.mVehicleHeadingDegrees) ||
            !ReadNumber(inTarget, inPointer, "speed_km_h", NumberRange{0.0, false, 3600.0, false}, false, speed_km_h) ||
            !ReadNumber(inTarget, inPointer, "offset_m", NumberRange{-1000.0, false, 1000.0, false}, false,
                        ioTarget.mVehicleOffset))
            return false;
        ioTarget.mVehicleSpeed = speed_km_h / 3.6;
        ioTarget.mType = static_cast<ETarget>(type);
        if (ioTarget.mType == ETarget::FemBarrier)
        {
            std::size_t material = 2; // brick
            if (!ReadEnum(inTarget, inPointer, "material", {"glass", "wood", "brick", "rubber", "steel"}, {}, false,
                          material))
                return false;
            ioTarget.mBarrierMaterial = cBarrierMaterialNames[material];
            for (int axis = 0; axis < 3; ++axis)
                if (ioTarget.mBarrierSize[axis] / ioTarget.mBarrierCell > 200.0)
                    return Fail(EError::InvalidArgument, Child(inPointer, "cell_m"),
                                "makes more than 200 cells along an axis of size_m");
        }
        // Each key belongs to its target type.
        const struct
        {
            const char* mKey;
            ETarget mType;
        } owners[] = {{"angle_deg", ETarget::RigidWall},   {"radius_m", ETarget::Pole},
                      {"overlap_percent", ETarget::OffsetWall}, {"mass_kg", ETarget::Vehicle},
                      {"box_size_m", ETarget::Vehicle},     {"heading_deg", ETarget::Vehicle},
                      {"speed_km_h", ETarget::Vehicle},     {"offset_m", ETarget::Vehicle},
                      {"size_m", ETarget::FemBarrier},      {"material", ETarget::FemBarrier},
                      {"cell_m", ETarget::FemBarrier}};
        for (const auto& owner : owners)
            if (inTarget.contains(owner.mKey) && ioTarget.mType != owner.mType)
                return Fail(EError::InvalidArgument, Child(inPointer, owner.mKey),
                            "does not apply to this target type");
        return true;
    }

    bool ReadImpact(const Json& inImpact, const std::string& inPointer, ImpactSpec& ioImpact)
    {
        if (!ExpectObject(inImpact, inPointer) ||
            !CheckKeys(inImpact, inPointer,
                       {{"speed_km_h", "speed_m_s", "heading_deg", "offset_m"},
                        {{"speed", "speeds are speed_km_h or speed_m_s"},
                         {"heading", "headings are heading_deg"},
                         {"offset", "offsets are offset_m"}}}))
            return false;

        // Speed: exactly one of km/h and m/s
        const bool has_km_h = inImpact.contains("speed_km_h");
        const bool has_m_s = inImpact.contains("speed_m_s");
        if (has_km_h && has_m_s)
            return Fail(EError::InvalidArgument, Child(inPointer, "speed_m_s"),
                        "give speed_km_h or speed_m_s, not both");
        if (!has_km_h && !has_m_s)
            return Fail(EError::InvalidArgument, Child(inPointer, "speed_km_h"), "required (or speed_m_s)");
        // Up to 1,000 m/s (3,600 km/h): far beyond any vehicle, short of where the scene's energies overflow.
        double speed = 0.0;
        if (!ReadNumber(inImpact, inPointer, has_km_h ? "speed_km_h" : "speed_m_s",
                        NumberRange{0.0, true, has_km_h ? 3600.0 : 1000.0, false}, true, speed))
            return false;
        ioImpact.mSpeed = has_km_h ? KilometresPerHourToMetresPerSecond(speed) : speed;

        return ReadNumber(inImpact, inPointer, "heading_deg", Heading(), false,
                          ioImpact.mHeadingDegrees) &&
               ReadNumber(inImpact, inPointer, "offset_m", NumberRange{-1000.0, false, 1000.0, false}, false,
                          ioImpact.mOffset);
    }

    bool ReadExpectations(const Json& inList, const std::string& inPointer, std::vector<Expectation>& outList)
    {
        if (!inList.is_array())
            return FailType(inPointer, "an array", inList);
        outList.clear();
        for (std::size_t i = 0; i < inList.size(); ++i)
        {
            Expectation expectation;
            if (!ReadExpectation(inList[i], inPointer + "/" + std::to_string(i), expectation))
                return false;
            outList.push_back(std::move(expectation));
        }
        return true;
    }

    bool ReadExpectation(const Json& inItem, const std::string& inPointer, Expectation& outExpectation)
    {
        // The file's quantity names; delta_v_km_h is DeltaV with its bounds converted to m/s
        constexpr std::size_t delta_v_km_h = 2;
        static constexpr std::array<EQuantity, 13> quantities{
            EQuantity::ResidualCrush,    EQuantity::DeltaV,
            EQuantity::DeltaV,           EQuantity::TotalImpulse,
            EQuantity::EnergyAbsorbed,   EQuantity::Collisions,
            EQuantity::FoldedVertices,   EQuantity::OutwardDisplacement,
            EQuantity::FoldedTriangles,  EQuantity::CrushAverage,
            EQuantity::PeakDeceleration, EQuantity::TimeToZeroVelocity,
            EQuantity::WallGap};
        std::size_t quantity = 0;
        if (!ExpectObject(inItem, inPointer) ||
            !CheckKeys(inItem, inPointer, {{"quantity", "zone", "min", "max"}, {}}) ||
            !ReadEnum(inItem, inPointer, "quantity",
                      {"residual_crush_m", "delta_v_m_s", "delta_v_km_h", "total_impulse_N_s",
                       "energy_absorbed_J", "collisions", "folded_vertices", "outward_displacement_m",
                       "folded_triangles", "crush_average_m", "peak_deceleration_m_s2",
                       "time_to_zero_velocity_s", "wall_gap_m"},
                      {{"residual_crush", "residual crush is residual_crush_m"},
                       {"delta_v", "delta-v is delta_v_m_s or delta_v_km_h"},
                       {"total_impulse", "impulses are total_impulse_N_s"},
                       {"energy", "energies are energy_absorbed_J"}},
                      true, quantity))
            return false;
        const std::string quantity_name = inItem.at("quantity").get<std::string>();
        outExpectation.mQuantity = quantities[quantity];

        // Zone: residual crush only
        std::size_t zone = static_cast<std::size_t>(EZone::Any);
        if (inItem.contains("zone") && outExpectation.mQuantity != EQuantity::ResidualCrush)
            return Fail(EError::InvalidArgument, Child(inPointer, "zone"),
                        "only residual_crush_m has a zone");
        if (!ReadEnum(inItem, inPointer, "zone", {"any", "front", "rear", "left", "right", "roof"}, {}, false,
                      zone))
            return false;
        outExpectation.mZone = static_cast<EZone>(zone);

        // Bounds: at least one, in order
        const bool has_min = inItem.contains("min");
        const bool has_max = inItem.contains("max");
        if (!has_min && !has_max)
            return Fail(EError::InvalidArgument, inPointer, "needs min, max or both");
        double low = -std::numeric_limits<double>::infinity();
        double high = std::numeric_limits<double>::infinity();
        // Bounds within 1e300 of zero, so that no unit conversion or display overflows to Inf.
        const NumberRange bound{-1.0e300, false, 1.0e300, false};
        if (!ReadNumber(inItem, inPointer, "min", bound, false, low) ||
            !ReadNumber(inItem, inPointer, "max", bound, false, high))
            return false;
        if (low > high)
            return Fail(EError::InvalidArgument, Child(inPointer, "max"),
                        "must be >= min (" + FormatNumber(low) + "), got " + FormatNumber(high));

        // The text as written (file units), the bounds in SI
        std::string text = quantity_name;
        if (outExpectation.mQuantity == EQuantity::ResidualCrush)
            text += "(" + std::string(ToString(outExpectation.mZone)) + ")";
        if (has_min && has_max)
            text += " in [" + FormatNumber(low) + ", " + FormatNumber(high) + "]";
        else if (has_min)
            text += " >= " + FormatNumber(low);
        else
            text += " <= " + FormatNumber(high);
        outExpectation.mText = std::move(text);
        const bool km_h = quantity == delta_v_km_h;
        outExpectation.mMin = km_h && has_min ? KilometresPerHourToMetresPerSecond(low) : low;
        outExpectation.mMax = km_h && has_max ? KilometresPerHourToMetresPerSecond(high) : high;
        outExpectation.mDisplayScale = km_h ? 3.6 : 1.0;
        return true;
    }

    std::filesystem::path mBaseFolder;
    std::optional<Error> mError;
};

/// "line L, column C: <what>" from a nlohmann parse error ("[json.exception.parse_error.101] parse error at
/// line 1, column 1: ...").
std::string DescribeParseError(const Json::parse_error& inError)
{
    const std::string what = inError.what();
    const std::size_t at = what.find("line ");
    if (at != std::string::npos)
        return what.substr(at);
    return "byte " + std::to_string(inError.byte) + ": " + what;
}

} // namespace

Result<CrashScenario> ParseCrashScenario(std::string_view inJson, const std::filesystem::path& inBaseFolder)
{
    DuplicateKeyFinder duplicates;
    try
    {
        // Parse strictly (no comments), noting the first duplicate key
        const Json root = Json::parse(
            inJson.begin(), inJson.end(),
            [&duplicates](int, Json::parse_event_t inEvent, Json& inParsed)
            { return duplicates.OnEvent(inEvent, inParsed); },
            true, false);
        if (duplicates.GetDuplicate())
            return MakeError(EError::InvalidArgument, *duplicates.GetDuplicate() + ": duplicate key");
        return ScenarioReader(inBaseFolder).Read(root);
    }
    catch (const Json::parse_error& error)
    {
        return MakeError(EError::CorruptData, DescribeParseError(error));
    }
    catch (const Json::out_of_range& error)
    {
        // A number beyond the double range (1e999): the parser's message, at the place it stopped
        const std::string what = error.what();
        const std::size_t detail = what.find("] ");
        return MakeError(EError::InvalidArgument,
                         ShowPointer(duplicates.Pointer()) + ": must be finite; " +
                             (detail == std::string::npos ? what : what.substr(detail + 2)));
    }
    catch (const std::exception& error)
    {
        // Not expected (types are checked before every get); never let one escape
        return MakeError(EError::CorruptData, std::string("scenario not readable: ") + error.what());
    }
}

Result<CrashScenario> LoadCrashScenario(const std::filesystem::path& inPath)
{
    try
    {
        // ReadFileBytes refuses a folder, a FIFO or a missing path itself
        Result<std::vector<std::byte>> bytes = ReadFileBytes(inPath);
        if (bytes.HasError())
            return bytes.GetError();
        const std::string_view text(reinterpret_cast<const char*>(bytes.Get().data()), bytes.Get().size());
        Result<CrashScenario> scenario = ParseCrashScenario(text, inPath.parent_path());
        if (scenario.HasError())
            return MakeError(scenario.GetError().mCode,
                             inPath.string() + ": " + scenario.GetError().mMessage);
        return scenario;
    }
    catch (const std::exception& error)
    {
        return MakeError(EError::IoError, "cannot read " + inPath.string() + ": " + error.what());
    }
}

} // namespace crumple::crash
