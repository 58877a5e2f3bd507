// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>

#include <random>

namespace crumple::ffd::test
{

/// X X^T for X #n by inRank with standard Gaussian entries: a positive semi-definite Gram matrix of rank
/// inRank, as the direct-manipulation solve factors.
inline Eigen::MatrixXd RandomGram(int inRows, int inRank, std::mt19937_64& ioRandom)
{
    std::normal_distribution<double> entry(0.0, 1.0);
    Eigen::MatrixXd x(inRows, inRank);
    for (int i = 0; i < inRows; ++i)
        for (int j = 0; j < inRank; ++j)
            x(i, j) = entry(ioRandom);
    return x * x.transpose();
}

} // namespace crumple::ffd::test
