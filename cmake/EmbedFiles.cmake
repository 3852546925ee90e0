# glintlab_embed_files(<target> <function> map|list <root> <files relative to root>...) adds a
# generated source defining glintlab::<function>(): the files' texts by path (map) or by stem in
# the given order (list). cmake/GenerateEmbeddedSource.cmake writes it.
include_guard(GLOBAL)

function(glintlab_embed_files target function container root)
  set(out "${CMAKE_CURRENT_BINARY_DIR}/${function}.cpp")
  list(TRANSFORM ARGN PREPEND "${root}/" OUTPUT_VARIABLE absolute)
  list(JOIN ARGN "|" files)
  add_custom_command(
    OUTPUT "${out}"
    COMMAND ${CMAKE_COMMAND} -DROOT=${root} -DOUT=${out} -DFUNCTION=${function} -DCONTAINER=${container}
            "-DFILES=${files}" -P "${PROJECT_SOURCE_DIR}/cmake/GenerateEmbeddedSource.cmake"
    DEPENDS ${absolute} "${PROJECT_SOURCE_DIR}/cmake/GenerateEmbeddedSource.cmake"
    COMMENT "Embedding ${function}"
    VERBATIM)
  target_sources(${target} PRIVATE "${out}")
endfunction()
