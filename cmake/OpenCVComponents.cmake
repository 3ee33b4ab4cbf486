# Debian ships OpenCV's CMake package files only in the libopencv-dev
# meta-package, which pulls in every OpenCV module (and Qt, VTK, ...). We
# install just the components we use, so find them by hand and give each an
# imported target named like upstream's: opencv_core, opencv_imgproc, ...
include_guard(GLOBAL)

find_path(PLAYERKIT_OPENCV_INCLUDE_DIR opencv2/core.hpp PATH_SUFFIXES opencv4 REQUIRED)

function(playerkit_find_opencv_component component)
  if(TARGET opencv_${component})
    return()
  endif()
  find_library(PLAYERKIT_OPENCV_${component}_LIBRARY opencv_${component} REQUIRED)
  add_library(opencv_${component} UNKNOWN IMPORTED GLOBAL)
  set_target_properties(opencv_${component} PROPERTIES
    IMPORTED_LOCATION "${PLAYERKIT_OPENCV_${component}_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${PLAYERKIT_OPENCV_INCLUDE_DIR}")
endfunction()
