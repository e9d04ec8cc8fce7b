# Embeds text files into the binary at build time: each file becomes a raw string literal in a
# generated source with a name -> text table, so they are never read from disk at run time (the
# CLBlast habit). Used for kernels/*.cl (svgm::embedded_kernels) and configs/default.yaml
# (svgm::embedded_configs). The generation re-runs when a file changes.
function(svgm_embed_files target pattern function output_name)
  file(GLOB files CONFIGURE_DEPENDS "${pattern}")
  set(out "${CMAKE_CURRENT_BINARY_DIR}/${output_name}")
  string(REPLACE ";" "|" file_list "${files}")
  add_custom_command(
    OUTPUT "${out}"
    COMMAND ${CMAKE_COMMAND} -DOUT=${out} "-DFILES=${file_list}" -DFUNCTION=${function}
            -P "${PROJECT_SOURCE_DIR}/cmake/GenerateKernelSource.cmake"
    DEPENDS ${files} "${PROJECT_SOURCE_DIR}/cmake/GenerateKernelSource.cmake"
    COMMENT "Embedding ${output_name}"
    VERBATIM)
  target_sources(${target} PRIVATE "${out}")
endfunction()

function(svgm_embed_kernels target)
  svgm_embed_files(${target} "${PROJECT_SOURCE_DIR}/kernels/*.cl" embedded_kernels kernels_embedded.cpp)
  svgm_embed_files(${target} "${PROJECT_SOURCE_DIR}/configs/*.yaml" embedded_configs configs_embedded.cpp)
endfunction()
