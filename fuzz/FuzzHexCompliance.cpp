// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Fuzz target: a hexahedral compliance file (SaveHexCompliance's output), decoded, and a load solved with
// what was accepted.
#include <crumple/fem/HexComplianceFile.h>
#include <crumple/fem/HexComplianceSolve.h>

#include <cstddef>
#include <cstdint>
#include <span>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* inData, std::size_t inSize)
{
    const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(inData), inSize);
    const crumple::Result<crumple::fem::HexCompliance> compliance = crumple::fem::DecodeHexCompliance(bytes);
    if (compliance.HasError())
        return 0;
    const Eigen::VectorXd load = Eigen::VectorXd::Ones(3 * static_cast<Eigen::Index>(compliance.Get().mLoadNodes.size()));
    (void)crumple::fem::HexComplianceSolve(compliance.Get(), load);
    return 0;
}
