// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/EImplicitPreconditioner.h>

namespace crumple::fem
{

const char* ToString(EImplicitPreconditioner inPreconditioner)
{
    switch (inPreconditioner)
    {
    case EImplicitPreconditioner::RestFactorization:
        return "RestFactorization";
    case EImplicitPreconditioner::BlockJacobi:
        return "BlockJacobi";
    }
    return "unknown";
}

} // namespace crumple::fem
