# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# test_props: collision impulses onto FEM props and FemProp on either backend (its GPU cases need crumple::gpu
# and run on llvmpipe where no GPU exists).
crumple_add_test(props
    props/CollisionImpulsesTest.cpp
    props/ContactSpreadTest.cpp
    props/FemPropTest.cpp
    props/FragmentBodyTest.cpp
    props/HeldPropBodiesTest.cpp
    props/LooseFragmentsTest.cpp
    props/PropBodyTest.cpp
    props/PropRecordingTest.cpp
    props/PropRemoveTest.cpp
    props/PropStepOffThreadTest.cpp
    props/PropWorldTest.cpp
    LINK crumple::props crumple_scenes_fem)
if(TARGET crumple_gpu)
    target_compile_definitions(test_props PRIVATE CRUMPLE_TEST_PROPS_WITH_GPU)
endif()
