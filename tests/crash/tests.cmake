# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# test_crash: the crumple-crash tool (tools/crash), built only when its target exists (nlohmann-json found).
if(TARGET crumple_crash_scenario)
    crumple_add_test(crash crash/ScenarioFileTest.cpp LINK crumple_crash_scenario)
endif()
