# rixrender's command-line contract: each bad input is a located message and
# exit status 1, never a crash (a crash would not print the expected text).
set(CLI_OUT ${CMAKE_CURRENT_BINARY_DIR}/cli)
file(MAKE_DIRECTORY ${CLI_OUT})
set(BAD ${CMAKE_CURRENT_SOURCE_DIR}/bad-input)

# Bad input exercises the error paths: they run in the sanitizer build too.
function(add_cli_failure name expected)
  add_test(NAME cli.${name}
           COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/expect-failure.sh "${expected}" $<TARGET_FILE:rixrender> --quiet ${ARGN}
           WORKING_DIRECTORY ${CLI_OUT})
  set_tests_properties(cli.${name} PROPERTIES LABELS "cli;sanitize")
endfunction()

add_cli_failure(malformed_rib "bad-input/unterminated.rib:4:29: unterminated string" ${BAD}/unterminated.rib -o out.exr)
add_cli_failure(unknown_plugin "Bxdf plugin \"notaplugin\" not found" ${BAD}/unknown-plugin.rib -o out.exr)
add_cli_failure(wrong_param_type "wrong-type.rib:[0-9]+:[0-9]+: Bxdf \"diffuse\" parameter \"diffuseColor\" is a color" ${BAD}/wrong-type.rib -o out.exr)
add_cli_failure(missing_image_strict "lightColorMap \".*no-such-sky.exr\" does not exist" ${BAD}/missing-image.rib --strict -o out.exr)
# Without --strict a missing file is a located warning and the render goes on (RenderMan's way).
add_test(NAME cli.missing_image_warns COMMAND rixrender --quiet --spp 1 -o missing-image.exr ${BAD}/missing-image.rib
         WORKING_DIRECTORY ${CLI_OUT})
set_tests_properties(cli.missing_image_warns PROPERTIES LABELS "cli;sanitize" PASS_REGULAR_EXPRESSION
  "missing-image.rib:4:3: PxrDomeLight: lightColorMap .*no-such-sky.exr\" does not exist .*rendering without it.*wrote missing-image.exr")
add_cli_failure(unwritable_output "folder \"/nonexistent-folder\" does not exist" ${PROJECT_SOURCE_DIR}/scenes/ch06/diffuse.rib -o /nonexistent-folder/x.exr)
add_cli_failure(output_is_a_folder "cannot write \".*bad-input\": it is a folder" ${PROJECT_SOURCE_DIR}/scenes/ch06/diffuse.rib -o ${BAD})
add_cli_failure(stats_is_a_folder "cannot write \".*bad-input\": it is a folder" ${PROJECT_SOURCE_DIR}/scenes/ch06/diffuse.rib -o out.exr --stats-json ${BAD})
add_cli_failure(zero_size_image "zero-size.rib:3:1: Format: resolution must be whole numbers of at least 1 pixel" ${BAD}/zero-size.rib -o out.exr)
add_cli_failure(nan_transform "nan-transform.rib:5:3: Scale: .*finite" ${BAD}/nan-transform.rib -o out.exr)
add_cli_failure(missing_scene "cannot open RIB file" ${BAD}/does-not-exist.rib -o out.exr)
# A plugin that crashes takes rixrender with it, but first rixrender names the plugin and the
# offset of the crash in it, and still dies of the signal (status 139: 128 + SIGSEGV). Not in
# the sanitizer build, whose own handler reports crashes there.
add_test(NAME cli.crashing_plugin
         COMMAND env EXPECT_STATUS=139 sh ${CMAKE_CURRENT_SOURCE_DIR}/expect-failure.sh
                 "rixrender: crashed \\(SIGSEGV\\) in the plugin .*/plugins/tests/probe_segfault.so at offsets? 0x[0-9a-f]+"
                 $<TARGET_FILE:rixrender> --quiet --spp 1 --plugin-path ${CMAKE_BINARY_DIR}/plugins/tests
                 ${BAD}/crashing-plugin.rib -o crashing-plugin.exr
         WORKING_DIRECTORY ${CLI_OUT})
# A plugin that jumps to an address in no loaded file (a function pointer or a return address
# written over): rixrender names the plugin that made the jump and says what it most often means.
add_test(NAME cli.plugin_jumps_out_of_code
         COMMAND env EXPECT_STATUS=139 sh ${CMAKE_CURRENT_SOURCE_DIR}/expect-failure.sh
                 "rixrender: crashed \\(SIGSEGV\\) in the plugin .*/probe_wild_jump.so at offsets? 0x[0-9a-f]+, jumping to an address that is no code: a return address or function pointer was written over"
                 $<TARGET_FILE:rixrender> --quiet --spp 1 --plugin-path ${CMAKE_BINARY_DIR}/plugins/tests
                 ${BAD}/wild-jump-plugin.rib -o wild-jump-plugin.exr
         WORKING_DIRECTORY ${CLI_OUT})
# A plugin that overflows the stack of a rendering thread (each thread has a stack of its own
# for the report).
add_test(NAME cli.plugin_overflows_its_stack
         COMMAND env EXPECT_STATUS=139 sh ${CMAKE_CURRENT_SOURCE_DIR}/expect-failure.sh
                 "rixrender: crashed \\(SIGSEGV\\) in the plugin .*/probe_recurses.so at offsets 0x[0-9a-f]+ [0-9a-fx ]+, having run out of stack"
                 $<TARGET_FILE:rixrender> --quiet --spp 16 --threads 2 --plugin-path ${CMAKE_BINARY_DIR}/plugins/tests
                 ${BAD}/recursing-plugin.rib -o recursing-plugin.exr
         WORKING_DIRECTORY ${CLI_OUT})
set_tests_properties(cli.crashing_plugin cli.plugin_jumps_out_of_code cli.plugin_overflows_its_stack
                     PROPERTIES LABELS cli)
add_cli_failure(unknown_format "unknown image format \".bmpx\"" ${PROJECT_SOURCE_DIR}/scenes/ch06/diffuse.rib --spp 1 -o out.bmpx)
add_cli_failure(corrupt_image_strict "corrupt-image.rib:4:5: PxrDomeLight: cannot read lightColorMap .*corrupt-sky.exr" ${BAD}/corrupt-image.rib --strict -o out.exr)
# An image that cannot be decoded is a missing one (a warning without --strict); a Git LFS
# pointer or an empty file left where the image should be is named as one.
add_test(NAME cli.corrupt_image_warns COMMAND rixrender --quiet --spp 1 -o corrupt-image.exr ${BAD}/corrupt-image.rib
         WORKING_DIRECTORY ${CLI_OUT})
set_tests_properties(cli.corrupt_image_warns PROPERTIES LABELS "cli;sanitize" PASS_REGULAR_EXPRESSION
  "corrupt-image.rib:4:5: PxrDomeLight: cannot read lightColorMap .*corrupt-sky.exr.*rendering without it.*wrote corrupt-image.exr")
add_cli_failure(lfs_pointer_image "lfs-pointer.rib:4:5: PxrDomeLight: cannot read lightColorMap .*lfs-sky.exr\": it is a Git LFS pointer, not the image" ${BAD}/lfs-pointer.rib --strict -o out.exr)
add_cli_failure(empty_image "empty-image.rib:4:5: PxrDomeLight: cannot read lightColorMap .*empty-sky.exr\": it is empty \\(0 bytes\\)" ${BAD}/empty-image.rib --strict -o out.exr)
add_test(NAME cli.lfs_pointer_texture COMMAND rixrender --quiet --spp 1 -o lfs-texture.exr ${BAD}/lfs-pointer-texture.rib
         WORKING_DIRECTORY ${CLI_OUT})
set_tests_properties(cli.lfs_pointer_texture PROPERTIES LABELS "cli;sanitize" PASS_REGULAR_EXPRESSION
  "lfs-pointer-texture.rib:3:30: Pattern \"PxrTexture\" \"tex\": texture \"lfs-sky.exr\" cannot be read \\(it is a Git LFS pointer, not the image")
# An empty texture file is named at the RIB line that names it, and is an error under --strict.
add_cli_failure(empty_texture "empty-texture.rib:3:30: Pattern \"PxrTexture\" \"tex\": texture \"empty-sky.exr\" cannot be read \\(it is empty \\(0 bytes\\)"
                ${BAD}/empty-texture.rib --strict -o out.exr)
add_cli_failure(scene_is_a_folder "\".*bad-input\" is a folder, not a RIB file" ${BAD} -o out.exr)
add_cli_failure(no_world "no-world.rib: there is no WorldBegin" ${BAD}/no-world.rib -o out.exr)
# A file that only makes textures is a pipeline's texture step: it writes them, as RenderMan does, and
# the next step's scene, which names a texture without making it, reads the file written.
set(MADE ${CLI_OUT}/made-textures)
file(MAKE_DIRECTORY ${MADE})
add_test(NAME cli.make_textures_only COMMAND rixrender --quiet ${CMAKE_CURRENT_SOURCE_DIR}/make-textures/make-sky.rib
         WORKING_DIRECTORY ${MADE})
set_tests_properties(cli.make_textures_only PROPERTIES LABELS "cli;sanitize" FIXTURES_SETUP made_textures
  PASS_REGULAR_EXPRESSION
  "wrote sky-clamped.tex \\(a texture made from .*sky.exr\\).*wrote sky.tex \\(a latitude-longitude environment map made from")
add_test(NAME cli.scene_reads_made_texture
         COMMAND rixrender --quiet --strict --spp 1 -o uses-sky.exr
                 ${CMAKE_CURRENT_SOURCE_DIR}/make-textures/uses-sky.rib
         WORKING_DIRECTORY ${MADE})
set_tests_properties(cli.scene_reads_made_texture PROPERTIES LABELS "cli;sanitize" FIXTURES_REQUIRED made_textures)
# Usage errors exit with status 2.
function(add_cli_usage_error name expected)
  add_test(NAME cli.${name}
           COMMAND env EXPECT_STATUS=2 sh ${CMAKE_CURRENT_SOURCE_DIR}/expect-failure.sh "${expected}" $<TARGET_FILE:rixrender> --quiet ${ARGN}
           WORKING_DIRECTORY ${CLI_OUT})
  set_tests_properties(cli.${name} PROPERTIES LABELS "cli;sanitize")
endfunction()
add_cli_usage_error(zero_spp "--spp: Value 0 not in range" ${PROJECT_SOURCE_DIR}/scenes/ch06/diffuse.rib --spp 0 -o out.exr)
add_cli_usage_error(zero_threads "--threads: Value 0 not in range" ${PROJECT_SOURCE_DIR}/scenes/ch06/diffuse.rib --threads 0 -o out.exr)
add_cli_usage_error(unknown_option "--fast" ${PROJECT_SOURCE_DIR}/scenes/ch06/diffuse.rib --fast)
add_cli_usage_error(no_scene "scene is required" -o out.exr)
add_cli_failure(binary_garbage "garbage.bin:1:1: expected a request name .*found string \"\\\\x00\\\\xffRIB" ${BAD}/garbage.bin -o out.exr)
# A good render writes its image and stats, and the stats say what happened.
add_test(NAME cli.renders_chapter6 COMMAND rixrender --quiet --spp 2 -o ch06.png --stats-json ch06.json
         --variance ch06-variance.exr ${PROJECT_SOURCE_DIR}/scenes/ch06/diffuse.rib)
set_tests_properties(cli.renders_chapter6 PROPERTIES WORKING_DIRECTORY ${CLI_OUT} PASS_REGULAR_EXPRESSION "wrote ch06.png")
add_test(NAME cli.stats_schema COMMAND ${CMAKE_COMMAND}
         -DSTATS=${CLI_OUT}/ch06.json -P ${CMAKE_CURRENT_SOURCE_DIR}/check-stats.cmake)
set_tests_properties(cli.stats_schema PROPERTIES DEPENDS cli.renders_chapter6)

# Determinism end to end (command line, film, image files): the same scene, seed
# and spp give the same pixels and variances with 1 or 2 threads and on a second run.
set(PLASTIC ${PROJECT_SOURCE_DIR}/scenes/ch06/plastic.rib)
add_test(NAME cli.same_pixels_any_thread_count
         COMMAND sh -c "for run in t1:1 t2:2 again:2; do name=\${run%%:*}; threads=\${run##*:}; $<TARGET_FILE:rixrender> --quiet --spp 2 --seed 5 --threads \$threads -o det-\$name.exr --variance det-\$name-var.exr ${PLASTIC} || exit 1; done; for other in t2 again; do $<TARGET_FILE:rixdiff> det-t1.exr det-\$other.exr --max-rmse 0 || exit 1; $<TARGET_FILE:rixdiff> det-t1-var.exr det-\$other-var.exr --max-rmse 0 || exit 1; done; echo same pixels"
         WORKING_DIRECTORY ${CLI_OUT})
set_tests_properties(cli.same_pixels_any_thread_count PROPERTIES PASS_REGULAR_EXPRESSION "same pixels" FAIL_REGULAR_EXPRESSION "FAIL")

# A framebuffer display writes a file named after the display, and says where.
add_test(NAME cli.framebuffer_display COMMAND rixrender --quiet --spp 1 ${CMAKE_CURRENT_SOURCE_DIR}/scenes/framebuffer.rib)
set_tests_properties(cli.framebuffer_display PROPERTIES WORKING_DIRECTORY ${CLI_OUT}
  PASS_REGULAR_EXPRESSION "framebuffer; the image was written to framebuffer-test.exr")
# TIFF output keeps linear floats.
# A shadow-map pass: its depth map goes to a file the renderer can write, with a message saying where (it
# used to fail once the render was done), and holds depth alone.
add_test(NAME cli.shadow_map_pass
         COMMAND sh -c "$<TARGET_FILE:rixrender> --quiet --spp 1 ${CMAKE_CURRENT_SOURCE_DIR}/scenes/shadow-pass.rib && oiiotool --info -v shadow-pass-test.z.exr")
set_tests_properties(cli.shadow_map_pass PROPERTIES WORKING_DIRECTORY ${CLI_OUT}
  PASS_REGULAR_EXPRESSION "does not write; the image was written to shadow-pass-test.z.exr.*1 channel.*channel list: Z\n")
# Further displays ("+name"): with -o, each goes beside the image, named after both, with the channels its
# mode asks for; a further framebuffer is skipped with a warning.
add_test(NAME cli.further_displays
         COMMAND sh -c "mkdir -p displays && $<TARGET_FILE:rixrender> --quiet --spp 1 -o displays/beauty.exr ${CMAKE_CURRENT_SOURCE_DIR}/scenes/displays.rib && oiiotool --info -v displays/beauty.normal.exr displays/beauty.depth.tif")
set_tests_properties(cli.further_displays PROPERTIES WORKING_DIRECTORY ${CLI_OUT}
  PASS_REGULAR_EXPRESSION "displays.rib:7:1: Display \"\\+preview\" \"framebuffer\" would show a further image in a window.*wrote displays/beauty.exr\nrixrender: wrote displays/beauty.normal.exr\nrixrender: wrote displays/beauty.depth.tif.*channel list: N.x, N.y, N.z.*beauty.depth.tif : +16 x +16, 1 channel, float tiff")
# Every image a frame writes is checked before it renders: a further display that cannot be written stops
# rixrender before the main image is written, not after.
add_test(NAME cli.further_display_unwritable
         COMMAND sh -c "mkdir -p blocked/beauty.normal.exr && $<TARGET_FILE:rixrender> --quiet --spp 1 -o blocked/beauty.exr ${CMAKE_CURRENT_SOURCE_DIR}/scenes/displays.rib; echo exit $? && ls blocked")
set_tests_properties(cli.further_display_unwritable PROPERTIES WORKING_DIRECTORY ${CLI_OUT}
  PASS_REGULAR_EXPRESSION "cannot write \"blocked/beauty.normal.exr\": it is a folder.*exit 1\nbeauty.normal.exr\n$"
  FAIL_REGULAR_EXPRESSION "wrote blocked")
# Procedural "RunProgram" runs its program only with --run-programs: the scene's two spheres are the
# program's, and the stats say the image is lit; without the flag it says how to run it.
add_test(NAME cli.run_programs
         COMMAND sh -c "$<TARGET_FILE:rixrender> --quiet --spp 1 --run-programs -o balls.exr --stats-json balls.json ${CMAKE_CURRENT_SOURCE_DIR}/scenes/run-program/balls.rib && grep -o '\"lit_fraction\": 0\\.[0-9]*' balls.json; $<TARGET_FILE:rixrender> --quiet --spp 1 -o balls-skipped.exr ${CMAKE_CURRENT_SOURCE_DIR}/scenes/run-program/balls.rib")
set_tests_properties(cli.run_programs PROPERTIES WORKING_DIRECTORY ${CLI_OUT} LABELS "cli;sanitize"
  PASS_REGULAR_EXPRESSION "wrote balls.exr\n\"lit_fraction\": 0\\.[0-9]*[1-9].*balls.rib:8:3: Procedural \"RunProgram\" \\(\"ball.sh\"\\): a scene's programs run only when asked for \\(rixrender --run-programs\\)")
add_test(NAME cli.tiff_output COMMAND rixrender --quiet --spp 1 -o ch06.tif ${PROJECT_SOURCE_DIR}/scenes/ch06/diffuse.rib)
set_tests_properties(cli.tiff_output PROPERTIES WORKING_DIRECTORY ${CLI_OUT} PASS_REGULAR_EXPRESSION "wrote ch06.tif")

# Every starter builds, loads and renders its chapter's scene safely: no crash,
# no non-finite values, and (until the TODOs are done) a message saying which
# body is missing.
foreach(pair emissive:ch06/emissive diffuse:ch06/diffuse specular:ch06/specular plastic:ch06/plastic
             ward:ch08/ward_teapot finishedwood:ch08/wood buggydiffuse:ch07/buggydiffuse ggx:ch09/ggx_spheres
             mydirect:ch11/mis mypath:ch11/box)
  string(REPLACE ":" ";" parts ${pair})
  list(GET parts 0 plugin)
  list(GET parts 1 scene)
  add_test(NAME starter.${plugin}.renders_safely
           COMMAND rixrender --quiet --spp 1 --plugin-path ${CMAKE_BINARY_DIR}/plugins/starter
                   -o starter-${plugin}.exr ${PROJECT_SOURCE_DIR}/scenes/${scene}.rib
           WORKING_DIRECTORY ${CLI_OUT})
  if(plugin STREQUAL "buggydiffuse")
    set(expected "wrote starter-buggydiffuse.exr")
  else()
    set(expected "TODO: .* is not implemented yet")
  endif()
  set_tests_properties(starter.${plugin}.renders_safely PROPERTIES
    PASS_REGULAR_EXPRESSION "${expected}" FAIL_REGULAR_EXPRESSION "non-finite;error")
endforeach()

# The visual tools.
add_test(NAME tools.rixdiff_identical COMMAND rixdiff ch06.tif ch06.tif --max-rmse 0 --heatmap same.png WORKING_DIRECTORY ${CLI_OUT})
set_tests_properties(tools.rixdiff_identical PROPERTIES DEPENDS cli.tiff_output PASS_REGULAR_EXPRESSION "RMSE    0\n")
add_test(NAME tools.rixdiff_threshold
         COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/expect-failure.sh "FAIL: relMSE above" $<TARGET_FILE:rixdiff>
                 ch06.tif starter-diffuse.exr --max-relmse 0.01
         WORKING_DIRECTORY ${CLI_OUT})
set_tests_properties(tools.rixdiff_threshold PROPERTIES DEPENDS "cli.tiff_output;starter.diffuse.renders_safely")
add_test(NAME tools.rixwarp_solution_passes COMMAND rixwarp specular --params "\"float gloss\" [40] \"int samplingMode\" [1]"
         --theta 30 --samples 100000 --out warp-specular.png WORKING_DIRECTORY ${CLI_OUT})
set_tests_properties(tools.rixwarp_solution_passes PROPERTIES PASS_REGULAR_EXPRESSION "-> PASS")
add_test(NAME tools.rixwarp_finds_the_planted_bug
         COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/expect-failure.sh "-> FAIL" $<TARGET_FILE:rixwarp> buggydiffuse
                 --plugin-path ${CMAKE_BINARY_DIR}/plugins/starter --samples 100000 --out warp-buggy.png
         WORKING_DIRECTORY ${CLI_OUT})
# Bad input is status 1; the two tools whose status 1 is a verdict (rixdiff, rixwarp) say it with 2, as diff does.
add_test(NAME tools.rixlobe_missing_plugin
         COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/expect-failure.sh "no-such-plugin" $<TARGET_FILE:rixlobe> no-such-plugin
         WORKING_DIRECTORY ${CLI_OUT})
add_test(NAME tools.rixwarp_missing_plugin
         COMMAND env EXPECT_STATUS=2 sh ${CMAKE_CURRENT_SOURCE_DIR}/expect-failure.sh "no-such-plugin"
                 $<TARGET_FILE:rixwarp> no-such-plugin WORKING_DIRECTORY ${CLI_OUT})
add_test(NAME tools.rixdiff_missing_image
         COMMAND env EXPECT_STATUS=2 sh ${CMAKE_CURRENT_SOURCE_DIR}/expect-failure.sh "no-such-image"
                 $<TARGET_FILE:rixdiff> no-such-image.exr no-such-image.exr WORKING_DIRECTORY ${CLI_OUT})
add_test(NAME tools.rixlobe COMMAND rixlobe ward --params "\"float uRoughness\" [0.3] \"float vRoughness\" [0.1]"
         --theta 40 --polar lobe-polar.png --sphere lobe-sphere.png WORKING_DIRECTORY ${CLI_OUT})
set_tests_properties(tools.rixlobe PROPERTIES PASS_REGULAR_EXPRESSION "polar slice: largest W = [0-9.]+.*spherical lobe")

# The convergence tool on a tiny study: CSV, table and plots.
add_test(NAME tools.rixconverge
         COMMAND rixconverge ${PROJECT_SOURCE_DIR}/scenes/ch04/estimators.rib --res 40x30 --spp 1,2,4 --repeats 1
                 --reference-spp 16 --out converge-test
                 --variant "cosine=Bxdf \"diffuse\" \"white\" \"int samplingMode\" [0]"
                 --variant "uniform=Bxdf \"diffuse\" \"white\" \"int samplingMode\" [1]"
         WORKING_DIRECTORY ${CLI_OUT})
set_tests_properties(tools.rixconverge PROPERTIES
  PASS_REGULAR_EXPRESSION "cosine: slope -?[0-9.]+.*uniform: slope -?[0-9.]+.*wrote converge-test/convergence.csv"
  FAIL_REGULAR_EXPRESSION "plotting failed")

# rixrender maps OpenImageIO only when a scene reads or writes an image: --help
# (and the grader's renders, which report pixels over a descriptor) start without it.
# (The sanitizer build links OpenImageIO in: see renderer/CMakeLists.txt.)
if(NOT BXDFLAB_SANITIZE)
  add_test(NAME cli.rixrender_starts_without_openimageio
           COMMAND sh -c "LD_DEBUG=libs \"$0\" --help 2>&1" $<TARGET_FILE:rixrender>)
  set_tests_properties(cli.rixrender_starts_without_openimageio PROPERTIES
    PASS_REGULAR_EXPRESSION "Usage:" FAIL_REGULAR_EXPRESSION "libOpenImageIO")
endif()
add_test(NAME cli.rixrender_loads_openimageio_to_write
         COMMAND sh -c "rm -f \"$1\"; log=$(LD_DEBUG=libs \"$0\" --quiet --spp 1 --resolution-scale 0.1 -o \"$1\" \"$2\" 2>&1); echo \"$log\" | grep -q 'calling init: .*/libOpenImageIO.so' && test -s \"$1\" && echo 'loaded OpenImageIO and wrote the image'"
                 $<TARGET_FILE:rixrender> ${CLI_OUT}/oiio-module.png ${PROJECT_SOURCE_DIR}/scenes/ch06/diffuse.rib)
set_tests_properties(cli.rixrender_loads_openimageio_to_write PROPERTIES
  PASS_REGULAR_EXPRESSION "loaded OpenImageIO and wrote the image")

# The renderer's folders include one another only along the data flow (docs/architecture.md).
add_test(NAME architecture.includes_follow_the_data_flow
         COMMAND ${BXDFLAB_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_include_direction.py ${PROJECT_SOURCE_DIR})
set_tests_properties(architecture.includes_follow_the_data_flow PROPERTIES
  PASS_REGULAR_EXPRESSION "files checked, 0 includes against the data flow")

# tools/python/prman.py: course scripts' Ri calls write the RIB RenderMan's prman module writes, and
# Begin("__render") renders it.
add_test(NAME tools.prman_module
         COMMAND ${BXDFLAB_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test_prman_module.py $<TARGET_FILE:rixrender>)
set_tests_properties(tools.prman_module PROPERTIES LABELS "cli")

# The README names every RIB request the scene builder handles, and no other.
add_test(NAME readme.lists_every_rib_request
         COMMAND ${BXDFLAB_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_readme_requests.py ${PROJECT_SOURCE_DIR})
set_tests_properties(readme.lists_every_rib_request PROPERTIES PASS_REGULAR_EXPRESSION "requests handled, 0 mismatches")

# Chapter 7's gdb session prints the shading context and the directions.
add_test(NAME chapters.ch07_gdb_walkthrough
         COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/check_gdb_walkthrough.sh ${PROJECT_SOURCE_DIR} $<TARGET_FILE:rixrender>
                 ${CMAKE_CURRENT_BINARY_DIR}/gdb-walkthrough)
set_tests_properties(chapters.ch07_gdb_walkthrough PROPERTIES
  PASS_REGULAR_EXPRESSION "\\$1 = [1-9][0-9]*\n\\$2 = {<RtFloat3> = {x = "
  FAIL_REGULAR_EXPRESSION "There is no member|incomplete type")

# The plugin ABI version moves with the Rix headers (stale plugin builds are refused, not run).
add_test(NAME api.version_tracks_the_headers COMMAND ${BXDFLAB_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_api_version.py ${PROJECT_SOURCE_DIR})
set_tests_properties(api.version_tracks_the_headers PROPERTIES PASS_REGULAR_EXPRESSION "the headers are as recorded")

# What every plugin source includes stays light to compile (RixBxdf.h with <mutex>
# and <unordered_set> was 53,000 lines preprocessed; it is about 42,000 without).
add_test(NAME api.headers_stay_light COMMAND ${BXDFLAB_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_header_weight.py
                                             ${CMAKE_CXX_COMPILER} ${PROJECT_SOURCE_DIR}/renderer/include/rix 45000)

# Every command the chapters show runs, and every figure they link exists.
add_test(NAME chapters.commands_and_figures COMMAND ${BXDFLAB_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_chapters.py ${PROJECT_SOURCE_DIR})
set_tests_properties(chapters.commands_and_figures PROPERTIES PASS_REGULAR_EXPRESSION "command blocks run; 0 problems" RUN_SERIAL TRUE)

# Memory stays bounded at any spp, for every integrator.
add_test(NAME cli.memory_bounded_at_any_spp
         COMMAND ${CMAKE_COMMAND} -DRIXRENDER=$<TARGET_FILE:rixrender> -DOUT=${CLI_OUT}/memory
                 "-DINTEGRATORS=PxrDirectLighting;PxrPathTracer;PxrVCM;PxrDefault;PxrValidateBxdf;PxrDebugShadingContext;PxrOcclusion"
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/check-bounded-memory.cmake)
set_tests_properties(cli.memory_bounded_at_any_spp PROPERTIES LABELS cli)

# The course text's way to build: its headers from $(RMANTREE)/include with
# -std=c++14 (every warning an error), a plain Makefile, and a plugin folder
# named in a rendermn.ini beside the scene. The text-style plugin then renders
# the chapter 6 scene with no warning and no invalid pdf.
add_test(NAME api.headers_compile_as_cxx14
         COMMAND ${CMAKE_CXX_COMPILER} -std=c++14 -fsyntax-only -Wall -Wextra -Wpedantic -Werror
                 -I${RMANTREE_DIR}/include ${CMAKE_CURRENT_SOURCE_DIR}/api_all_headers.cpp)
set(TEXT_STYLE ${CLI_OUT}/textstyle)
add_test(NAME api.text_style_plugin_with_a_makefile
         COMMAND sh -c "rm -rf ${TEXT_STYLE} && mkdir -p ${TEXT_STYLE} && cp ${CMAKE_CURRENT_SOURCE_DIR}/plugins/textstyle/* ${TEXT_STYLE}/ && make -s -C ${TEXT_STYLE} RMANTREE=${RMANTREE_DIR} && printf '/standardrixpluginpath .\\n' > ${TEXT_STYLE}/rendermn.ini && sed 's/Bxdf \"diffuse\"/Bxdf \"textdiffuse\"/' ${PROJECT_SOURCE_DIR}/scenes/ch06/diffuse.rib > ${TEXT_STYLE}/scene.rib && cd ${TEXT_STYLE} && $<TARGET_FILE:rixrender> --quiet --spp 4 --stats-json stats.json -o text.exr scene.rib && grep -q '\"invalid_pdf_samples\": 0' stats.json && grep -q '\"nonfinite_samples\": 0' stats.json && echo rendered")
set_tests_properties(api.text_style_plugin_with_a_makefile PROPERTIES PASS_REGULAR_EXPRESSION "rendered"
                     FAIL_REGULAR_EXPRESSION "warning|error")

# The course text's errata (chapters/appendix-course-text.md): every corrected
# form compiles against the API as the text builds it; every printed form is an error.
set(ERRATA_COMPILE ${CMAKE_CXX_COMPILER} -std=c++14 -fsyntax-only -Wall -Wextra -Werror -I${RMANTREE_DIR}/include
    ${CMAKE_CURRENT_SOURCE_DIR}/course_text/errata.cpp)
add_test(NAME course_text.errata_corrected_forms_compile COMMAND ${ERRATA_COMPILE})
set_tests_properties(course_text.errata_corrected_forms_compile PROPERTIES LABELS cli)
foreach(erratum 6_5 8_6 GetEvaluationDomain EvaluateSamples EvaluateSampleAtIndex RixBXLookupByName RixLobeSampled)
  add_test(NAME course_text.erratum_${erratum}_as_printed_is_an_error COMMAND ${ERRATA_COMPILE} -DAS_PRINTED_${erratum})
  set_tests_properties(course_text.erratum_${erratum}_as_printed_is_an_error PROPERTIES WILL_FAIL TRUE LABELS cli)
endforeach()
# The integrator the text calls PxrValidateBxdF: found as PxrValidateBxdf (as a file system that
# ignores case finds it), with a warning that names the right spelling.
add_test(NAME course_text.misspelled_integrator_is_found_with_a_warning
         COMMAND sh -c "printf 'Integrator \"PxrValidateBxdF\" \"v\"\\nWorldBegin\\nWorldEnd\\n' > ${CLI_OUT}/errata.rib && $<TARGET_FILE:rixrender> --quiet -o ${CLI_OUT}/errata.exr ${CLI_OUT}/errata.rib 2>&1; true")
set_tests_properties(course_text.misspelled_integrator_is_found_with_a_warning PROPERTIES
                     PASS_REGULAR_EXPRESSION "errata.rib:1:1: Integrator plugin \"PxrValidateBxdF\" is spelled \"PxrValidateBxdf\" on the plugin search path: [^\n]*PxrValidateBxdf.so is used.*wrote" LABELS cli)

# A student's workspace: the exercises copied outside the repository (never
# into it, never over existing work), and the copy builds on its own.
add_test(NAME cli.new_workspace_outside_the_repository
         COMMAND sh -c "ws=$(mktemp -d) && rmdir $ws && ${PROJECT_SOURCE_DIR}/scripts/new-workspace.sh --no-build $ws && test -f $ws/ch06/diffuse/Diffuse.cpp && test -f $ws/WORKSPACE.md && ! ${PROJECT_SOURCE_DIR}/scripts/new-workspace.sh --no-build $ws && ! ${PROJECT_SOURCE_DIR}/scripts/new-workspace.sh --no-build ${PROJECT_SOURCE_DIR}/out/ws && cmake -S $ws -B $ws/build -DBXDFLAB_ROOT=${PROJECT_SOURCE_DIR} > /dev/null && cmake --build $ws/build --target hello > /dev/null && test -f $ws/build/plugins/hello.so && rm -rf $ws && echo workspace-ok")
set_tests_properties(cli.new_workspace_outside_the_repository PROPERTIES PASS_REGULAR_EXPRESSION "workspace-ok" LABELS cli)
# Typing slips in a scene are warnings that name what was meant, and the render goes on.
add_test(NAME cli.typos_name_what_was_meant COMMAND rixrender --quiet --spp 1 -o typos.exr
         ${CMAKE_CURRENT_SOURCE_DIR}/scenes/typos.rib WORKING_DIRECTORY ${CLI_OUT})
set_tests_properties(cli.typos_name_what_was_meant PROPERTIES LABELS "cli;sanitize" PASS_REGULAR_EXPRESSION
  "typos.rib:7:30: PxrDiskLight \"key\": parameter \"intensty\" is not used; ignored \\(did you mean \"intensity\"\\?\\).*typos.rib:9:3: AttributeBegn is not a RIB request; skipped \\(did you mean AttributeBegin\\?\\).*typos.rib:5:[0-9]+: Integrator \"PxrDirectLighting\": parameter \"numLightSample\" is not used; ignored \\(did you mean \"numLightSamples\"\\?\\).*wrote typos.exr")
