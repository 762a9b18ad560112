# Defines OpenImageIO::OpenImageIO from the installed headers and libraries.
#
# Debian 12's own OpenImageIOConfig.cmake cannot be used: its target lists
# /usr/include/opencv4 (absent unless OpenCV's headers are installed) and it
# pulls in Imath's Python targets, whose libraries the -dev packages lack.
include(${CMAKE_CURRENT_LIST_DIR}/ImportedLibrary.cmake)
find_path(OIIO_INCLUDE_DIR OpenImageIO/imagebuf.h REQUIRED)
find_path(IMATH_INCLUDE_DIR ImathVec.h PATH_SUFFIXES Imath REQUIRED)
find_library(OIIO_LIBRARY OpenImageIO REQUIRED)
find_library(OIIO_UTIL_LIBRARY OpenImageIO_Util REQUIRED)
bxdflab_import_library(OpenImageIO::OpenImageIO "${OIIO_INCLUDE_DIR};${IMATH_INCLUDE_DIR}"
                       "${OIIO_LIBRARY};${OIIO_UTIL_LIBRARY}")
message(STATUS "OpenImageIO: ${OIIO_LIBRARY}")
