# Defines libzip::zip from the installed header and library.
#
# Debian 12's own libzip-config.cmake cannot be used: it also imports the
# zipcmp, zipmerge and ziptool programs, which live in other packages, and
# stops the configure step when they are absent.
find_path(LIBZIP_INCLUDE_DIR zip.h REQUIRED)
find_library(LIBZIP_LIBRARY zip REQUIRED)
if(NOT TARGET libzip::zip)
  add_library(libzip::zip INTERFACE IMPORTED)
  set_target_properties(libzip::zip PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${LIBZIP_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${LIBZIP_LIBRARY}")
endif()
