# -DPLAYERKIT_SANITIZE=thread (or address) instruments every target.
if(PLAYERKIT_SANITIZE)
  add_compile_options(-fsanitize=${PLAYERKIT_SANITIZE} -fno-omit-frame-pointer)
  add_link_options(-fsanitize=${PLAYERKIT_SANITIZE})
endif()
