# Install rules and packaging, included last from the top-level CMakeLists.txt
# (install(TARGETS) works on targets defined elsewhere once they exist).
#
#   cmake --install build [--prefix DIR]   tools, client libraries, headers, CMake
#                                          package, pkg-config files, man pages,
#                                          bash completion
#   cpack --config build/CPackConfig.cmake the .deb (packaging/README.md)
#
# What is installed:
#   bin/                                   every executable of tools/ (found, not listed)
#   lib/libplayerkit_{protocol,client,playercclient}.a
#   include/playerkit/{protocol,client}/   the libraries' headers, as lib/ lays them out
#   lib/cmake/playerkit/                   find_package(playerkit): playerkit::client,
#                                          playerkit::playercclient (and playerkit::protocol)
#   lib/pkgconfig/                         playerkit-client.pc, playercclient.pc
#   share/man/man1/                        a page per tool, from its --help (gzipped)
#   share/bash-completion/completions/     a script per tool, from its --help
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(PLAYERKIT_INSTALL_INCLUDEDIR ${CMAKE_INSTALL_INCLUDEDIR}/playerkit)
set(PLAYERKIT_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/playerkit)
set(PLAYERKIT_INSTALL_PKGCONFIGDIR ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
set(PLAYERKIT_INSTALL_COMPLETIONDIR ${CMAKE_INSTALL_DATADIR}/bash-completion/completions)
set(playerkit_packaging_dir ${PROJECT_SOURCE_DIR}/packaging)
set(playerkit_packaging_out ${PROJECT_BINARY_DIR}/packaging)

# ---- the tools ---------------------------------------------------------------

# playerkit_collect_tools(<var> <dir>): every executable target defined in <dir>
# and below, except test programs (they link GoogleTest). New tools under
# tools/ (player-drivers) are picked up without being named here.
function(playerkit_collect_tools out dir)
  set(found "")
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  foreach(target IN LISTS targets)
    get_target_property(type ${target} TYPE)
    get_target_property(libraries ${target} LINK_LIBRARIES)
    get_target_property(excluded ${target} EXCLUDE_FROM_ALL)
    if(type STREQUAL "EXECUTABLE" AND NOT excluded AND NOT target MATCHES "_test$"
       AND NOT "GTest::gtest_main" IN_LIST libraries AND NOT "GTest::gtest" IN_LIST libraries)
      list(APPEND found ${target})
    endif()
  endforeach()
  get_property(subdirectories DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(subdirectory IN LISTS subdirectories)
    playerkit_collect_tools(below ${subdirectory})
    list(APPEND found ${below})
  endforeach()
  set(${out} ${found} PARENT_SCOPE)
endfunction()

playerkit_collect_tools(playerkit_tools ${PROJECT_SOURCE_DIR}/tools)
list(SORT playerkit_tools)
if(playerkit_tools)
  install(TARGETS ${playerkit_tools} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()

# Man pages and bash completion, generated from each tool's --help at build
# time (packaging/make_man_page.py, packaging/make_completion.py).
find_package(Python3 COMPONENTS Interpreter)
if(NOT Python3_Interpreter_FOUND)
  message(WARNING "python3 not found: no man pages or bash completion for the tools")
elseif(NOT CMAKE_CROSSCOMPILING AND playerkit_tools)
  string(JOIN "," playerkit_tools_csv ${playerkit_tools})
  set(playerkit_generated_docs "")
  set(generator_sources ${playerkit_packaging_dir}/cli_help.py)
  foreach(tool IN LISTS playerkit_tools)
    set(page ${playerkit_packaging_out}/man/${tool}.1)
    set(completion ${playerkit_packaging_out}/completions/${tool})
    add_custom_command(OUTPUT ${page}
      COMMAND ${CMAKE_COMMAND} -E make_directory ${playerkit_packaging_out}/man
      COMMAND Python3::Interpreter -B ${playerkit_packaging_dir}/make_man_page.py $<TARGET_FILE:${tool}>
              --version ${PROJECT_VERSION} --see-also ${playerkit_tools_csv} -o ${page}
      # Installed compressed, as Debian's policy asks (-n: no name or time
      # inside, so the same page gives the same bytes).
      COMMAND gzip -9nkf ${page}
      BYPRODUCTS ${page}.gz
      DEPENDS ${tool} ${playerkit_packaging_dir}/make_man_page.py ${generator_sources}
      COMMENT "Man page ${tool}.1 from ${tool} --help" VERBATIM)
    add_custom_command(OUTPUT ${completion}
      COMMAND ${CMAKE_COMMAND} -E make_directory ${playerkit_packaging_out}/completions
      COMMAND Python3::Interpreter -B ${playerkit_packaging_dir}/make_completion.py $<TARGET_FILE:${tool}>
              -o ${completion}
      DEPENDS ${tool} ${playerkit_packaging_dir}/make_completion.py ${generator_sources}
      COMMENT "Bash completion for ${tool} from ${tool} --help" VERBATIM)
    list(APPEND playerkit_generated_docs ${page} ${completion})
    install(FILES ${page}.gz DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
    install(FILES ${completion} DESTINATION ${PLAYERKIT_INSTALL_COMPLETIONDIR})
  endforeach()
  add_custom_target(playerkit_tool_docs ALL DEPENDS ${playerkit_generated_docs})
endif()

# ---- the client libraries: headers, CMake package ----------------------------

# The package's libraries; consumers see them without the prefix:
# playerkit::protocol, playerkit::client, playerkit::playercclient.
set(playerkit_package_libraries playerkit_protocol playerkit_client playerkit_playercclient)

# playerkit_prepare_for_export(<target>): the target's usage requirements as an
# installed consumer needs them, without changing what the build sees.
#  - include directories in the source tree are build-only; installed, lib/X
#    becomes include/playerkit/X (lib/client/c keeps <playercclient.h> working);
#  - private link items that carry nothing (playerkit_warnings: compile flags
#    only, and LINK_ONLY drops those) are not exported.
# Returns in <missing> the project libraries it links that are not exported.
function(playerkit_prepare_for_export target exported missing)
  get_target_property(includes ${target} INTERFACE_INCLUDE_DIRECTORIES)
  if(NOT includes)
    set(includes "")
  endif()
  set(rewritten "")
  foreach(dir IN LISTS includes)
    if(dir MATCHES "^\\$<" OR NOT IS_ABSOLUTE "${dir}")
      list(APPEND rewritten "${dir}")
      continue()
    endif()
    list(APPEND rewritten "$<BUILD_INTERFACE:${dir}>")
    cmake_path(IS_PREFIX PROJECT_SOURCE_DIR "${dir}" NORMALIZE in_source)
    if(in_source)
      file(RELATIVE_PATH relative ${PROJECT_SOURCE_DIR}/lib ${dir})
      if(relative MATCHES "^\\.\\.")
        message(FATAL_ERROR "${target}: include directory ${dir} is outside lib/")
      endif()
      cmake_path(APPEND PLAYERKIT_INSTALL_INCLUDEDIR "${relative}" OUTPUT_VARIABLE installed)
      list(APPEND rewritten "$<INSTALL_INTERFACE:${installed}>")
    endif()
  endforeach()
  set_property(TARGET ${target} PROPERTY INTERFACE_INCLUDE_DIRECTORIES "${rewritten}")

  get_target_property(links ${target} INTERFACE_LINK_LIBRARIES)
  if(NOT links)
    set(links "")
  endif()
  set(kept "")
  set(not_exported "")
  foreach(item IN LISTS links)
    string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" linked "${item}")
    if(TARGET "${linked}")
      get_target_property(imported ${linked} IMPORTED)
      get_target_property(type ${linked} TYPE)
      get_target_property(its_links ${linked} INTERFACE_LINK_LIBRARIES)
      if(NOT imported AND type STREQUAL "INTERFACE_LIBRARY" AND NOT its_links AND NOT item STREQUAL linked)
        continue()  # flags only, and LINK_ONLY would not pass them on anyway
      endif()
      if(NOT imported AND NOT linked IN_LIST exported)
        list(APPEND not_exported ${linked})
      endif()
    endif()
    list(APPEND kept "${item}")
  endforeach()
  set_property(TARGET ${target} PROPERTY INTERFACE_LINK_LIBRARIES "${kept}")
  set(${missing} ${not_exported} PARENT_SCOPE)
endfunction()

set(playerkit_exported "")
set(playerkit_export_names "")
foreach(target IN LISTS playerkit_package_libraries)
  if(TARGET ${target})
    list(APPEND playerkit_exported ${target})
    string(REGEX REPLACE "^playerkit_" "" name ${target})
    list(APPEND playerkit_export_names ${name})
  endif()
endforeach()

set(playerkit_missing "")
foreach(target IN LISTS playerkit_exported)
  playerkit_prepare_for_export(${target} "${playerkit_exported}" missing)
  list(APPEND playerkit_missing ${missing})
endforeach()
list(REMOVE_DUPLICATES playerkit_missing)

if(NOT playerkit_exported)
  message(WARNING "no client libraries to install (lib/protocol, lib/client not built?)")
elseif(playerkit_missing)
  # Exporting would stop CMake for everyone; say what to add instead.
  message(WARNING "find_package(playerkit) is not installed: ${playerkit_exported} link "
                  "${playerkit_missing}, which cmake/Install.cmake does not export; add them to "
                  "playerkit_package_libraries.")
else()
  foreach(target name IN ZIP_LISTS playerkit_exported playerkit_export_names)
    set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
    # The headers use C++20 (std::span, concepts); consumers get it from the target.
    target_compile_features(${target} INTERFACE cxx_std_20)
  endforeach()
  install(TARGETS ${playerkit_exported} EXPORT playerkitTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(EXPORT playerkitTargets NAMESPACE playerkit:: DESTINATION ${PLAYERKIT_INSTALL_CMAKEDIR})

  # The headers of each exported library's folder (and its subfolders), as
  # lib/ lays them out: they include each other as "protocol/...", "client/...".
  set(header_dirs "")
  foreach(target IN LISTS playerkit_exported)
    get_target_property(source_dir ${target} SOURCE_DIR)
    list(APPEND header_dirs ${source_dir})
  endforeach()
  foreach(dir IN LISTS header_dirs)
    set(nested FALSE)
    foreach(other IN LISTS header_dirs)
      cmake_path(IS_PREFIX other "${dir}" inside)
      if(inside AND NOT other STREQUAL dir)
        set(nested TRUE)
      endif()
    endforeach()
    if(nested)
      continue()  # lib/client/c comes with lib/client
    endif()
    file(RELATIVE_PATH relative ${PROJECT_SOURCE_DIR}/lib ${dir})
    cmake_path(GET relative PARENT_PATH parent)
    install(DIRECTORY ${dir} DESTINATION ${PLAYERKIT_INSTALL_INCLUDEDIR}/${parent}
      FILES_MATCHING PATTERN "*.hpp" PATTERN "*.h"
      REGEX "_test[^/]*$" EXCLUDE)
  endforeach()

  # find_dependency() for each imported target the libraries link: the package
  # name is what precedes "::" (Boost::system: Boost with that component).
  set(boost_components "")
  set(packages "")
  foreach(target IN LISTS playerkit_exported)
    get_target_property(links ${target} INTERFACE_LINK_LIBRARIES)
    if(NOT links)
      continue()
    endif()
    foreach(item IN LISTS links)
      string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" linked "${item}")
      if(linked MATCHES "^Boost::(.*)$")
        if(NOT CMAKE_MATCH_1 STREQUAL "headers" AND NOT CMAKE_MATCH_1 STREQUAL "boost")
          list(APPEND boost_components ${CMAKE_MATCH_1})
        endif()
        list(APPEND packages Boost)
      elseif(linked MATCHES "^([A-Za-z0-9_]+)::")
        list(APPEND packages ${CMAKE_MATCH_1})
      endif()
    endforeach()
  endforeach()
  list(REMOVE_DUPLICATES packages)
  list(REMOVE_DUPLICATES boost_components)
  set(PLAYERKIT_FIND_DEPENDENCIES "")
  foreach(package IN LISTS packages)
    if(package STREQUAL "Boost")
      string(APPEND PLAYERKIT_FIND_DEPENDENCIES
        "find_dependency(Boost COMPONENTS ${boost_components})\n")
    else()
      string(APPEND PLAYERKIT_FIND_DEPENDENCIES "find_dependency(${package})\n")
    endif()
  endforeach()
  string(JOIN " " PLAYERKIT_PACKAGE_COMPONENTS ${playerkit_export_names})

  configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/playerkitConfig.cmake.in
    ${playerkit_packaging_out}/playerkitConfig.cmake
    INSTALL_DESTINATION ${PLAYERKIT_INSTALL_CMAKEDIR})
  # 0.x: a minor version may break the API.
  write_basic_package_version_file(${playerkit_packaging_out}/playerkitConfigVersion.cmake
    COMPATIBILITY SameMinorVersion)
  install(FILES ${playerkit_packaging_out}/playerkitConfig.cmake
                ${playerkit_packaging_out}/playerkitConfigVersion.cmake
          DESTINATION ${PLAYERKIT_INSTALL_CMAKEDIR})

  # pkg-config files. Their prefix is the one installed to (cmake --install
  # --prefix, or /usr in the .deb), known only at install time: the .pc.in are
  # configured now except for @PLAYERKIT_PC_PREFIX@, filled in by install(CODE).
  set(PLAYERKIT_PC_PREFIX "@PLAYERKIT_PC_PREFIX@")
  foreach(pc playerkit-client playercclient)
    configure_file(${playerkit_packaging_dir}/pkgconfig/${pc}.pc.in
                   ${playerkit_packaging_out}/pkgconfig/${pc}.pc.in @ONLY)
    install(CODE "
      set(PLAYERKIT_PC_PREFIX \"\${CMAKE_INSTALL_PREFIX}\")
      configure_file(\"${playerkit_packaging_out}/pkgconfig/${pc}.pc.in\"
                     \"${playerkit_packaging_out}/pkgconfig/${pc}.pc\" @ONLY)")
    install(FILES ${playerkit_packaging_out}/pkgconfig/${pc}.pc
            DESTINATION ${PLAYERKIT_INSTALL_PKGCONFIGDIR})
  endforeach()
endif()

# ---- the .deb ------------------------------------------------------------------

set(PLAYERKIT_PACKAGE_MAINTAINER "playerkit maintainers <maintainers@users.noreply.h-seed-11439134.example>"
    CACHE STRING "Maintainer field of the .deb")
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME playerkit)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "${PLAYERKIT_PACKAGE_MAINTAINER}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Player 1.5 robot device server, tools and client libraries")
set(CPACK_PACKAGE_DESCRIPTION
  "A from-scratch C++20 reimplementation of the Player 1.5 robot device server, wire-compatible \
with Player 1.5 clients: player-serve (the daemon), player-cat, player-send, player-log and \
amcl-offline, and the client libraries (C++ on Boost.Asio, and the C API of playercclient.h) \
with their headers, CMake package and pkg-config files.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # playerkit_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)   # runtime libraries (OpenCV, zlib, ...) from the binaries
# Only for building programs against the client libraries.
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "libboost-system-dev, nlohmann-json3-dev, pkgconf, cmake")
set(CPACK_STRIP_FILES ON)
include(CPack)
