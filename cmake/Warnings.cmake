# Every playerkit target links this interface library to get the project's warnings.
add_library(playerkit_warnings INTERFACE)
target_compile_options(playerkit_warnings INTERFACE
  $<$<COMPILE_LANG_AND_ID:CXX,GNU,Clang>:-Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion>
  $<$<COMPILE_LANG_AND_ID:C,GNU,Clang>:-Wall -Wextra -Wpedantic>)
if(PLAYERKIT_WERROR)
  target_compile_options(playerkit_warnings INTERFACE -Werror)
endif()
