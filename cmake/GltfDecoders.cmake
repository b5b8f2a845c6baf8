# The decoders of glTF's compressed data, Debian's libwebp-dev
# (EXT_texture_webp), libmeshoptimizer-dev (EXT_meshopt_compression) and
# libdraco-dev (KHR_draco_mesh_compression),
# as penumbra_gltf_decoders: an interface target carrying the libraries and
# the PENUMBRA_HAVE_* definitions the loader's sources test. Required on
# Linux (scripts/setup.sh installs them); the mingw cross build has neither,
# and there files that require the extensions are refused in one line.
add_library(penumbra_gltf_decoders INTERFACE)
set(PENUMBRA_GLTF_DECODERS OFF)  # what the installed package must find again
if(NOT (CMAKE_CROSSCOMPILING AND MINGW))
  set(PENUMBRA_GLTF_DECODERS ON)
  find_package(WebP CONFIG QUIET)  # vcpkg's libwebp
  if(TARGET WebP::webp)
    set(_webp WebP::webp)
  else()
    find_package(PkgConfig REQUIRED)
    pkg_check_modules(WEBP REQUIRED IMPORTED_TARGET GLOBAL libwebp)
    set(_webp PkgConfig::WEBP)
  endif()
  find_package(meshoptimizer CONFIG REQUIRED)
  find_package(draco CONFIG REQUIRED)
  target_link_libraries(penumbra_gltf_decoders INTERFACE ${_webp} meshoptimizer::meshoptimizer
    draco::draco)
  target_compile_definitions(penumbra_gltf_decoders INTERFACE PENUMBRA_HAVE_WEBP PENUMBRA_HAVE_MESHOPT
    PENUMBRA_HAVE_DRACO)
endif()
