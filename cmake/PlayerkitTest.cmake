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

# With clang, the test programs share one precompiled header of gtest,
# nlohmann/json and the standard headers most tests include: parsing them was
# most of a test batch's time once code generation at -O0 got cheap (clang's
# frontend 5.7 of 7.1 s on player_cat_test's batch). Seven test batches took
# 47.5 s without it and 37.1 s with it, one compile at a time. GCC's
# precompiled headers gained nothing here (its -O0 code generation dominates),
# so GCC builds go without. The header must be built with the tests' own
# flags (PLAYERKIT_TEST_COMPILE_OPTIONS): clang refuses a PCH whose
# optimisation level differs. Test programs with C sources go without too.
option(PLAYERKIT_TEST_PCH "Share a precompiled header among the test programs (clang)" ON)
set(playerkit_test_pch_enabled OFF)
if(BUILD_TESTING AND PLAYERKIT_TEST_PCH AND CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  set(playerkit_test_pch_enabled ON)
  add_library(playerkit_test_pch OBJECT ${CMAKE_CURRENT_LIST_DIR}/test_pch.cpp)
  target_link_libraries(playerkit_test_pch PRIVATE GTest::gtest nlohmann_json::nlohmann_json playerkit_warnings)
  target_compile_definitions(playerkit_test_pch PRIVATE PLAYERKIT_TEST_DATA_DIR="${PROJECT_SOURCE_DIR}/tests/data")
  if(PLAYERKIT_TEST_COMPILE_OPTIONS)
    target_compile_options(playerkit_test_pch PRIVATE ${PLAYERKIT_TEST_COMPILE_OPTIONS})
  endif()
  target_precompile_headers(playerkit_test_pch PRIVATE
    <gtest/gtest.h> <nlohmann/json.hpp>
    <algorithm> <array> <chrono> <cstdint> <filesystem> <fstream> <functional> <map>
    <memory> <optional> <sstream> <string> <string_view> <thread> <vector>)
endif()

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
  set(c_sources ${ARG_SOURCES})
  list(FILTER c_sources INCLUDE REGEX "\\.c$")
  if(playerkit_test_pch_enabled AND NOT c_sources)
    target_precompile_headers(${ARG_NAME} REUSE_FROM playerkit_test_pch)
  endif()
  # A test that hangs fails after two minutes. Instrumented code
  # (PLAYERKIT_SANITIZE) runs several times slower, and scripts/test runs
  # three tests per core: there the longest amcl test took 96-98 s of its
  # 120 in three CI runs and 120 in a fourth (33 s alone), so such builds
  # give every test six minutes.
  set(timeout 120)
  if(PLAYERKIT_SANITIZE)
    set(timeout 360)
  endif()
  gtest_discover_tests(${ARG_NAME} TEST_PREFIX "${ARG_NAME}." DISCOVERY_TIMEOUT 30 PROPERTIES TIMEOUT ${timeout})
endfunction()
