# -DPLAYERKIT_SANITIZE=thread (or address) instruments every target.
if(PLAYERKIT_SANITIZE)
  add_compile_options(-fsanitize=${PLAYERKIT_SANITIZE} -fno-omit-frame-pointer)
  add_link_options(-fsanitize=${PLAYERKIT_SANITIZE})
endif()
# GCC warns that Boost.Asio's atomic_thread_fence is invisible to TSan. Asio's
# fences sit beside mutexes that TSan does see; the warning is noise here.
if(PLAYERKIT_SANITIZE STREQUAL "thread" AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  add_compile_options(-Wno-tsan)
endif()
