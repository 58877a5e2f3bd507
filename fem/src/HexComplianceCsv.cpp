// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/HexComplianceCsv.h>

#include <cstdio>
#include <fstream>

namespace crumple::fem
{

Status WriteHexComplianceCsv(const std::filesystem::path& inPath, const HexCompliance& inCompliance)
{
    // Refuse what cannot be written consistently.
    const Eigen::Index rows = 3 * static_cast<Eigen::Index>(inCompliance.mOutputNodes.size());
    const Eigen::Index cols = 3 * static_cast<Eigen::Index>(inCompliance.mLoadNodes.size());
    if (cols == 0 || rows == 0 || inCompliance.mMatrix.rows() != rows || inCompliance.mMatrix.cols() != cols)
        return MakeError(EError::InvalidArgument,
                         "WriteHexComplianceCsv: the compliance is empty or its matrix does not match its node lists");
    if (inPath.empty())
        return MakeError(EError::InvalidArgument, "WriteHexComplianceCsv: empty path");

    // Write the temporary file line by line.
    static constexpr char cAxes[3] = {'x', 'y', 'z'};
    std::filesystem::path temporary = inPath;
    temporary += ".tmp";
    {
        std::ofstream out(temporary, std::ios::trunc);
        if (out)
            out << "output_node,output_axis,load_node,load_axis,compliance_m_per_n\n";
        char line[96];
        for (Eigen::Index col = 0; col < cols && out; ++col)
            for (Eigen::Index row = 0; row < rows; ++row)
            {
                std::snprintf(line, sizeof(line), "%d,%c,%d,%c,%.17g\n", inCompliance.mOutputNodes[row / 3],
                              cAxes[row % 3], inCompliance.mLoadNodes[col / 3], cAxes[col % 3],
                              inCompliance.mMatrix(row, col));
                out << line;
            }
        if (out)
            out.close();
        if (!out)
        {
            std::error_code ignored;
            std::filesystem::remove(temporary, ignored);
            return MakeError(EError::IoError, "WriteHexComplianceCsv: cannot write " + temporary.string());
        }
    }

    // Replace the destination in one step.
    std::error_code error;
    std::filesystem::rename(temporary, inPath, error);
    if (error)
    {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        return MakeError(EError::IoError, "WriteHexComplianceCsv: cannot rename " + temporary.string() + " to " +
                                              inPath.string() + ": " + error.message());
    }
    return Status::Ok();
}

} // namespace crumple::fem
