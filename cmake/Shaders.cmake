# penumbra_add_shaders(TARGET name NAMESPACE ns INCLUDE_DIRS dirs...
#                      [STAGES files... HLSL_INCLUDE_DIRS dirs...]
#                      [SOURCES files...]
#                      [EFFECT_VARIANTS stage bits masks [stage bits masks ...]])
#
# Builds every entry point and embeds the results in a static library.
#
# STAGES are written once, in the shared dialect (docs/ARCHITECTURE.md,
# "Shaders"); the extension names the stage (.rgen .rmiss .rchit .rahit .rint
# .comp, and .vert / .frag for the raster subset). For each, the build writes two wrappers that include the API's
# prelude and then the stage:
# - GLSL (prelude.glsl, found through INCLUDE_DIRS): glslang compiles it to
#   SPIR-V for Vulkan. glslang writes a depfile, so editing an included
#   .hlsli recompiles exactly the shaders that include it.
# - HLSL (prelude.hlsli, through HLSL_INCLUDE_DIRS): where DXC was found (see
#   below) it compiles it to validated DXIL for D3D12, -T lib_6_5 (ray-tracing
#   stages), -T cs_6_3 (compute) or vs_6_0 / ps_6_0 (raster); without DXC the
#   DXIL is empty and the D3D12 backend says so at pipeline creation. The
#   Vulkan attributes the prelude spells ([[vk::binding]]) are for DXC's
#   SPIR-V mode, so -Wno-ignored-attributes. Whether DXC is here or not, glslang's HLSL
#   front-end compiles the same wrapper with PENUMBRA_HLSL_CHECK (the DXR
#   intrinsics stubbed, hlsl/prelude.hlsli), for every effect variant's
#   extremes, so an HLSL-only error in a stage or in the core fails the build.
# SOURCES are plain GLSL stages (tests' shaders) or .hlsl compute harnesses
# (glslang's HLSL front-end, entry point "main"), compiled to SPIR-V alone.
#
# Binding layout: penumbra_shader_layout (tools/shader_layout) reflects the
# SPIR-V at build time and writes it, the SPIR-V and the DXIL into one
# generated header per shader.
#
# The library is also penumbra::<TARGET without "penumbra_">, the name it is
# exported by. The generated header <TARGET>.h declares, in namespace <ns>:
#   std::span<const uint32_t> find(name);   // SPIR-V words, empty if unknown
#   rhi::ShaderDesc shaderDesc(name);        // everything a backend needs
# where `name` is the source file name, e.g. "path_trace.rgen".
#
# EFFECT_VARIANTS (shaders/shared/effects.h): each listed stage is also built
# once per mask M of `masks` (comma separated, each a proper subset of
# `bits`) with -DPT_EFFECTS=M, named "<stem>.e<M>.<ext>" (path_trace.e5.rgen);
# the plain name holds every effect.

# --- DXC: Windows SDK, Vulkan SDK, PATH, or -DDXC_EXECUTABLE=... -------------
# Only a build with the D3D12 backend (WIN32: MSVC or the mingw-w64 cross
# build) embeds DXIL; scripts/setup.sh installs DXC on Debian when
# ../shared/tools/d3d12-on-linux is there.
set(DXC_EXECUTABLE "" CACHE FILEPATH "DirectX Shader Compiler used to build the D3D12 backend's DXIL")
if(WIN32 AND NOT DXC_EXECUTABLE)
  set(_dxc_hints)
  if(VCPKG_INSTALLED_DIR AND VCPKG_TARGET_TRIPLET)  # vcpkg's directx-dxc port
    list(APPEND _dxc_hints "${VCPKG_INSTALLED_DIR}/${VCPKG_TARGET_TRIPLET}/tools/directx-dxc")
  endif()
  if(DEFINED ENV{VULKAN_SDK})
    list(APPEND _dxc_hints "$ENV{VULKAN_SDK}/Bin" "$ENV{VULKAN_SDK}/bin")
  endif()
  # Windows SDKs install dxc.exe under Windows Kits/10/bin/<version>/x64; newest first.
  file(GLOB _sdk_bins LIST_DIRECTORIES true "C:/Program Files (x86)/Windows Kits/10/bin/10.*")
  list(SORT _sdk_bins COMPARE NATURAL ORDER DESCENDING)
  foreach(dir ${_sdk_bins})
    list(APPEND _dxc_hints "${dir}/x64")
  endforeach()
  # A cross build runs the build machine's DXC: look on its PATH too.
  find_program(_dxc_found NAMES dxc HINTS ${_dxc_hints} NO_CACHE NO_CMAKE_FIND_ROOT_PATH)
  if(_dxc_found)
    set(DXC_EXECUTABLE "${_dxc_found}" CACHE FILEPATH "" FORCE)
  endif()
endif()
set(PENUMBRA_HAVE_DXIL OFF)
if(WIN32 AND DXC_EXECUTABLE)
  set(PENUMBRA_HAVE_DXIL ON)
  message(STATUS "Penumbra: DXIL for the D3D12 backend is compiled with ${DXC_EXECUTABLE}")
elseif(WIN32)
  message(WARNING "Penumbra: DXC not found: this build embeds no DXIL and its D3D12 backend cannot create "
                  "pipelines (install the Windows SDK or the Vulkan SDK, run scripts/setup.sh on Debian, "
                  "or pass -DDXC_EXECUTABLE=/path/to/dxc)")
endif()

# Which compiler turns the stages into SPIR-V for Vulkan: glslang (the
# default: GLSL wrapper, glsl/prelude.glsl) or DXC (-spirv, from the same
# HLSL wrapper the DXIL is built from: one compiler and one prelude for both
# APIs). docs/results.md measures the two on the H200 and says why the
# default is what it is.
set(PENUMBRA_SPIRV_COMPILER "glslang" CACHE STRING "SPIR-V compiler of the shader stages: glslang | dxc")
set_property(CACHE PENUMBRA_SPIRV_COMPILER PROPERTY STRINGS glslang dxc)
if(PENUMBRA_SPIRV_COMPILER STREQUAL "dxc")
  if(NOT DXC_EXECUTABLE)
    find_program(_dxc_spirv NAMES dxc NO_CACHE)
    if(NOT _dxc_spirv)
      message(FATAL_ERROR "PENUMBRA_SPIRV_COMPILER=dxc: no dxc found (scripts/setup.sh installs it, or pass -DDXC_EXECUTABLE=...)")
    endif()
    set(DXC_EXECUTABLE "${_dxc_spirv}" CACHE FILEPATH "" FORCE)
  endif()
  message(STATUS "Penumbra: the stages' SPIR-V is compiled from HLSL with ${DXC_EXECUTABLE}")
elseif(NOT PENUMBRA_SPIRV_COMPILER STREQUAL "glslang")
  message(FATAL_ERROR "PENUMBRA_SPIRV_COMPILER is '${PENUMBRA_SPIRV_COMPILER}': glslang or dxc")
endif()

# --- The reflection tool: built here, or taken from a native build ---------
# A cross build cannot run what it builds, so it names a native build's tool
# directory (scripts/build-windows-cross.sh passes build/tools/shader_layout).
set(PENUMBRA_HOST_TOOLS_DIR "" CACHE PATH
    "Directory holding a native penumbra_shader_layout (required when cross-compiling)")
if(CMAKE_CROSSCOMPILING)
  if(NOT PENUMBRA_HOST_TOOLS_DIR)
    message(FATAL_ERROR "Cross-compiling needs -DPENUMBRA_HOST_TOOLS_DIR=<native build>/tools/shader_layout "
                        "(the build-time shader reflection tool must run on this machine)")
  endif()
  find_program(PENUMBRA_SHADER_LAYOUT penumbra_shader_layout PATHS ${PENUMBRA_HOST_TOOLS_DIR}
               NO_DEFAULT_PATH NO_CMAKE_FIND_ROOT_PATH REQUIRED)
  set(_penumbra_layout_command ${PENUMBRA_SHADER_LAYOUT})
  set(_penumbra_layout_depends ${PENUMBRA_SHADER_LAYOUT})
else()
  set(_penumbra_layout_command $<TARGET_FILE:penumbra_shader_layout>)
  set(_penumbra_layout_depends penumbra_shader_layout)
endif()

function(_penumbra_shader_stage name out)
  if(name MATCHES "\\.rgen$")
    set(stage RayGeneration)
  elseif(name MATCHES "\\.rmiss$")
    set(stage Miss)
  elseif(name MATCHES "\\.rchit$")
    set(stage ClosestHit)
  elseif(name MATCHES "\\.rahit$")
    set(stage AnyHit)
  elseif(name MATCHES "\\.rint$")
    set(stage Intersection)
  elseif(name MATCHES "\\.(comp|hlsl)$")
    set(stage Compute)
  elseif(name MATCHES "\\.vert$")
    set(stage Vertex)
  elseif(name MATCHES "\\.frag$")
    set(stage Pixel)
  else()
    message(FATAL_ERROR "penumbra_add_shaders: cannot tell the stage of '${name}'")
  endif()
  set(${out} ${stage} PARENT_SCOPE)
endfunction()

# DXC's target profile of a stage, for DXIL and for -spirv alike.
function(_penumbra_dxc_profile stage out)
  if(stage STREQUAL "Compute")
    set(profile -T cs_6_3 -E main)
  elseif(stage STREQUAL "Vertex")
    set(profile -T vs_6_0 -E main)
  elseif(stage STREQUAL "Pixel")
    set(profile -T ps_6_0 -E main)
  else()
    # 6.5 for GeometryIndex() (DXR 1.1, D3D12_RAYTRACING_TIER_1_1).
    set(profile -T lib_6_5)
  endif()
  set(${out} ${profile} PARENT_SCOPE)
endfunction()

function(penumbra_add_shaders)
  cmake_parse_arguments(ARG "" "TARGET;NAMESPACE"
                        "STAGES;SOURCES;INCLUDE_DIRS;HLSL_INCLUDE_DIRS;EFFECT_VARIANTS" ${ARGN})
  set(out_dir ${CMAKE_CURRENT_BINARY_DIR}/spirv)
  set(wrapper_dir ${CMAKE_CURRENT_BINARY_DIR}/stages)
  file(MAKE_DIRECTORY ${out_dir} ${wrapper_dir})
  set(include_flags)
  foreach(dir ${ARG_INCLUDE_DIRS})
    list(APPEND include_flags -I${dir})
  endforeach()
  set(hlsl_include_flags)
  set(hlsl_depends)
  foreach(dir ${ARG_HLSL_INCLUDE_DIRS})
    list(APPEND hlsl_include_flags -I${dir})
    file(GLOB headers ${dir}/*.hlsli ${dir}/*.h)
    list(APPEND hlsl_depends ${headers})
  endforeach()

  set(headers)
  set(checks)
  set(table_entries)
  set(includes)
  # Jobs: "<source>|<embedded name>|<PT_EFFECTS value or ->|<stage or source>".
  set(jobs)
  foreach(src ${ARG_STAGES})
    get_filename_component(abs ${src} ABSOLUTE)
    get_filename_component(name ${src} NAME)
    list(APPEND jobs "${abs}|${name}|-|stage")
  endforeach()
  foreach(src ${ARG_SOURCES})
    get_filename_component(abs ${src} ABSOLUTE)
    get_filename_component(name ${src} NAME)
    list(APPEND jobs "${abs}|${name}|-|source")
  endforeach()
  set(variant_args ${ARG_EFFECT_VARIANTS})
  while(variant_args)
    list(POP_FRONT variant_args src bits masks)
    get_filename_component(abs ${src} ABSOLUTE)
    get_filename_component(name ${src} NAME)
    string(REGEX REPLACE "^([^.]+)\\.(.*)$" "\\1" stem ${name})
    string(REGEX REPLACE "^([^.]+)\\.(.*)$" "\\2" ext ${name})
    string(REPLACE "," ";" masks "${masks}")
    foreach(mask ${masks})
      math(EXPR inside "${mask} & ${bits}")
      if(NOT inside EQUAL mask OR mask EQUAL bits)
        message(FATAL_ERROR "penumbra_add_shaders: variant ${mask} of ${name} is not a proper subset of its bits ${bits}")
      endif()
      list(APPEND jobs "${abs}|${stem}.e${mask}.${ext}|${mask}|stage")
    endforeach()
  endwhile()

  foreach(job ${jobs})
    string(REPLACE "|" ";" job_parts "${job}")
    list(GET job_parts 0 abs)
    list(GET job_parts 1 name)
    list(GET job_parts 2 effects)
    list(GET job_parts 3 kind)
    set(effect_defines)
    if(NOT effects STREQUAL "-")
      set(effect_defines -DPT_EFFECTS=${effects})
    endif()
    get_filename_component(source_name ${abs} NAME)
    string(MAKE_C_IDENTIFIER "shader_${name}" var)
    _penumbra_shader_stage(${name} stage)
    set(spv ${out_dir}/${name}.spv)
    set(header ${out_dir}/${name}.h)
    set(lang_flags --target-env vulkan1.2)
    set(glslang_input ${abs})
    if(kind STREQUAL "stage")
      # The wrappers: written at configure time, one per stage source (the
      # variants share it).
      # Each names the stage by file name, found through its own directory
      # (glslang takes no absolute include paths), and names the stage with
      # -S (its own name ends in .glsl / .hlsl).
      set(glslang_input ${wrapper_dir}/${source_name}.glsl)
      set(hlsl_input ${wrapper_dir}/${source_name}.hlsl)
      # file(CONFIGURE) writes only what changed, so a configure rebuilds nothing.
      file(CONFIGURE OUTPUT ${glslang_input} CONTENT
           "#version 460\n#extension GL_GOOGLE_include_directive : require\n#include \"prelude.glsl\"\n#include \"${source_name}\"\n")
      file(CONFIGURE OUTPUT ${hlsl_input} CONTENT "#include \"prelude.hlsli\"\n#include \"${source_name}\"\n")
      get_filename_component(stage_dir ${abs} DIRECTORY)
      string(REGEX REPLACE "^.*\\." "" glslang_stage ${source_name})
      list(APPEND lang_flags -S ${glslang_stage} -I${stage_dir})
      if(NOT stage MATCHES "^(Compute|Vertex|Pixel)$")
        list(APPEND lang_flags -DPT_STAGE_RAY_TRACING=1)
      endif()
      # glslang's HLSL front-end checks raster stages as what they are, the
      # others as compute shaders (hlsl/prelude.hlsli).
      set(hlsl_check_stage comp)
      if(stage MATCHES "^(Vertex|Pixel)$")
        set(hlsl_check_stage ${glslang_stage})
      endif()
    elseif(name MATCHES "\\.hlsl$")
      # HLSL compute harness: glslang's HLSL front-end, entry point "main".
      # SPIR-V 1.3: glslang 12's HLSL front-end still emits BufferBlock, which
      # SPIR-V 1.4+ forbids. glslang's shift flags do not class registers the
      # way DXC's -fvk-*-shift do (structured buffers shift as SSBOs whatever
      # their register), so HLSL sources spell [[vk::binding(PENUMBRA_U(n))]]
      # next to register(un).
      set(lang_flags --target-env vulkan1.1 -D -S comp -e main)
    endif()
    if(kind STREQUAL "stage" AND PENUMBRA_SPIRV_COMPILER STREQUAL "dxc")
      _penumbra_dxc_profile(${stage} spirv_profile)
      add_custom_command(
        OUTPUT ${spv}
        COMMAND ${DXC_EXECUTABLE} -spirv -fspv-target-env=vulkan1.2 ${spirv_profile} -HV 2021 -O3
                -Wno-ignored-attributes ${effect_defines} -I${stage_dir} ${hlsl_include_flags}
                -Fo ${spv} ${hlsl_input}
        DEPENDS ${abs} ${hlsl_depends}
        COMMENT "dxc -spirv ${name}"
        VERBATIM)
    else()
      add_custom_command(
        OUTPUT ${spv}
        COMMAND ${GLSLANG_VALIDATOR} ${lang_flags} ${effect_defines} ${include_flags} --quiet
                --depfile ${spv}.d -o ${spv} ${glslang_input}
        DEPENDS ${abs}
        DEPFILE ${spv}.d
        COMMENT "glslang ${name}"
        VERBATIM)
    endif()

    set(dxil_args)
    set(dxil_depends)
    if(kind STREQUAL "stage")
      # The HLSL check: every stage's plain build (all effects) and its
      # variant without any, so both sides of each PT_HAS_EFFECT are parsed.
      if(effects STREQUAL "-" OR effects STREQUAL "0")
        set(check ${out_dir}/hlsl_check/${name}.spv)
        add_custom_command(
          OUTPUT ${check}
          COMMAND ${CMAKE_COMMAND} -E make_directory ${out_dir}/hlsl_check
          COMMAND ${GLSLANG_VALIDATOR} --target-env vulkan1.1 -D -S ${hlsl_check_stage} -e main -DPENUMBRA_HLSL_CHECK=1
                  ${effect_defines} -I${stage_dir} ${hlsl_include_flags} --quiet --depfile ${check}.d -o ${check}
                  ${hlsl_input}
          DEPENDS ${abs}
          DEPFILE ${check}.d
          COMMENT "HLSL check ${name}"
          VERBATIM)
        list(APPEND checks ${check})
      endif()
      if(PENUMBRA_HAVE_DXIL)
        set(dxil ${out_dir}/${name}.dxil)
        _penumbra_dxc_profile(${stage} profile)
        add_custom_command(
          OUTPUT ${dxil}
          COMMAND ${DXC_EXECUTABLE} ${profile} -HV 2021 -Wno-ignored-attributes ${effect_defines} -I${stage_dir} ${hlsl_include_flags} -Fo ${dxil}
                  ${hlsl_input}
          DEPENDS ${abs} ${hlsl_depends}
          COMMENT "dxc ${name}"
          VERBATIM)
        set(dxil_args --dxil ${dxil})
        set(dxil_depends ${dxil})
      endif()
    endif()
    add_custom_command(
      OUTPUT ${header}
      COMMAND ${_penumbra_layout_command} --name ${name} --var ${var} --spirv ${spv} ${dxil_args}
              --out ${header}
      DEPENDS ${spv} ${dxil_depends} ${_penumbra_layout_depends}
      COMMENT "reflect + embed ${name}"
      VERBATIM)
    list(APPEND headers ${header})
    string(APPEND includes "#include \"${name}.h\"\n")
    string(APPEND table_entries
      "    {\"${name}\", rhi::ShaderStage::${stage}, ${var}_spirv, "
      "{${var}_dxil, ${var}_dxil_bytes}, ${var}_record_bytes, &${var}_layout},\n")
  endforeach()

  set(table_cpp ${out_dir}/${ARG_TARGET}.cpp)
  set(namespace ${ARG_NAMESPACE})
  file(CONFIGURE OUTPUT ${out_dir}/include/${ARG_TARGET}.h CONTENT [=[
// Generated by cmake/Shaders.cmake.
#pragma once
#include <cstdint>
#include <span>
#include <string_view>

#include "penumbra/rhi/pipeline.h"

namespace @namespace@ {
// SPIR-V words of an embedded shader by source file name; empty if unknown.
std::span<const uint32_t> find(std::string_view name);
// The shader in both APIs' forms with its build-time reflected layout;
// exportName = name. Throws penumbra::Error if no such shader is embedded.
rhi::ShaderDesc shaderDesc(std::string_view name);
}
]=] @ONLY)
  file(CONFIGURE OUTPUT ${table_cpp} CONTENT [=[
// Generated by cmake/Shaders.cmake: every shader's SPIR-V, DXIL and
// reflected binding layout, by file name.
#include "@ARG_TARGET@.h"

#include <string>

#include "penumbra/util/error.h"
@includes@
namespace @namespace@ {
namespace {
namespace rhi = penumbra::rhi;
struct Entry {
  std::string_view name;
  rhi::ShaderStage stage;
  std::span<const uint32_t> spirv;
  std::span<const uint8_t> dxil;
  uint32_t shaderRecordBytes;
  rhi::PipelineBindingLayout (*layout)();
};
const Entry kShaders[] = {
@table_entries@};
const Entry* lookup(std::string_view name) {
  for (const auto& entry : kShaders)
    if (entry.name == name) return &entry;
  return nullptr;
}
}  // namespace

std::span<const uint32_t> find(std::string_view name) {
  const Entry* entry = lookup(name);
  return entry ? entry->spirv : std::span<const uint32_t>{};
}

rhi::ShaderDesc shaderDesc(std::string_view name) {
  const Entry* entry = lookup(name);
  if (!entry) throw penumbra::Error("shader '" + std::string(name) + "' is not embedded in this build");
  rhi::ShaderDesc desc;
  desc.stage = entry->stage;
  desc.spirv = entry->spirv;
  desc.dxil = entry->dxil;
  desc.bindingLayout = entry->layout();
  desc.shaderRecordBytes = entry->shaderRecordBytes;
  desc.exportName = std::string(name);
  return desc;
}
}  // namespace @namespace@
]=] @ONLY)
  add_library(${ARG_TARGET} STATIC ${table_cpp} ${headers} ${checks})
  string(REGEX REPLACE "^penumbra_" "" export_name ${ARG_TARGET})
  add_library(penumbra::${export_name} ALIAS ${ARG_TARGET})
  # Installed (cmake/Install.cmake), the generated header goes beside the
  # shaders' shared headers; PUBLIC_HEADER is how install(TARGETS) finds it.
  set_target_properties(${ARG_TARGET} PROPERTIES EXPORT_NAME ${export_name}
                        PUBLIC_HEADER ${out_dir}/include/${ARG_TARGET}.h)
  target_include_directories(${ARG_TARGET} PRIVATE ${out_dir}
    PUBLIC $<BUILD_INTERFACE:${out_dir}/include> $<INSTALL_INTERFACE:${PENUMBRA_INSTALL_SHADER_INCLUDEDIR}>)
  target_link_libraries(${ARG_TARGET} PUBLIC penumbra::rhi)
endfunction()
