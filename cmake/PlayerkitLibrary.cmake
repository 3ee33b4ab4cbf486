# playerkit_folder_library(NAME name [DEPENDS target...] [PRIVATE_DEPENDS target...]
#                          [TEST_DEPENDS target...])
#
# A library `playerkit_<name>` of every non-test .cpp in the calling folder,
# and one test program `<name>_test` of its *_test.cpp files. A folder still
# being written (no sources yet) adds nothing, so a new folder can be wired
# in before its first file lands.
function(playerkit_folder_library)
  cmake_parse_arguments(ARG "" "NAME" "DEPENDS;PRIVATE_DEPENDS;TEST_DEPENDS" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  list(FILTER sources EXCLUDE REGEX "_test\\.cpp$")
  if(NOT sources)
    return()
  endif()
  add_library(playerkit_${ARG_NAME} ${sources})
  target_include_directories(playerkit_${ARG_NAME} PUBLIC ${PROJECT_SOURCE_DIR}/lib)
  target_link_libraries(playerkit_${ARG_NAME}
    PUBLIC ${ARG_DEPENDS}
    PRIVATE ${ARG_PRIVATE_DEPENDS} playerkit_warnings)
  file(GLOB tests CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*_test.cpp)
  if(tests)
    playerkit_add_test(NAME ${ARG_NAME}_test SOURCES ${tests}
                       LIBS playerkit_${ARG_NAME} ${ARG_TEST_DEPENDS})
  endif()
endfunction()
