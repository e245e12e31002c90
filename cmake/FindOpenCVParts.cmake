# Finds the three OpenCV modules swarm uses (core, imgproc, imgcodecs) and defines OpenCV::parts.
# Debian splits OpenCV into per-module -dev packages; only the libopencv-dev meta package (which
# drags in GUI, DNN, video, ...) ships OpenCVConfig.cmake, so we look the modules up directly.
find_path(OpenCVParts_INCLUDE_DIR opencv2/core.hpp PATH_SUFFIXES opencv4)
set(_swarm_opencv_libs)
foreach(module core imgproc imgcodecs)
  find_library(OpenCVParts_${module}_LIBRARY opencv_${module})
  list(APPEND _swarm_opencv_libs OpenCVParts_${module}_LIBRARY)
endforeach()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(OpenCVParts REQUIRED_VARS OpenCVParts_INCLUDE_DIR ${_swarm_opencv_libs})
if(OpenCVParts_FOUND AND NOT TARGET OpenCV::parts)
  add_library(OpenCV::parts INTERFACE IMPORTED)
  set_target_properties(OpenCV::parts PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${OpenCVParts_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${OpenCVParts_imgcodecs_LIBRARY};${OpenCVParts_imgproc_LIBRARY};${OpenCVParts_core_LIBRARY}")
endif()
