# shadowc_add_filters: compile filter descriptions at build time (docs/integration.md).
#
#   shadowc_add_filters(TARGET <tgt> FILES <a.shadow>... OUTPUT_DIR <dir>
#                       [EMIT <kind>...] [OPTIONS <flag>...])
#
# Each FILES entry <stem>.shadow is compiled by `shadowc compile <file> -o <dir>/<stem> -MD -MT
# <dir>/<stem>/<stem>.d --emit <kinds>` into its own directory, so one edited description reruns
# exactly its own command. The depfile (DEPFILE) names only the .d as its target: Ninja rejects a
# depfile naming outputs the rule does not declare, and pass file names are only known after
# planning. EMIT takes kinds as a list or comma-separated (glsl;spirv or glsl,spirv; default: every
# kind the compiler writes by default) and passes them through to --emit unchanged, so kinds the
# compiler learns later work here too; the kinds listed in _shadowc_kind_outputs below also become
# declared OUTPUTs (the ones whose names are known before compiling). OPTIONS go to the command
# line as they are (-O0, -Werror).
#
# <tgt> is created (built by ALL) when it does not exist; an existing target (say, the engine's
# executable) instead depends on a helper target <tgt>_shadowc_filters, so the outputs are there
# before it builds; for an INTERFACE library, which never builds, the helper is also built by ALL. The compiler is shadowc::shadowc: the installed one after find_package(shadowc),
# the in-tree executable after add_subdirectory (the command then rebuilds when shadowc changes).
#
# The filter's name (`filter <name> {`) must be the file's stem: the compiler names the depfile
# <name>.d and the lookup <name>_lookup.glsl, and both paths are needed at configure time.
include_guard(GLOBAL)

# Output names (relative to the filter's directory) that a kind always produces. Pass shaders
# are named by the plan, so .glsl/.spv per pass are not declared; they still rebuild with the rest.
function(_shadowc_kind_outputs kind name out_var)
  if(kind STREQUAL "manifest")
    set(${out_var} manifest.json PARENT_SCOPE)
  elseif(kind STREQUAL "glsl")
    set(${out_var} ${name}_lookup.glsl PARENT_SCOPE)
  elseif(kind STREQUAL "cpp")
    set(${out_var} ${name}.h PARENT_SCOPE)
  elseif(kind STREQUAL "hlsl")
    set(${out_var} ${name}_lookup.hlsl PARENT_SCOPE)
  elseif(kind STREQUAL "msl")
    set(${out_var} ${name}_lookup.metal PARENT_SCOPE)
  else()
    set(${out_var} "" PARENT_SCOPE)
  endif()
endfunction()

function(shadowc_add_filters)
  cmake_parse_arguments(PARSE_ARGV 0 arg "" "TARGET;OUTPUT_DIR" "FILES;EMIT;OPTIONS")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "shadowc_add_filters: unknown arguments: ${arg_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT arg_TARGET OR NOT arg_FILES OR NOT arg_OUTPUT_DIR)
    message(FATAL_ERROR "shadowc_add_filters: TARGET, FILES and OUTPUT_DIR are required")
  endif()
  if(NOT TARGET shadowc::shadowc)
    message(FATAL_ERROR "shadowc_add_filters: no shadowc::shadowc target "
                        "(use find_package(shadowc) or add_subdirectory(<shadowc source>) first)")
  endif()
  set(emit_args "")
  set(kinds glsl spirv manifest)  # the compiler's default --emit
  if(arg_EMIT)
    string(REPLACE "," ";" kinds "${arg_EMIT}")
    list(JOIN kinds "," emit_csv)
    set(emit_args --emit ${emit_csv})
  endif()
  get_filename_component(out_root "${arg_OUTPUT_DIR}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_BINARY_DIR}")

  set(all_outputs "")
  foreach(file IN LISTS arg_FILES)
    get_filename_component(src "${file}" ABSOLUTE)
    get_filename_component(stem "${src}" NAME_WE)
    if(NOT EXISTS "${src}")
      message(FATAL_ERROR "shadowc_add_filters: ${src}: no such file")
    endif()
    # Configure-time check of the name rule above (the compiler checks everything else).
    file(STRINGS "${src}" decl REGEX "^[ \t]*filter[ \t]+[A-Za-z_][A-Za-z0-9_]*" LIMIT_COUNT 1)
    string(REGEX REPLACE "^[ \t]*filter[ \t]+([A-Za-z_][A-Za-z0-9_]*).*" "\\1" name "${decl}")
    if(NOT name STREQUAL stem)
      message(FATAL_ERROR "shadowc_add_filters: ${src}: the filter is named '${name}'; "
                          "name the file ${name}.shadow (the outputs are named after the filter)")
    endif()
    set(dir "${out_root}/${stem}")
    set(outputs "${dir}/${stem}.d")
    foreach(kind IN LISTS kinds)
      _shadowc_kind_outputs(${kind} ${stem} names)
      foreach(n IN LISTS names)
        list(APPEND outputs "${dir}/${n}")
      endforeach()
    endforeach()
    file(RELATIVE_PATH shown "${CMAKE_BINARY_DIR}" "${dir}")
    add_custom_command(
      OUTPUT ${outputs}
      COMMAND shadowc::shadowc compile "${src}" -o "${dir}" -MD -MT "${dir}/${stem}.d" ${emit_args} ${arg_OPTIONS}
      DEPENDS "${src}" "$<TARGET_FILE:shadowc::shadowc>"
      DEPFILE "${dir}/${stem}.d"
      COMMENT "shadowc: compiling ${stem}.shadow -> ${shown}"
      VERBATIM COMMAND_EXPAND_LISTS)
    list(APPEND all_outputs ${outputs})
  endforeach()

  if(TARGET ${arg_TARGET})
    # An INTERFACE library never builds, so a helper that is only its dependency would never run:
    # there the helper is built by ALL too (and targets linking the library still wait for it).
    get_target_property(type ${arg_TARGET} TYPE)
    set(all "")
    if(type STREQUAL "INTERFACE_LIBRARY")
      set(all ALL)
    endif()
    add_custom_target(${arg_TARGET}_shadowc_filters ${all} DEPENDS ${all_outputs})
    add_dependencies(${arg_TARGET} ${arg_TARGET}_shadowc_filters)
  else()
    add_custom_target(${arg_TARGET} ALL DEPENDS ${all_outputs})
  endif()
endfunction()
