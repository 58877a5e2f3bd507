// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/FileBytes.h>
#include <crumple/fem/ExactNumber.h>
#include <crumple/fem/HexComplianceCsv.h>

#include <span>
#include <string>

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

    // The table in memory (locale-free numbers that round-trip), then one atomic write.
    static constexpr char cAxes[3] = {'x', 'y', 'z'};
    std::string text = "output_node,output_axis,load_node,load_axis,compliance_m_per_n\n";
    for (Eigen::Index col = 0; col < cols; ++col)
        for (Eigen::Index row = 0; row < rows; ++row)
            text += std::to_string(inCompliance.mOutputNodes[row / 3]) + ',' + cAxes[row % 3] + ',' +
                    std::to_string(inCompliance.mLoadNodes[col / 3]) + ',' + cAxes[col % 3] + ',' +
                    ExactNumber(inCompliance.mMatrix(row, col)) + '\n';
    return WriteFileAtomically(inPath, std::as_bytes(std::span(text.data(), text.size())), "WriteHexComplianceCsv");
}

} // namespace crumple::fem
