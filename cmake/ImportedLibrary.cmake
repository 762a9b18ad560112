# bxdflab_import_library(TARGET INCLUDE_DIRS LIBRARIES): an imported target
# made from headers and libraries found with find_path / find_library, for
# the Debian packages whose own CMake files cannot be used (see
# OpenImageIOTarget.cmake and LibZipTarget.cmake for why).
function(bxdflab_import_library target include_dirs libraries)
  if(NOT TARGET ${target})
    add_library(${target} INTERFACE IMPORTED GLOBAL)
    set_target_properties(${target} PROPERTIES
      INTERFACE_INCLUDE_DIRECTORIES "${include_dirs}"
      INTERFACE_LINK_LIBRARIES "${libraries}")
  endif()
endfunction()
