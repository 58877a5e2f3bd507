// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/ProceduralEdgeSettings.h>

#include <cmath>
#include <sstream>

namespace crumple::fem
{

namespace
{

// "ProceduralEdgeSettings.mX = v unit: reason", the message of every refusal.
Error FieldError(EError inCode, const char* inField, double inValue, const char* inUnit,
                 const std::string& inReason)
{
    std::ostringstream message;
    message << "ProceduralEdgeSettings." << inField << " = " << inValue << (inUnit[0] != 0 ? " " : "")
            << inUnit << ": " << inReason;
    return MakeError(inCode, message.str());
}

// Largest accepted amplitude (m) for a random fraction inRandom and a section size inSize (m).
double MaxAmplitude(double inRandom, double inSize)
{
    return ProceduralEdgeSettings::cMaxAmplitudeFraction * (1.0 - 2.0 * inRandom) * inSize;
}

// Refusal of an amplitude above MaxAmplitude, naming what the limit was computed from.
Error AmplitudeError(const char* inField, double inValue, const char* inRandomField, double inRandom,
                     const char* inSizeName, double inSize)
{
    std::ostringstream reason;
    reason << "must be <= " << ProceduralEdgeSettings::cMaxAmplitudeFraction << " x (1 - 2 x "
           << inRandomField << " " << inRandom << ") x " << inSizeName << " " << inSize
           << " m = " << MaxAmplitude(inRandom, inSize) << " m, or section outlines could cross";
    return FieldError(EError::InvalidArgument, inField, inValue, "m", reason.str());
}

} // namespace

Status ValidateProceduralEdgeSettings(const ProceduralEdgeSettings& inSettings)
{
    // Every number must be finite before any range check can mean anything.
    const struct
    {
        const char* mName;
        double mValue;
        const char* mUnit;
    } fields[] = {{"mAverageSectionWidth", inSettings.mAverageSectionWidth, "m"},
                  {"mAverageSectionHeight", inSettings.mAverageSectionHeight, "m"},
                  {"mRandomSectionWidth", inSettings.mRandomSectionWidth, ""},
                  {"mRandomSectionHeight", inSettings.mRandomSectionHeight, ""},
                  {"mHorizontalEdgeFrequency", inSettings.mHorizontalEdgeFrequency, "1/m"},
                  {"mVerticalEdgeFrequency", inSettings.mVerticalEdgeFrequency, "1/m"},
                  {"mHorizontalEdgeAmplitude", inSettings.mHorizontalEdgeAmplitude, "m"},
                  {"mVerticalEdgeAmplitude", inSettings.mVerticalEdgeAmplitude, "m"}};
    for (const auto& field : fields)
        if (!std::isfinite(field.mValue))
            return FieldError(EError::NonFinite, field.mName, field.mValue, field.mUnit, "must be finite");

    // Sizes, fractions, frequencies and amplitudes in their ranges.
    for (int index = 0; index < 2; ++index)
        if (!(fields[index].mValue > 0.0))
            return FieldError(EError::InvalidArgument, fields[index].mName, fields[index].mValue, "m",
                              "must be > 0");
    for (int index = 2; index < 4; ++index)
        if (!(fields[index].mValue >= 0.0 &&
              fields[index].mValue < ProceduralEdgeSettings::cMaxRandomSection))
            return FieldError(EError::InvalidArgument, fields[index].mName, fields[index].mValue, "",
                              "must lie in [0, 0.45): a corner moved by half a cell or more could cross its "
                              "neighbour");
    for (int index = 4; index < 6; ++index)
        if (!(fields[index].mValue >= 0.0 && fields[index].mValue <= 1.0e6))
            return FieldError(EError::InvalidArgument, fields[index].mName, fields[index].mValue, "1/m",
                              "must lie in [0, 1e6]");
    for (int index = 6; index < 8; ++index)
        if (!(fields[index].mValue >= 0.0))
            return FieldError(EError::InvalidArgument, fields[index].mName, fields[index].mValue, "m",
                              "must be >= 0");

    // Amplitudes against the average section sizes.
    return ValidateEdgeAmplitudes(inSettings, inSettings.mAverageSectionWidth,
                                  inSettings.mAverageSectionHeight);
}

Status ValidateEdgeAmplitudes(const ProceduralEdgeSettings& inSettings, double inWidth, double inHeight)
{
    // Horizontal edges are offset along v, so they are bounded by the height, and vertical ones by the width.
    if (!(inSettings.mHorizontalEdgeAmplitude <= MaxAmplitude(inSettings.mRandomSectionHeight, inHeight)))
        return AmplitudeError("mHorizontalEdgeAmplitude", inSettings.mHorizontalEdgeAmplitude,
                              "mRandomSectionHeight", inSettings.mRandomSectionHeight, "section height",
                              inHeight);
    if (!(inSettings.mVerticalEdgeAmplitude <= MaxAmplitude(inSettings.mRandomSectionWidth, inWidth)))
        return AmplitudeError("mVerticalEdgeAmplitude", inSettings.mVerticalEdgeAmplitude,
                              "mRandomSectionWidth", inSettings.mRandomSectionWidth, "section width",
                              inWidth);
    return Status::Ok();
}

} // namespace crumple::fem
