# Every playerkit target links this interface library to get the project's warnings.
add_library(playerkit_warnings INTERFACE)
target_compile_options(playerkit_warnings INTERFACE
  $<$<COMPILE_LANG_AND_ID:CXX,GNU,Clang>:-Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion>
  $<$<COMPILE_LANG_AND_ID:C,GNU,Clang>:-Wall -Wextra -Wpedantic>)
if(PLAYERKIT_WERROR)
  target_compile_options(playerkit_warnings INTERFACE -Werror)
endif()

# GCC 12 at -O2/-O3 reports out-of-bounds and overlapping memcpy inside
# libstdc++'s std::copy and std::string after inlining (array-bounds,
# restrict, stringop-overflow, stringop-overread), on code that does
# neither (GCC bug 105329 and its relatives; seen with Debian 12's GCC 12). Unity batches
# inline more across files and surface more of them. The checks stay on at
# -O1 and -O0, where CI builds with -Werror.
string(TOUPPER "${CMAKE_BUILD_TYPE}" playerkit_build_type)
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13
   AND "${CMAKE_CXX_FLAGS_${playerkit_build_type}}" MATCHES "-O[23]")
  target_compile_options(playerkit_warnings INTERFACE
    $<$<COMPILE_LANGUAGE:CXX>:-Wno-array-bounds -Wno-restrict -Wno-stringop-overflow -Wno-stringop-overread>)
endif()
