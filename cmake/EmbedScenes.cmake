# Embeds the built-in scenes, scenes/<name>.toml, into the binary: `builtin:<name>` loads them and
# `glintlab scenes` lists them in the order given.
# glintlab_embed_scenes(<target> <name>...) adds a generated source defining
# glintlab::embedded_scenes(); a scenes/*.toml file missing from the list is a configure error.
include(${CMAKE_CURRENT_LIST_DIR}/EmbedFiles.cmake)

function(glintlab_embed_scenes target)
  set(root "${PROJECT_SOURCE_DIR}/scenes")
  file(GLOB present RELATIVE "${root}" CONFIGURE_DEPENDS "${root}/*.toml")
  set(files "")
  foreach(name IN LISTS ARGN)
    if(NOT EXISTS "${root}/${name}.toml")
      message(FATAL_ERROR "glintlab_embed_scenes: scenes/${name}.toml does not exist")
    endif()
    list(APPEND files "${name}.toml")
  endforeach()
  foreach(f IN LISTS present)
    if(NOT f IN_LIST files)
      message(FATAL_ERROR "scenes/${f} is not listed in glintlab_embed_scenes (src/scene/CMakeLists.txt)")
    endif()
  endforeach()
  glintlab_embed_files(${target} embedded_scenes list "${root}" ${files})
endfunction()
