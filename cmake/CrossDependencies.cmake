# Dependencies of the mingw-w64 cross build (cmake/toolchains/). Everything
# the Windows binary needs is header-only except zlib, so:
# - header-only libraries (glm, nlohmann-json, CLI11, fmt, xxHash, stb, tinygltf, tinyexr, the
#   Vulkan headers, DirectX-Headers) come from the build machine's Debian
#   packages through include directories that hold ONLY those libraries
#   (symlinks under the build tree). Adding /usr/include itself would put
#   glibc's headers in front of mingw's.
# - tinyexr, which Debian ships as a Linux .so, is compiled from its single
#   header here, with zlib from libz-mingw-w64-dev (linked statically).
# It defines the same targets/variables the native find_package calls do.

set(_farm ${CMAKE_BINARY_DIR}/cross-headers)
file(MAKE_DIRECTORY ${_farm})
# penumbra_cross_headers(<dir> <header dir or file>...): links each entry of
# /usr/include (or PENUMBRA_HOST_INCLUDE_DIR) into <dir>.
set(PENUMBRA_HOST_INCLUDE_DIR /usr/include CACHE PATH "Where the build machine's header-only packages live")
function(penumbra_cross_headers dir)
  file(MAKE_DIRECTORY ${dir})
  foreach(entry ${ARGN})
    set(source ${PENUMBRA_HOST_INCLUDE_DIR}/${entry})
    if(NOT EXISTS ${source})
      message(FATAL_ERROR "Cross build: ${source} is missing (run scripts/setup.sh)")
    endif()
    file(CREATE_LINK ${source} ${dir}/${entry} SYMBOLIC)
  endforeach()
endfunction()

penumbra_cross_headers(${_farm}/glm glm)
add_library(glm::glm INTERFACE IMPORTED)
set_target_properties(glm::glm PROPERTIES INTERFACE_INCLUDE_DIRECTORIES ${_farm}/glm)

penumbra_cross_headers(${_farm}/json nlohmann)
add_library(nlohmann_json::nlohmann_json INTERFACE IMPORTED)
set_target_properties(nlohmann_json::nlohmann_json PROPERTIES INTERFACE_INCLUDE_DIRECTORIES ${_farm}/json)

penumbra_cross_headers(${_farm}/cli11 CLI)
add_library(CLI11::CLI11 INTERFACE IMPORTED)
set_target_properties(CLI11::CLI11 PROPERTIES INTERFACE_INCLUDE_DIRECTORIES ${_farm}/cli11)

penumbra_cross_headers(${_farm}/fmt fmt)
add_library(fmt::fmt-header-only INTERFACE IMPORTED)
set_target_properties(fmt::fmt-header-only PROPERTIES INTERFACE_INCLUDE_DIRECTORIES ${_farm}/fmt
                      INTERFACE_COMPILE_DEFINITIONS FMT_HEADER_ONLY=1)

penumbra_cross_headers(${_farm}/xxhash xxhash.h)
set(PENUMBRA_XXHASH_INCLUDE_DIR ${_farm}/xxhash)

penumbra_cross_headers(${_farm}/stb stb)
set(STB_INCLUDE_DIR ${_farm}/stb/stb)

penumbra_cross_headers(${_farm}/tinygltf tiny_gltf.h)
set(TINYGLTF_INCLUDE_DIR ${_farm}/tinygltf)

penumbra_cross_headers(${_farm}/vulkan vulkan vk_video)
set(Vulkan_INCLUDE_DIRS ${_farm}/vulkan)

# DirectX-Headers (directx-headers-dev): only directx/ and dxguids/, so
# mingw's own d3d12.h is never shadowed or mixed in. mingw's rpcndr.h is
# version 475; DirectX-Headers asks for 500 unless told otherwise.
penumbra_cross_headers(${_farm}/directx directx dxguids)
set(PENUMBRA_DIRECTX_INCLUDE_DIRS ${_farm}/directx)
set(PENUMBRA_DIRECTX_DEFINITIONS __REQUIRED_RPCNDR_H_VERSION__=475)

# tinyexr from its header, over mingw's static zlib.
find_library(PENUMBRA_MINGW_ZLIB NAMES libz.a REQUIRED)
find_path(PENUMBRA_MINGW_ZLIB_INCLUDE zlib.h REQUIRED)
penumbra_cross_headers(${_farm}/tinyexr tinyexr.h)
add_library(penumbra_tinyexr STATIC ${PROJECT_SOURCE_DIR}/engine/penumbra/image/tinyexr_implementation.cpp)
target_include_directories(penumbra_tinyexr SYSTEM PUBLIC ${_farm}/tinyexr PRIVATE ${PENUMBRA_MINGW_ZLIB_INCLUDE})
target_link_libraries(penumbra_tinyexr PRIVATE ${PENUMBRA_MINGW_ZLIB})
add_library(tinyexr::tinyexr ALIAS penumbra_tinyexr)

# GLFW and Dear ImGui for penumbra-viewer.exe. Debian ships both for Linux
# only, so scripts/setup.sh unpacks Debian's SOURCE packages of the versions
# the native build uses (glfw3 3.3.8-1, imgui 1.86+ds-1) into
# PENUMBRA_WINDOWS_SOURCES, and they are compiled here for Win32 as static
# libraries: GLFW through its own CMake (target glfw, as find_package(glfw3)
# gives natively), the ImGui core as imgui::imgui (vcpkg's name), with
# IMGUI_INCLUDE_DIRS and IMGUI_BACKEND_SOURCES/HEADERS (imgui_impl_glfw) set
# as apps/viewer expects. Third-party code: no Penumbra warnings, headers SYSTEM.
set(PENUMBRA_WINDOWS_SOURCES /usr/local/src/penumbra-deps CACHE PATH
    "Debian's glfw3 and imgui sources for the cross build's viewer (scripts/setup.sh unpacks them)")
set(_glfw_source ${PENUMBRA_WINDOWS_SOURCES}/glfw3)
set(_imgui_source ${PENUMBRA_WINDOWS_SOURCES}/imgui)
foreach(_file ${_glfw_source}/CMakeLists.txt ${_glfw_source}/src/win32_window.c
              ${_imgui_source}/imgui.cpp ${_imgui_source}/backends/imgui_impl_glfw.cpp)
  if(NOT EXISTS ${_file})
    message(FATAL_ERROR "Cross build: ${_file} is missing. scripts/setup.sh unpacks Debian's glfw3 and "
                        "imgui sources into /usr/local/src/penumbra-deps (or where the environment variable "
                        "PENUMBRA_WINDOWS_SOURCES says); point -DPENUMBRA_WINDOWS_SOURCES= at that directory")
  endif()
endforeach()

# In a function so that its settings stay local to GLFW's directory.
function(penumbra_add_glfw source)
  set(BUILD_SHARED_LIBS OFF)
  set(GLFW_BUILD_EXAMPLES OFF)
  set(GLFW_BUILD_TESTS OFF)
  set(GLFW_BUILD_DOCS OFF)
  set(GLFW_INSTALL OFF)
  add_subdirectory(${source} ${CMAKE_BINARY_DIR}/third_party/glfw3 EXCLUDE_FROM_ALL)
endfunction()
penumbra_add_glfw(${_glfw_source})
# Its include directory as a system one for its users (warnings as errors).
set_property(TARGET glfw APPEND PROPERTY INTERFACE_SYSTEM_INCLUDE_DIRECTORIES ${_glfw_source}/include)

# The core as Debian's libimgui.a has it, with ImGui's own stb_truetype and
# stb_rect_pack (Debian's build takes them from libstb, a Linux .so).
add_library(penumbra_imgui STATIC
  ${_imgui_source}/imgui.cpp
  ${_imgui_source}/imgui_demo.cpp
  ${_imgui_source}/imgui_draw.cpp
  ${_imgui_source}/imgui_tables.cpp
  ${_imgui_source}/imgui_widgets.cpp
  ${_imgui_source}/misc/cpp/imgui_stdlib.cpp)
target_include_directories(penumbra_imgui SYSTEM PUBLIC ${_imgui_source})
# Not Penumbra's code: 1.86's C++20 deprecation warnings are not ours to fix.
target_compile_options(penumbra_imgui PRIVATE -w)
add_library(imgui::imgui ALIAS penumbra_imgui)
set(IMGUI_INCLUDE_DIRS ${_imgui_source})
set(IMGUI_BACKEND_SOURCES ${_imgui_source}/backends)
set(IMGUI_BACKEND_HEADERS ${_imgui_source}/backends)

# The Windows test executable (tests/CMakeLists.txt): Boost.Math's
# distributions for its chi-square checks (header-only), and Catch2: Debian's
# catch2 is a Linux static library, so its source package of the same version
# (scripts/setup.sh) is built here through its own CMake, which gives
# Catch2::Catch2WithMain as find_package(Catch2) does natively.
if(PENUMBRA_BUILD_TESTS)
  penumbra_cross_headers(${_farm}/boost boost)
  set(PENUMBRA_TEST_INCLUDE_DIRS ${_farm}/boost)
  set(_catch2_source ${PENUMBRA_WINDOWS_SOURCES}/catch2)
  if(NOT EXISTS ${_catch2_source}/CMakeLists.txt)
    message(FATAL_ERROR "Cross build: ${_catch2_source} is missing. scripts/setup.sh unpacks Debian's catch2 "
                        "source there (or configure with -DPENUMBRA_BUILD_TESTS=OFF)")
  endif()
  function(penumbra_add_catch2 source)
    set(BUILD_SHARED_LIBS OFF)
    set(CATCH_INSTALL_DOCS OFF)
    set(CATCH_INSTALL_EXTRAS OFF)
    add_subdirectory(${source} ${CMAKE_BINARY_DIR}/third_party/catch2 EXCLUDE_FROM_ALL SYSTEM)
  endfunction()
  penumbra_add_catch2(${_catch2_source})
endif()
