# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# The crash runner and the crumple-crash program, built from library targets only: the scene builders of
# scenes/ (engine scenes, car-mesh loader, painter) and crumple::fem (paths relative to this file).
if(NOT TARGET crumple_crash_scenario)
    return()
endif()
find_package(nlohmann_json 3 QUIET) # imported targets are per directory
if(NOT TARGET crumple_scenes_pictures OR NOT TARGET crumple_fem OR NOT (TARGET crumple_scenes_bullet OR TARGET crumple_scenes_ode))
    message(STATUS "crumple: crumple-crash not built: it needs assimp, crumple::render, crumple::fem and Bullet or ODE")
    return()
endif()
add_library(crumple_crash_run STATIC ${CMAKE_CURRENT_LIST_DIR}/src/Calibration.cpp ${CMAKE_CURRENT_LIST_DIR}/src/CrashRun.cpp
    ${CMAKE_CURRENT_LIST_DIR}/src/CrashReport.cpp ${CMAKE_CURRENT_LIST_DIR}/src/CrashSweep.cpp
    ${CMAKE_CURRENT_LIST_DIR}/src/SlurmSweep.cpp ${CMAKE_CURRENT_LIST_DIR}/src/OutputFolders.cpp
    ${CMAKE_CURRENT_LIST_DIR}/src/FemBarrierCoupling.cpp ${CMAKE_CURRENT_LIST_DIR}/src/FloatingBarrierCrash.cpp
    ${CMAKE_CURRENT_LIST_DIR}/src/RecutCarMesh.cpp ${CMAKE_CURRENT_LIST_DIR}/src/SanityChecks.cpp ${CMAKE_CURRENT_LIST_DIR}/src/ShippedCars.cpp
    ${CMAKE_CURRENT_LIST_DIR}/src/StepOverlap.cpp
    ${CMAKE_CURRENT_LIST_DIR}/src/TimeHistory.cpp
    ${CMAKE_CURRENT_LIST_DIR}/src/TimeHistoryPlots.cpp ${CMAKE_CURRENT_LIST_DIR}/src/WallGap.cpp)
target_link_libraries(crumple_crash_run PUBLIC crumple_crash_scenario crumple_scenes_pictures
    PRIVATE nlohmann_json::nlohmann_json crumple::compile_options)
if(TARGET crumple_scenes_bullet)
    target_link_libraries(crumple_crash_run PUBLIC crumple_scenes_bullet)
    target_compile_definitions(crumple_crash_run PRIVATE CRUMPLE_CRASH_BULLET)
endif()
if(TARGET crumple_scenes_ode)
    target_link_libraries(crumple_crash_run PUBLIC crumple_scenes_ode)
    target_compile_definitions(crumple_crash_run PRIVATE CRUMPLE_CRASH_ODE)
endif()
target_link_libraries(crumple_crash_run PUBLIC crumple::fem)
add_executable(crumple-crash ${CMAKE_CURRENT_LIST_DIR}/src/CrashMain.cpp)
target_link_libraries(crumple-crash PRIVATE crumple_crash_run crumple::compile_options)
# cmake --install: the tool, its scenario schema and the shipped scenarios and presets (scenarios name their
# presets by relative path, so both folders keep their layout under share/crumple).
include(GNUInstallDirs)
install(TARGETS crumple-crash RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT tools)
install(FILES ${PROJECT_SOURCE_DIR}/docs/scenarios.md ${PROJECT_SOURCE_DIR}/README.md
        DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT tools)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/samples/scenarios ${PROJECT_SOURCE_DIR}/samples/presets
        DESTINATION ${CMAKE_INSTALL_DATADIR}/crumple COMPONENT tools)
if(CRUMPLE_BUILD_TESTS)
    if(TARGET crumple-replay) # the command-line checks replay each run with crumple-replay (tools/replay)
        include(${PROJECT_SOURCE_DIR}/tests/crash/cli.cmake)
    endif()
    # The runner's private parts (the FEM barrier coupling), against known answers.
    find_package(Catch2 REQUIRED) # imported targets are per directory
    include(Catch)
    add_executable(test_crash_run ${PROJECT_SOURCE_DIR}/tests/TestMain.cpp ${PROJECT_SOURCE_DIR}/tests/crash/FemBarrierCouplingTest.cpp
        ${PROJECT_SOURCE_DIR}/tests/crash/CrushModelTest.cpp ${PROJECT_SOURCE_DIR}/tests/crash/TimeHistoryTest.cpp
        ${PROJECT_SOURCE_DIR}/tests/crash/ChartsTest.cpp ${PROJECT_SOURCE_DIR}/tests/crash/RigidWheelsTest.cpp
        ${PROJECT_SOURCE_DIR}/tests/crash/OutputFoldersTest.cpp ${PROJECT_SOURCE_DIR}/tests/crash/MeshPreparationTest.cpp
        ${PROJECT_SOURCE_DIR}/tests/crash/SanityChecksTest.cpp ${PROJECT_SOURCE_DIR}/tests/crash/WallGapTest.cpp
        ${PROJECT_SOURCE_DIR}/tests/crash/SurfaceFoldsTest.cpp ${PROJECT_SOURCE_DIR}/tests/crash/CrushProfileTest.cpp
        ${PROJECT_SOURCE_DIR}/tests/crash/StepOverlapTest.cpp ${PROJECT_SOURCE_DIR}/tests/crash/OccupantCellWarningTest.cpp)
    target_compile_definitions(test_crash_run PRIVATE CRUMPLE_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
    target_link_libraries(test_crash_run PRIVATE crumple_crash_run Catch2::Catch2 crumple::compile_options)
    target_include_directories(test_crash_run PRIVATE ${CMAKE_CURRENT_LIST_DIR}/src)
    catch_discover_tests(test_crash_run TEST_PREFIX "crash: " PROPERTIES LABELS crash)
endif()
