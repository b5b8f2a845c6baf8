# penumbra_embed_files(TARGET name FILES files...)
#
# Embeds text files (the built-in scenes) into a static library so the
# `penumbra` binary is self-contained. Lookup: penumbra::embedded::find(name)
# where name is the file name without directory. The library is also
# penumbra::<name without "penumbra_">, the name it is exported by.
function(penumbra_embed_files)
  cmake_parse_arguments(ARG "" "TARGET" "FILES" ${ARGN})
  set(out ${CMAKE_CURRENT_BINARY_DIR}/${ARG_TARGET}_embedded.cpp)
  set(abs_files)
  foreach(f ${ARG_FILES})
    get_filename_component(abs ${f} ABSOLUTE)
    list(APPEND abs_files ${abs})
  endforeach()
  add_custom_command(
    OUTPUT ${out}
    COMMAND ${CMAKE_COMMAND} -DOUT=${out} "-DFILES=${abs_files}"
            -P ${PROJECT_SOURCE_DIR}/cmake/EmbedFilesScript.cmake
    DEPENDS ${abs_files} ${PROJECT_SOURCE_DIR}/cmake/EmbedFilesScript.cmake
    COMMENT "Embedding ${ARG_TARGET}"
    VERBATIM)
  add_library(${ARG_TARGET} STATIC ${out})
  string(REGEX REPLACE "^penumbra_" "" export_name ${ARG_TARGET})
  add_library(penumbra::${export_name} ALIAS ${ARG_TARGET})
  set_target_properties(${ARG_TARGET} PROPERTIES EXPORT_NAME ${export_name})
  # util/embedded_files.h is the interface the generated source implements.
  target_link_libraries(${ARG_TARGET} PUBLIC penumbra::util)
endfunction()
