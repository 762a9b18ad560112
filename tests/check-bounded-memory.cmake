# Memory must not grow with samples per pixel: for every integrator, the peak
# resident memory of a 64-spp render stays within 10% of a 4-spp render of the
# same scene (the renderer shades in fixed-size chunks, whatever the spp), or
# within 16 MiB, and a 256-spp render within 10% (or 4 MiB) of the 64-spp one.
# The absolute allowances are there because rixrender now starts at about
# 15 MiB (OpenImageIO is loaded only to write the image): the peak is then the
# largest chunk any worker met, which a longer render samples more of (the
# path tracer measured 16-20 MiB at 4 spp, 22-23 MiB at 64, 22-23 MiB at 256
# and 1024). The bug this guards against grew by gigabytes.
# Usage: cmake -DRIXRENDER=... -DOUT=dir -DINTEGRATORS="A;B" -P check-bounded-memory.cmake
file(MAKE_DIRECTORY ${OUT})
foreach(integrator ${INTEGRATORS})
  set(rib ${OUT}/memory-${integrator}.rib)
  file(WRITE ${rib} "Format 200 150 1
Projection \"perspective\" \"fov\" [40]
Integrator \"${integrator}\" \"i\"
WorldBegin
  AttributeBegin
    Translate 0 2 3
    Scale 0.6 0.6 0.6
    Light \"PxrSphereLight\" \"key\" \"float intensity\" [20]
  AttributeEnd
  Bxdf \"plastic\" \"p\" \"color diffuseColor\" [0.5 0.5 0.5]
  AttributeBegin
    Translate 0 0 4
    Sphere 1 -1 1 360
  AttributeEnd
  Bxdf \"diffuse\" \"floor\"
  Polygon \"P\" [-5 -1 0  5 -1 0  5 -1 9  -5 -1 9]
WorldEnd
")
  foreach(spp 4 64 256)
    execute_process(COMMAND ${RIXRENDER} --quiet --spp ${spp} -o ${OUT}/memory-${integrator}-${spp}.exr
                            --stats-json ${OUT}/memory-${integrator}-${spp}.json ${rib}
                    RESULT_VARIABLE status ERROR_VARIABLE errors)
    if(NOT status EQUAL 0)
      message(FATAL_ERROR "${integrator} at ${spp} spp failed: ${errors}")
    endif()
    file(READ ${OUT}/memory-${integrator}-${spp}.json json)
    string(JSON peak${spp} GET "${json}" peak_memory_mb)
  endforeach()
  # limit = max(peak * 110 %, peak + allowance), in whole MiB.
  function(bounded_memory_limit peak allowance out)
    string(REGEX REPLACE "\\..*" "" whole "${peak}")
    math(EXPR relative "${whole} * 110 / 100 + 1")
    math(EXPR absolute "${whole} + ${allowance}")
    if(relative GREATER absolute)
      set(${out} ${relative} PARENT_SCOPE)
    else()
      set(${out} ${absolute} PARENT_SCOPE)
    endif()
  endfunction()
  bounded_memory_limit(${peak4} 16 limit64)
  bounded_memory_limit(${peak64} 4 limit256)
  message(STATUS "${integrator}: peak ${peak4} MiB at 4 spp, ${peak64} at 64 (limit ${limit64}), ${peak256} at 256 (limit ${limit256})")
  if(peak64 GREATER limit64 OR peak256 GREATER limit256)
    message(FATAL_ERROR "${integrator}: peak memory grew with spp: ${peak4} MiB at 4 spp, ${peak64} at 64, ${peak256} at 256")
  endif()
endforeach()
