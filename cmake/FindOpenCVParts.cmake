# Finds the five OpenCV parts zrender uses (core, imgproc, imgcodecs, videoio, highgui) from Debian's
# libopencv-*-dev packages, which ship no OpenCVConfig.cmake (only the libopencv-dev meta package
# does, and it pulls in about a hundred packages).
find_path(OpenCVParts_INCLUDE_DIR opencv2/core.hpp PATH_SUFFIXES opencv4)
set(_zr_parts core imgproc imgcodecs videoio highgui)
set(OpenCVParts_LIBRARIES)
foreach(_part IN LISTS _zr_parts)
  find_library(OpenCVParts_${_part}_LIBRARY NAMES opencv_${_part})
  list(APPEND OpenCVParts_LIBRARIES ${OpenCVParts_${_part}_LIBRARY})
  list(APPEND _zr_required OpenCVParts_${_part}_LIBRARY)
endforeach()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(OpenCVParts REQUIRED_VARS OpenCVParts_INCLUDE_DIR ${_zr_required})
# OpenCV::Headers: the headers alone, for the program's own code, which uses OpenCV's small
# vector and matrix types (cv::Vec, cv::Matx: templates, all in the headers) and links none of
# its libraries. OpenCV::Core: core and imgproc, linked by the program (cv::Mat is its image
# type; it draws with imgproc). OpenCV::Codecs:
# imgcodecs and videoio, whose Debian builds pull in some 200 shared libraries; only the codec
# plugin and the tests link them.
if(OpenCVParts_FOUND AND NOT TARGET OpenCV::Core)
  add_library(OpenCV::Headers INTERFACE IMPORTED)
  set_target_properties(OpenCV::Headers PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${OpenCVParts_INCLUDE_DIR}")
  add_library(OpenCV::Core INTERFACE IMPORTED)
  set_target_properties(OpenCV::Core PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${OpenCVParts_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${OpenCVParts_core_LIBRARY};${OpenCVParts_imgproc_LIBRARY}")
  add_library(OpenCV::Codecs INTERFACE IMPORTED)
  set_target_properties(OpenCV::Codecs PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${OpenCVParts_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${OpenCVParts_imgcodecs_LIBRARY};${OpenCVParts_videoio_LIBRARY};OpenCV::Core")
  # OpenCV::Highgui: the window of `zrender view` (Qt on Debian), for its plugin only.
  add_library(OpenCV::Highgui INTERFACE IMPORTED)
  set_target_properties(OpenCV::Highgui PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${OpenCVParts_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${OpenCVParts_highgui_LIBRARY};OpenCV::Core")
  # Core, imgproc and the codecs plus what src/ImageCodecs.cpp needs, for builds that compile
  # src/*.cpp themselves (the fuzzers).
  find_package(PNG REQUIRED)
  add_library(OpenCV::Parts INTERFACE IMPORTED)
  set_target_properties(OpenCV::Parts PROPERTIES
    INTERFACE_LINK_LIBRARIES "OpenCV::Codecs;PNG::PNG;${CMAKE_DL_LIBS}")
endif()
