# -DPLAYERKIT_FUZZ=ON (scripts/fuzz, clang only): every target instrumented
# for libFuzzer's coverage and for AddressSanitizer and UBSan, and one
# libFuzzer binary per fuzz target of tests/fuzz. UBSan stops at the first
# report, so libFuzzer sees undefined behaviour as a crash.
option(PLAYERKIT_FUZZ "Build the libFuzzer targets of tests/fuzz (clang)" OFF)
if(PLAYERKIT_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "PLAYERKIT_FUZZ needs clang (scripts/fuzz configures it)")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all
                      -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()
