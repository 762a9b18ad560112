# Memory must not grow with samples per pixel: for every integrator, the peak
# resident memory of a 64-spp render stays within 10% of a 4-spp render of the
# same scene (the renderer shades in fixed-size chunks, whatever the spp), or
# within 4 MiB: rixrender now starts at about 15 MiB (OpenImageIO is loaded
# only to write the image), and worker threads starting up move that by a
# MiB or two from run to run. The bug this guards against grew by gigabytes.
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
  foreach(spp 4 64)
    execute_process(COMMAND ${RIXRENDER} --quiet --spp ${spp} -o ${OUT}/memory-${integrator}-${spp}.exr
                            --stats-json ${OUT}/memory-${integrator}-${spp}.json ${rib}
                    RESULT_VARIABLE status ERROR_VARIABLE errors)
    if(NOT status EQUAL 0)
      message(FATAL_ERROR "${integrator} at ${spp} spp failed: ${errors}")
    endif()
    file(READ ${OUT}/memory-${integrator}-${spp}.json json)
    string(JSON peak${spp} GET "${json}" peak_memory_mb)
  endforeach()
  string(REGEX REPLACE "\\..*" "" whole4 "${peak4}")
  math(EXPR limit "${whole4} * 110 / 100")
  math(EXPR floor "${whole4} + 4")
  if(limit LESS floor)
    set(limit ${floor})
  endif()
  message(STATUS "${integrator}: peak ${peak4} MiB at 4 spp, ${peak64} MiB at 64 spp (limit ${limit})")
  if(peak64 GREATER limit)
    message(FATAL_ERROR "${integrator}: peak memory grew with spp: ${peak4} MiB at 4 spp, ${peak64} MiB at 64 spp")
  endif()
endforeach()
