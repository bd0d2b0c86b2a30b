# Embeds every shaders/*.glsl file into a generated C++ source as a raw string literal, so the
# binary runs from anywhere; `--shader-dir` swaps in the files on disk at run time.
set(FLOODLIGHT_SHADER_DIR "${CMAKE_SOURCE_DIR}/shaders")

function(floodlight_embed_shaders out_var)
  file(GLOB shader_files CONFIGURE_DEPENDS "${FLOODLIGHT_SHADER_DIR}/*.glsl")
  set(out "${CMAKE_BINARY_DIR}/generated/EmbeddedShaders.cpp")
  add_custom_command(
    OUTPUT "${out}"
    COMMAND ${CMAKE_COMMAND} -DOUT=${out} -DDIR=${FLOODLIGHT_SHADER_DIR}
            -P "${CMAKE_SOURCE_DIR}/cmake/GenerateEmbeddedShaders.cmake"
    DEPENDS ${shader_files} "${CMAKE_SOURCE_DIR}/cmake/GenerateEmbeddedShaders.cmake"
    COMMENT "Embedding shaders"
    VERBATIM)
  set(${out_var} "${out}" PARENT_SCOPE)
endfunction()
