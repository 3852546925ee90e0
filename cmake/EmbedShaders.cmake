# Embeds every file under shaders/ into the binary, so the CLI runs from any directory.
# glintlab_embed_shaders(<target>) adds a generated source defining glintlab::embedded_shaders().
include(${CMAKE_CURRENT_LIST_DIR}/EmbedFiles.cmake)

function(glintlab_embed_shaders target)
  file(GLOB_RECURSE shader_files RELATIVE "${PROJECT_SOURCE_DIR}/shaders" CONFIGURE_DEPENDS
       "${PROJECT_SOURCE_DIR}/shaders/*.glsl" "${PROJECT_SOURCE_DIR}/shaders/*.vert"
       "${PROJECT_SOURCE_DIR}/shaders/*.frag" "${PROJECT_SOURCE_DIR}/shaders/*.comp")
  list(SORT shader_files)
  glintlab_embed_files(${target} embedded_shaders map "${PROJECT_SOURCE_DIR}/shaders" ${shader_files})
endfunction()
