# Writes page_assets.cpp: the live page's files as string literals, so the
# executable serves them the same from the build tree and installed.
#   cmake -DPAGE_DIR=.../page -DOUTPUT=.../page_assets.cpp -P embed_page.cmake
# Each file: its name in PAGE_DIR, the path it is served at, its media type
# (text, served as UTF-8).
set(assets
  index.html /        text/html
  view.js    /view.js text/javascript)

set(code "// Generated from tools/player-view/page by embed_page.cmake: do not edit.\n")
string(APPEND code "#include \"page_server.hpp\"\n\nnamespace playerkit::player_view {\n\n")
string(APPEND code "const std::vector<PageAsset>& page_assets() {\n  static const std::vector<PageAsset> assets{\n")
list(LENGTH assets count)
math(EXPR last "${count} - 1")
foreach(i RANGE 0 ${last} 3)
  math(EXPR j "${i} + 1")
  math(EXPR k "${i} + 2")
  list(GET assets ${i} name)
  list(GET assets ${j} path)
  list(GET assets ${k} type)
  file(READ "${PAGE_DIR}/${name}" body)
  # A raw string literal ends at the first )PAGE": a file holding it cannot be embedded this way.
  string(FIND "${body}" ")PAGE\"" clash)
  if(NOT clash EQUAL -1)
    message(FATAL_ERROR "${PAGE_DIR}/${name} contains )PAGE\", which ends the literal it is embedded in")
  endif()
  string(APPEND code "      {\"${path}\", \"${type}; charset=utf-8\", R\"PAGE(${body})PAGE\"},\n")
endforeach()
string(APPEND code "  };\n  return assets;\n}\n\n}  // namespace playerkit::player_view\n")
# Rewritten only when it changes, so an unchanged page does not recompile.
if(EXISTS "${OUTPUT}")
  file(READ "${OUTPUT}" old)
  if(old STREQUAL code)
    return()
  endif()
endif()
file(WRITE "${OUTPUT}" "${code}")
