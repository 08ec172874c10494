# shadowc_include_root(TARGET SCOPE FOLDER...): gives TARGET an include directory that holds only
# the named compiler/ folders (as symbolic links), so a stage sees the headers of the folders it
# owns and, through what it links, of the stages before it; nothing else. An `#include "emit/x.h"`
# in a file of an earlier stage then fails to compile instead of passing review
# (docs/integration.md "Layering").
function(shadowc_include_root target scope)
  set(root ${CMAKE_BINARY_DIR}/include_roots/${target})
  file(MAKE_DIRECTORY ${root})
  foreach(folder IN LISTS ARGN)
    if(NOT IS_DIRECTORY ${PROJECT_SOURCE_DIR}/compiler/${folder})
      message(FATAL_ERROR "shadowc_include_root(${target}): no folder compiler/${folder}")
    endif()
    file(CREATE_LINK ${PROJECT_SOURCE_DIR}/compiler/${folder} ${root}/${folder} SYMBOLIC)
  endforeach()
  target_include_directories(${target} ${scope} ${root})
endfunction()
