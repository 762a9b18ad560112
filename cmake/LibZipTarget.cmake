# Defines libzip::zip from the installed header and library.
#
# Debian 12's own libzip-config.cmake cannot be used: it also imports the
# zipcmp, zipmerge and ziptool programs, which live in other packages, and
# stops the configure step when they are absent.
include(${CMAKE_CURRENT_LIST_DIR}/ImportedLibrary.cmake)
find_path(LIBZIP_INCLUDE_DIR zip.h REQUIRED)
find_library(LIBZIP_LIBRARY zip REQUIRED)
bxdflab_import_library(libzip::zip "${LIBZIP_INCLUDE_DIR}" "${LIBZIP_LIBRARY}")
