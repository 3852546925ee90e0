# Embeds every file under shaders/ into the binary, so the CLI runs from any directory.
# glintlab_embed_shaders(<target>) adds a generated source defining glintlab::embedded_shaders().
function(glintlab_embed_shaders target)
  file(GLOB_RECURSE shader_files CONFIGURE_DEPENDS
       "${PROJECT_SOURCE_DIR}/shaders/*.glsl" "${PROJECT_SOURCE_DIR}/shaders/*.vert"
       "${PROJECT_SOURCE_DIR}/shaders/*.frag" "${PROJECT_SOURCE_DIR}/shaders/*.comp")
  set(out "${CMAKE_CURRENT_BINARY_DIR}/embedded_shaders.cpp")
  add_custom_command(
    OUTPUT "${out}"
    COMMAND ${CMAKE_COMMAND} -DROOT=${PROJECT_SOURCE_DIR}/shaders -DOUT=${out}
            -P "${PROJECT_SOURCE_DIR}/cmake/GenerateShaderSource.cmake"
    DEPENDS ${shader_files} "${PROJECT_SOURCE_DIR}/cmake/GenerateShaderSource.cmake"
    COMMENT "Embedding GLSL sources")
  target_sources(${target} PRIVATE "${out}")
endfunction()
