# The sources that turn RIB text into a Scene (lexer, parser, graphics state,
# shapes, lights), relative to renderer/src. rixcore builds them with the rest
# of the renderer; the RIB fuzzer (tests/fuzz) builds exactly this slice with
# clang and libFuzzer.
set(RIX_SCENE_SOURCES
  core/Diagnostics.cpp
  core/GitLfs.cpp
  core/ImageFiles.cpp
  core/Spelling.cpp
  core/TextureLocator.cpp
  parse/RibLexer.cpp
  parse/RibParser.cpp
  parse/RibRequest.cpp
  parse/ParamList.cpp
  parse/StandardDeclarations.cpp
  parse/RequestNames.cpp
  parse/ZipMember.cpp
  scene/SceneBuilder.cpp
  scene/PatternReach.cpp
  scene/requests/OptionRequests.cpp
  scene/requests/StateRequests.cpp
  scene/requests/ShadingRequests.cpp
  scene/requests/ShapeRequests.cpp
  scene/requests/InstanceRequests.cpp
  scene/requests/FreeformRequests.cpp
  scene/shapes/Quadric.cpp
  scene/shapes/Sphere.cpp
  scene/shapes/Cylinder.cpp
  scene/shapes/Disk.cpp
  scene/shapes/Cone.cpp
  scene/shapes/Paraboloid.cpp
  scene/shapes/Hyperboloid.cpp
  scene/shapes/TriangleMesh.cpp
  scene/shapes/MeshBuilders.cpp
  scene/shapes/Triangulation.cpp
  scene/shapes/Primvars.cpp
  scene/shapes/SubdivisionSurface.cpp
  scene/shapes/Curves.cpp
  scene/shapes/NurbsSurface.cpp
  scene/shapes/BlobbySurface.cpp
  scene/lights/AreaLights.cpp
  scene/lights/MeshLight.cpp
  scene/lights/InfiniteLights.cpp
  scene/lights/DayLight.cpp
  scene/lights/LightFactory.cpp
  scene/lights/PointLights.cpp
  scene/lights/Blackbody.cpp
)
