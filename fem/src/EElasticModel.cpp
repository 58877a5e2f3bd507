// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/EElasticModel.h>

namespace crumple::fem
{

const char* ToString(EElasticModel inModel)
{
    switch (inModel)
    {
    case EElasticModel::StVenantKirchhoff:
        return "StVenantKirchhoff";
    case EElasticModel::CorotatedLinear:
        return "CorotatedLinear";
    }
    return "unknown";
}

} // namespace crumple::fem
