# Embeds kernels/*.cl into the binary: each file becomes a raw string literal in a generated
# source with a name -> text table, so kernels are never read from disk at run time (the
# CLBlast habit). The generation runs at build time and re-runs when a .cl file changes.
function(svgm_embed_kernels target)
  file(GLOB kernel_files CONFIGURE_DEPENDS "${PROJECT_SOURCE_DIR}/kernels/*.cl")
  set(out "${CMAKE_CURRENT_BINARY_DIR}/kernels_embedded.cpp")
  string(REPLACE ";" "|" kernel_list "${kernel_files}")
  add_custom_command(
    OUTPUT "${out}"
    COMMAND ${CMAKE_COMMAND} -DOUT=${out} "-DFILES=${kernel_list}"
            -P "${PROJECT_SOURCE_DIR}/cmake/GenerateKernelSource.cmake"
    DEPENDS ${kernel_files} "${PROJECT_SOURCE_DIR}/cmake/GenerateKernelSource.cmake"
    COMMENT "Embedding OpenCL kernels"
    VERBATIM)
  target_sources(${target} PRIVATE "${out}")
endfunction()
