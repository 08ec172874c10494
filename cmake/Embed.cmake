# shadowc_embed(TARGET NAMESPACE BASE_DIR FILES...): compiles text files into a static library
# exposing   std::string_view <NAMESPACE>::find(std::string_view relativePath)   and
#            std::span<const shadowc::EmbeddedFile> <NAMESPACE>::all()
# so that templates stay real .glsl files in the tree (Filament's matc embeds its shader
# sources the same way) and the binary needs no files at run time.
# The header every embedded set shares (embed/embedded_file.h), alone in its include root.
add_library(shadowc_embed_header INTERFACE)
shadowc_include_root(shadowc_embed_header INTERFACE embed)

function(shadowc_embed target ns base_dir)
  set(out_cpp ${CMAKE_CURRENT_BINARY_DIR}/${target}_embedded.cpp)
  set(inputs ${ARGN})
  add_custom_command(
    OUTPUT ${out_cpp}
    COMMAND ${CMAKE_COMMAND} -DOUT=${out_cpp} -DNS=${ns} -DBASE=${base_dir} "-DFILES=${inputs}"
            -P ${PROJECT_SOURCE_DIR}/cmake/EmbedScript.cmake
    DEPENDS ${inputs} ${PROJECT_SOURCE_DIR}/cmake/EmbedScript.cmake
    COMMENT "Embedding ${target} (${ns})"
    VERBATIM)
  add_library(${target} STATIC ${out_cpp})
  target_link_libraries(${target} PUBLIC shadowc_embed_header)
endfunction()
