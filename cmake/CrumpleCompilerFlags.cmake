# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# Determinism first (Box2D, Jolt): no contraction of a*b+c into FMA, no fast-math, ever.
# The same inputs give bitwise the same outputs from the same binary.
add_library(crumple_compile_options INTERFACE)
add_library(crumple::compile_options ALIAS crumple_compile_options)
if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    target_compile_options(crumple_compile_options INTERFACE
        -ffp-contract=off -fno-fast-math -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion)
elseif(MSVC)
    target_compile_options(crumple_compile_options INTERFACE /fp:precise /W4)
endif()
if(CRUMPLE_ENABLE_ASSERTS)
    target_compile_definitions(crumple_compile_options INTERFACE CRUMPLE_ENABLE_ASSERTS)
endif()
if(CRUMPLE_VALIDATE)
    target_compile_definitions(crumple_compile_options INTERFACE CRUMPLE_ENABLE_VALIDATE)
endif()
