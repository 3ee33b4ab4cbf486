# -DPLAYERKIT_SANITIZE=<list> instruments every target with -fsanitize=<list>:
# thread, or address,undefined (scripts/test --sanitize).
if(PLAYERKIT_SANITIZE)
  add_compile_options(-fsanitize=${PLAYERKIT_SANITIZE} -fno-omit-frame-pointer)
  add_link_options(-fsanitize=${PLAYERKIT_SANITIZE})
  # A UBSan report would otherwise print and carry on, and the test around it
  # still pass: every report ends the process with an error instead.
  if(PLAYERKIT_SANITIZE MATCHES "address|undefined")
    add_compile_options(-fno-sanitize-recover=all)
    add_link_options(-fno-sanitize-recover=all)
  endif()
endif()
# GCC warns, once per Asio handler, that Boost.Asio's atomic_thread_fence is
# invisible to TSan (it could cause false race reports; our runs show none).
# One note here instead of hundreds of lines per build.
if(PLAYERKIT_SANITIZE STREQUAL "thread" AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  add_compile_options(-Wno-tsan)
endif()
