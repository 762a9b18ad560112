# The sources that turn RIB text into a Scene (lexer, parser, graphics state,
# shapes, lights), relative to renderer/src. rixcore builds them with the rest
# of the renderer; the RIB fuzzer (tests/fuzz) builds exactly this slice with
# clang and libFuzzer.
set(RIX_SCENE_SOURCES
  core/Diagnostics.cpp
  core/ImageFiles.cpp
  parse/RibLexer.cpp
  parse/RibParser.cpp
  parse/RibRequest.cpp
  parse/ParamList.cpp
  parse/StandardDeclarations.cpp
  scene/SceneBuilder.cpp
  scene/shapes/Quadric.cpp
  scene/shapes/TriangleMesh.cpp
  scene/shapes/MeshBuilders.cpp
  scene/lights/AreaLights.cpp
  scene/lights/InfiniteLights.cpp
  scene/lights/LightFactory.cpp
)
