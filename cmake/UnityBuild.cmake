# Every target compiles its sources in batches of PLAYERKIT_UNITY_BATCH (CMake
# unity builds; test programs in larger ones, PLAYERKIT_TEST_UNITY_BATCH in
# cmake/PlayerkitTest.cmake). Most of a file's compile time is parsing the headers it
# shares with its neighbours (Boost.Asio, nlohmann/json, gtest, Eigen); a batch
# parses them once. Measured on the whole tree: the libraries took 3 to 6
# times less CPU (lib/client 67 s -> 15 s, lib/links 33 s -> 5 s).
#
# What that asks of the code: two .cpp files of one folder may land in one
# batch, so file-local helpers (anonymous namespace, static) must not share a
# name with another file's of the same target; shared helpers go in the
# folder's own header instead of being copied. A file that cannot share a
# batch (one including kernel headers that clash with libc's) says so with
# playerkit_compile_alone().
#
# -DPLAYERKIT_UNITY_BUILD=OFF compiles file by file (what an IDE or a
# single-file change may prefer).
option(PLAYERKIT_UNITY_BUILD "Compile each target's sources in batches" ON)
set(PLAYERKIT_UNITY_BATCH 8 CACHE STRING "Library and program sources per batch")
if(PLAYERKIT_UNITY_BUILD)
  set(CMAKE_UNITY_BUILD ON)
  set(CMAKE_UNITY_BUILD_BATCH_SIZE ${PLAYERKIT_UNITY_BATCH})
endif()

# playerkit_compile_alone(file.cpp ...): these sources stay out of batches.
function(playerkit_compile_alone)
  set_source_files_properties(${ARGN} DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}
                              PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
endfunction()
