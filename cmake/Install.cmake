# install() rules and the exported CMake package: after
# `cmake --install build --prefix P`, a project finds the engine with
# find_package(Penumbra) (CMAKE_PREFIX_PATH=P) and links penumbra::engine,
# penumbra::backends or any one library (docs/ARCHITECTURE.md, "Build").
# tests/package builds such a project against the installed tree.
include(CMakePackageConfigHelpers)
set(_config_dir ${CMAKE_INSTALL_LIBDIR}/cmake/Penumbra)

# Every library an exported one links, privately included: the libraries are
# static, so a consumer's link needs the archives of their PRIVATE
# dependencies too (penumbra_shaders, penumbra_scenes, the D3D12 backend).
set(_exported penumbra_util penumbra_rhi penumbra_shaders penumbra_scenes penumbra_image penumbra_scene
    penumbra_gltf_decoders penumbra_render penumbra_batch penumbra_study penumbra_engine penumbra_backends)
if(TARGET penumbra_backend_d3d12)
  list(APPEND _exported penumbra_backend_d3d12)
endif()
install(TARGETS ${_exported} EXPORT PenumbraTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  PUBLIC_HEADER DESTINATION ${PENUMBRA_INSTALL_SHADER_INCLUDEDIR})  # penumbra_shaders.h
install(EXPORT PenumbraTargets NAMESPACE penumbra:: DESTINATION ${_config_dir})

# The public headers, by the paths they include each other by
# (<penumbra/rhi/device.h>). Left out, the internals: the glTF loader's
# pieces, which take tinygltf's types (a private dependency); the SPIR-V
# reflection the package does not contain; JSON reading helpers; the RHI's
# validation objects and fault injection (reached through rhi/validation.h
# and the device's create info, not by name).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/engine/penumbra DESTINATION ${PENUMBRA_INSTALL_INCLUDEDIR}
  FILES_MATCHING PATTERN "*.h"
  REGEX "/scene/(tinygltf|gltf_accessors|gltf_instancing|gltf_lights|gltf_materials|gltf_meshopt|gltf_draco|gltf_container|gltf_primitives|gltf_textures|json_reading)\\.h$" EXCLUDE
  REGEX "/rhi/(shader_reflection|validation_objects|fault_injection)\\.h$" EXCLUDE)
install(FILES ${PROJECT_SOURCE_DIR}/backends/backend_factory.h
  DESTINATION ${PENUMBRA_INSTALL_INCLUDEDIR}/penumbra)
# The structs and registers C++ shares with the shaders (path_tracer_shared.h
# for render/path_tracer.h, bindings.hlsli for render/shader_binding_offsets.h), in
# their own root, as the build's include directory of shaders/shared.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/shaders/shared/ DESTINATION ${PENUMBRA_INSTALL_SHADER_INCLUDEDIR}
  FILES_MATCHING PATTERN "*.h" PATTERN "bindings.hlsli")

# DirectX-Headers' target, where the D3D12 backend links one (native Windows).
if(TARGET penumbra_backend_d3d12 AND PENUMBRA_DIRECTX_HEADERS)
  set(PENUMBRA_PACKAGE_NEEDS_DIRECTX_HEADERS ON)
else()
  set(PENUMBRA_PACKAGE_NEEDS_DIRECTX_HEADERS OFF)
endif()
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/PenumbraConfig.cmake.in
  ${PROJECT_BINARY_DIR}/PenumbraConfig.cmake INSTALL_DESTINATION ${_config_dir})
# 0.x: a minor version may change the interface.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/PenumbraConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/PenumbraConfig.cmake ${PROJECT_BINARY_DIR}/PenumbraConfigVersion.cmake
  DESTINATION ${_config_dir})

install(TARGETS penumbra RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
if(TARGET penumbra-viewer)
  install(TARGETS penumbra-viewer RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
# As in the build tree (apps/render): a portable bin/ carries the shared
# tinyexr beside the binaries, found through their $ORIGIN rpath.
get_target_property(_tinyexr_type tinyexr::tinyexr TYPE)
if(PENUMBRA_PORTABLE AND NOT WIN32 AND _tinyexr_type STREQUAL "SHARED_LIBRARY")
  install(FILES $<TARGET_FILE:tinyexr::tinyexr> $<TARGET_SONAME_FILE:tinyexr::tinyexr>
          DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
