// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

/// CRUMPLE_API marks a symbol exported from a shared build; static builds (the default) need nothing.
#if defined(CRUMPLE_SHARED)
#if defined(CRUMPLE_BUILDING_LIBRARY)
#define CRUMPLE_API [[gnu::visibility("default")]] // the C++11 spelling: it may follow [[nodiscard]]
#else
#define CRUMPLE_API
#endif
#else
#define CRUMPLE_API
#endif
