# add_rix_plugin(<name> <source>... [TARGET <target>] [OUTPUT_DIR <dir>])
#
# Builds the Rix plugin <name> as the shared object <name>.so, which the
# renderer finds by that name (`Bxdf "<name>" ...` loads <name>.so).
#   TARGET      the CMake target name (default: <name>); set it when two
#               plugins share a name, e.g. a starter and its solution.
#   OUTPUT_DIR  where the .so goes (default: ${RIX_PLUGIN_OUTPUT_DIR}, or
#               ${CMAKE_BINARY_DIR}/plugins when that is not set).
# The plugin sees only the course API headers; symbols are hidden except the
# C entry points the API marks PRMANEXPORT.
set(RIX_API_INCLUDE_DIR ${CMAKE_CURRENT_LIST_DIR}/../renderer/include/rix CACHE PATH "Rix API headers")

function(add_rix_plugin name)
  cmake_parse_arguments(PLUGIN "" "TARGET;OUTPUT_DIR" "" ${ARGN})
  set(sources ${PLUGIN_UNPARSED_ARGUMENTS})
  if(NOT sources)
    message(FATAL_ERROR "add_rix_plugin(${name}): no source files given")
  endif()
  set(target ${name})
  if(PLUGIN_TARGET)
    set(target ${PLUGIN_TARGET})
  endif()
  set(output_dir ${CMAKE_BINARY_DIR}/plugins)
  if(RIX_PLUGIN_OUTPUT_DIR)
    set(output_dir ${RIX_PLUGIN_OUTPUT_DIR})
  endif()
  if(PLUGIN_OUTPUT_DIR)
    set(output_dir ${PLUGIN_OUTPUT_DIR})
  endif()

  add_library(${target} MODULE ${sources})
  target_include_directories(${target} PRIVATE ${RIX_API_INCLUDE_DIR})
  set_target_properties(${target} PROPERTIES
    PREFIX ""
    OUTPUT_NAME ${name}
    SUFFIX ".so"
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON
    LIBRARY_OUTPUT_DIRECTORY ${output_dir})
  target_compile_features(${target} PRIVATE cxx_std_17)
  if(TARGET bxdflab_warnings)
    target_link_libraries(${target} PRIVATE bxdflab_warnings)
  else()
    target_compile_options(${target} PRIVATE -Wall -Wextra)
  endif()
  # Full debug information for every API class the plugin uses (the compilers
  # otherwise describe a class only where its vtable is emitted, which is
  # inside the renderer): in gdb, `print shadingCtx->numPts` then works.
  target_compile_options(${target} PRIVATE $<$<CXX_COMPILER_ID:GNU>:-femit-class-debug-always>
                                           $<$<CXX_COMPILER_ID:Clang>:-fstandalone-debug>)
  # An unresolved symbol should fail the build, not the render.
  target_link_options(${target} PRIVATE -Wl,--no-undefined)
endfunction()
