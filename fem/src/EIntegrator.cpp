// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/EIntegrator.h>

namespace crumple::fem
{

const char* ToString(EIntegrator inIntegrator)
{
    switch (inIntegrator)
    {
    case EIntegrator::SymplecticEuler:
        return "SymplecticEuler";
    case EIntegrator::ImplicitEuler:
        return "ImplicitEuler";
    }
    return "unknown";
}

} // namespace crumple::fem
