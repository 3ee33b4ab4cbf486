# playerkit_export_library_for_plugins(target)
# Driver plugins (-d lib.so) are MODULE libraries that call into playerkit_core
# without linking it. An executable that loads them links the whole core
# archive (not just the objects it uses itself) and exports its symbols.
function(playerkit_export_library_for_plugins target)
  set_target_properties(${target} PROPERTIES ENABLE_EXPORTS ON)
  target_link_options(${target} PRIVATE
    "LINKER:--whole-archive" "$<TARGET_FILE:playerkit_core>" "LINKER:--no-whole-archive")
  add_dependencies(${target} playerkit_core)
endfunction()
