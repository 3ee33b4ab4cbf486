# -DPLAYERKIT_SANITIZE=thread (or address) instruments every target.
if(PLAYERKIT_SANITIZE)
  add_compile_options(-fsanitize=${PLAYERKIT_SANITIZE} -fno-omit-frame-pointer)
  add_link_options(-fsanitize=${PLAYERKIT_SANITIZE})
endif()
# GCC warns, once per Asio handler, that Boost.Asio's atomic_thread_fence is
# invisible to TSan (it could cause false race reports; our runs show none).
# One note here instead of hundreds of lines per build.
if(PLAYERKIT_SANITIZE STREQUAL "thread" AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  add_compile_options(-Wno-tsan)
endif()
