# playerkit_add_test(NAME foo_test SOURCES foo_test.cpp LIBS playerkit_protocol)
# Builds one GoogleTest program and registers each of its tests with CTest.
#
# Test sources are compiled in batches like every target (PLAYERKIT_UNITY_BUILD,
# cmake/UnityBuild.cmake), larger ones: most of a test file's compile time is
# instantiating what its neighbours instantiate too (gtest's assertions,
# nlohmann/json, the structs' comparisons), which a batch does once. One batch
# of all 47 protocol test files takes 42 s of CPU, six batches of eight 85 s.
# Tests keep their helpers in a namespace named after the file
# (namespace foo_test { ... }), not in an anonymous one shared by the batch.
# Extra compile options for test sources only: CI passes -O0, since test code
# runs once and most of its compile time is optimising gtest's expansions;
# the library code under test keeps the build type's flags.
set(PLAYERKIT_TEST_COMPILE_OPTIONS "" CACHE STRING "Compile options for test sources (e.g. -O0)")
set(PLAYERKIT_TEST_UNITY_BATCH 24 CACHE STRING "Test sources per batch")

function(playerkit_add_test)
  if(NOT BUILD_TESTING)
    return()
  endif()
  cmake_parse_arguments(ARG "" "NAME" "SOURCES;LIBS" ${ARGN})
  add_executable(${ARG_NAME} ${ARG_SOURCES})
  target_link_libraries(${ARG_NAME} PRIVATE ${ARG_LIBS} GTest::gtest GTest::gtest_main playerkit_warnings)
  target_compile_definitions(${ARG_NAME} PRIVATE
    PLAYERKIT_TEST_DATA_DIR="${PROJECT_SOURCE_DIR}/tests/data")
  if(PLAYERKIT_TEST_COMPILE_OPTIONS)
    target_compile_options(${ARG_NAME} PRIVATE ${PLAYERKIT_TEST_COMPILE_OPTIONS})
  endif()
  set_target_properties(${ARG_NAME} PROPERTIES UNITY_BUILD_BATCH_SIZE ${PLAYERKIT_TEST_UNITY_BATCH})
  gtest_discover_tests(${ARG_NAME} TEST_PREFIX "${ARG_NAME}." DISCOVERY_TIMEOUT 30 PROPERTIES TIMEOUT 120)
endfunction()
