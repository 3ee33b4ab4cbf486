# playerkit_add_test(NAME foo_test SOURCES foo_test.cpp LIBS playerkit_protocol)
# Builds one GoogleTest program and registers each of its tests with CTest.
function(playerkit_add_test)
  if(NOT BUILD_TESTING)
    return()
  endif()
  cmake_parse_arguments(ARG "" "NAME" "SOURCES;LIBS" ${ARGN})
  add_executable(${ARG_NAME} ${ARG_SOURCES})
  target_link_libraries(${ARG_NAME} PRIVATE ${ARG_LIBS} GTest::gtest GTest::gtest_main playerkit_warnings)
  target_compile_definitions(${ARG_NAME} PRIVATE
    PLAYERKIT_TEST_DATA_DIR="${PROJECT_SOURCE_DIR}/tests/data")
  gtest_discover_tests(${ARG_NAME} TEST_PREFIX "${ARG_NAME}." DISCOVERY_TIMEOUT 30 PROPERTIES TIMEOUT 120)
endfunction()
