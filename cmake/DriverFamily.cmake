# playerkit_driver_family(NAME family HEADERS header... SPECS spec_function...
#                         [DEPENDS target...] [TEST_NEEDS family...]
#                         [TEST_LIBS target...] [DEFAULT ON|OFF])
#
# One family of built-in drivers (lib/drivers/<family>): library
# playerkit_drivers_<family> of the folder's sources, test program
# drivers_<family>_test, and option PLAYERKIT_DRIVERS_<FAMILY> to leave it
# out (Player 1.5's configure had --disable-<family>), so that one family's
# missing dependency never breaks the others. SPECS names the family's
# `core::DriverSpec f()` functions, or `std::vector<core::DriverSpec> f()` for
# drivers made from one table (namespace playerkit::drivers); the list of
# built-in drivers is generated from the families built (builtin_drivers.cpp.in).
# TEST_NEEDS: families whose drivers this family's tests use (amcl's tests
# replay logs through readlog); without them the tests are not built.
# TEST_LIBS: more libraries for the tests only (the emulators).
function(playerkit_driver_family)
  cmake_parse_arguments(ARG "" "NAME;DEFAULT" "HEADERS;SPECS;DEPENDS;TEST_NEEDS;TEST_LIBS" ${ARGN})
  if(NOT DEFINED ARG_DEFAULT)
    set(ARG_DEFAULT ON)
  endif()
  string(TOUPPER "${ARG_NAME}" upper)
  option(PLAYERKIT_DRIVERS_${upper} "Build the ${ARG_NAME} drivers" ${ARG_DEFAULT})
  if(NOT PLAYERKIT_DRIVERS_${upper})
    message(STATUS "drivers: ${ARG_NAME} left out (PLAYERKIT_DRIVERS_${upper}=OFF)")
    return()
  endif()

  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  list(FILTER sources EXCLUDE REGEX "_test\\.cpp$")
  if(NOT sources)
    return()  # a family still being written
  endif()
  add_library(playerkit_drivers_${ARG_NAME} ${sources})
  target_include_directories(playerkit_drivers_${ARG_NAME} PUBLIC ${PROJECT_SOURCE_DIR}/lib)
  target_link_libraries(playerkit_drivers_${ARG_NAME}
    PUBLIC playerkit_core ${ARG_DEPENDS} PRIVATE playerkit_warnings)

  set_property(GLOBAL APPEND PROPERTY PLAYERKIT_DRIVER_FAMILIES ${ARG_NAME})
  set_property(GLOBAL PROPERTY PLAYERKIT_DRIVER_SPECS_${ARG_NAME} ${ARG_SPECS})
  set_property(GLOBAL PROPERTY PLAYERKIT_DRIVER_HEADERS_${ARG_NAME} ${ARG_HEADERS})

  file(GLOB tests CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*_test.cpp)
  if(tests)
    set(missing "")
    foreach(needed IN LISTS ARG_TEST_NEEDS)
      string(TOUPPER "${needed}" needed_upper)
      if(NOT PLAYERKIT_DRIVERS_${needed_upper})
        list(APPEND missing ${needed})
      endif()
    endforeach()
    if(missing)
      message(STATUS "drivers: ${ARG_NAME} tests left out, they need ${missing}")
    else()
      # The tests build devices from config text through the built-in list.
      set_property(GLOBAL APPEND PROPERTY PLAYERKIT_DRIVER_TESTS drivers_${ARG_NAME}_test)
      playerkit_add_test(NAME drivers_${ARG_NAME}_test SOURCES ${tests}
                         LIBS playerkit_drivers playerkit_test_support ${ARG_TEST_LIBS})
    endif()
  endif()
endfunction()

# After every family: playerkit_drivers, the built-in list of what was built.
function(playerkit_builtin_drivers)
  get_property(families GLOBAL PROPERTY PLAYERKIT_DRIVER_FAMILIES)
  set(includes "")
  set(registrations "")
  foreach(family IN LISTS families)
    get_property(headers GLOBAL PROPERTY PLAYERKIT_DRIVER_HEADERS_${family})
    foreach(header IN LISTS headers)
      string(APPEND includes "#include \"${header}\"\n")
    endforeach()
    get_property(specs GLOBAL PROPERTY PLAYERKIT_DRIVER_SPECS_${family})
    foreach(spec IN LISTS specs)
      string(APPEND registrations "  add(${spec}(), \"${family}\");\n")
    endforeach()
  endforeach()
  set(PLAYERKIT_BUILTIN_INCLUDES "${includes}")
  set(PLAYERKIT_BUILTIN_REGISTRATIONS "${registrations}")
  configure_file(${CMAKE_CURRENT_SOURCE_DIR}/builtin_drivers.cpp.in
                 ${CMAKE_CURRENT_BINARY_DIR}/builtin_drivers.cpp @ONLY)
  add_library(playerkit_drivers ${CMAKE_CURRENT_BINARY_DIR}/builtin_drivers.cpp)
  target_include_directories(playerkit_drivers PUBLIC ${PROJECT_SOURCE_DIR}/lib)
  list(TRANSFORM families PREPEND playerkit_drivers_ OUTPUT_VARIABLE family_targets)
  target_link_libraries(playerkit_drivers PUBLIC playerkit_core ${family_targets} PRIVATE playerkit_warnings)
endfunction()

# playerkit_add_family(name)
#
# The one line that adds a hardware family (lib/families/<name>) to the build,
# unless -DPLAYERKIT_DRIVERS_<NAME>=OFF leaves it out: its protocol, drivers,
# emulators, probes and trace framing all go together.
function(playerkit_add_family name)
  string(TOUPPER "${name}" upper)
  option(PLAYERKIT_DRIVERS_${upper} "Build the ${name} family (drivers, emulators, probes)" ON)
  if(NOT PLAYERKIT_DRIVERS_${upper})
    message(STATUS "families: ${name} left out (PLAYERKIT_DRIVERS_${upper}=OFF)")
    return()
  endif()
  add_subdirectory(${name})
endfunction()

# playerkit_family_spec(NAME family SPEC function HEADER header
#                       [DEPENDS target...] [TEST_DEPENDS target...])
#
# A family's own folder (lib/families/<family>): library
# playerkit_<family>_family of its sources (the spec, probes, emulator
# factories), test program <family>_family_test, and the registration of
# `families::FamilySpec function()` (namespace playerkit::families) in the
# built-in family list (builtin_families.cpp.in).
function(playerkit_family_spec)
  cmake_parse_arguments(ARG "" "NAME;SPEC;HEADER" "DEPENDS;TEST_DEPENDS" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  list(FILTER sources EXCLUDE REGEX "_test\\.cpp$")
  add_library(playerkit_${ARG_NAME}_family ${sources})
  target_include_directories(playerkit_${ARG_NAME}_family PUBLIC ${PROJECT_SOURCE_DIR}/lib)
  target_link_libraries(playerkit_${ARG_NAME}_family
    PUBLIC playerkit_families ${ARG_DEPENDS} PRIVATE playerkit_warnings)
  set_property(GLOBAL APPEND PROPERTY PLAYERKIT_FAMILY_SPECS ${ARG_NAME})
  set_property(GLOBAL PROPERTY PLAYERKIT_FAMILY_SPEC_${ARG_NAME} ${ARG_SPEC})
  set_property(GLOBAL PROPERTY PLAYERKIT_FAMILY_HEADER_${ARG_NAME} ${ARG_HEADER})
  file(GLOB tests CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*_test.cpp)
  if(tests)
    playerkit_add_test(NAME ${ARG_NAME}_family_test SOURCES ${tests}
                       LIBS playerkit_${ARG_NAME}_family ${ARG_TEST_DEPENDS})
  endif()
endfunction()

# After every family: playerkit_family_registry, the built-in family list of
# what was built (families::register_builtin_families).
function(playerkit_builtin_families)
  get_property(families GLOBAL PROPERTY PLAYERKIT_FAMILY_SPECS)
  set(includes "")
  set(registrations "")
  set(targets "")
  foreach(family IN LISTS families)
    get_property(header GLOBAL PROPERTY PLAYERKIT_FAMILY_HEADER_${family})
    get_property(spec GLOBAL PROPERTY PLAYERKIT_FAMILY_SPEC_${family})
    string(APPEND includes "#include \"${header}\"\n")
    string(APPEND registrations "  registry.add(${spec}());\n")
    list(APPEND targets playerkit_${family}_family)
  endforeach()
  set(PLAYERKIT_FAMILY_INCLUDES "${includes}")
  set(PLAYERKIT_FAMILY_REGISTRATIONS "${registrations}")
  configure_file(${CMAKE_CURRENT_SOURCE_DIR}/builtin_families.cpp.in
                 ${CMAKE_CURRENT_BINARY_DIR}/builtin_families.cpp @ONLY)
  add_library(playerkit_family_registry ${CMAKE_CURRENT_BINARY_DIR}/builtin_families.cpp)
  target_include_directories(playerkit_family_registry PUBLIC ${PROJECT_SOURCE_DIR}/lib)
  target_link_libraries(playerkit_family_registry PUBLIC playerkit_families ${targets} PRIVATE playerkit_warnings)
endfunction()
