# The layering held by the build (docs/integration.md "Layering"): planted_include.cpp is compiled
# with a stage target's include directories (its own include root and those of the stages it
# links). An include of a later stage's header must fail for exactly that reason (the test passes
# only when the compiler says the header is not found); its sibling includes a header the stage
# may see and must compile, so the failures are not from broken flags.
set(planted_src ${CMAKE_CURRENT_SOURCE_DIR}/architecture/planted/planted_include.cpp)
function(shadowc_planted_include name stage header expect)
  set(test architecture.planted_include.${name})
  add_test(NAME ${test}
           COMMAND ${CMAKE_CXX_COMPILER} -std=c++20 -fsyntax-only
                   "-I$<JOIN:$<TARGET_PROPERTY:${stage},INCLUDE_DIRECTORIES>,;-I>"
                   -DPLANTED_HEADER=${header} ${planted_src}
           COMMAND_EXPAND_LISTS)
  set_tests_properties(${test} PROPERTIES LABELS architecture)
  if(expect STREQUAL "fails")
    string(REPLACE "." "\\." header_re ${header})
    set_tests_properties(${test} PROPERTIES PASS_REGULAR_EXPRESSION "${header_re}.*(No such file|not found)")
  endif()
endfunction()
# A later stage's header, from each stage: not found.
shadowc_planted_include(dsl_cannot_see_spec shadowc_dsl spec/filter_spec.h fails)
shadowc_planted_include(spec_cannot_see_plan shadowc_spec plan/planner.h fails)
shadowc_planted_include(plan_cannot_see_emit shadowc_plan emit/filter_emitter.h fails)
shadowc_planted_include(emit_cannot_see_driver shadowc_emit driver/driver.h fails)
shadowc_planted_include(emit_cannot_see_backend shadowc_emit backend/spirv_backend.h fails)
shadowc_planted_include(plan_cannot_see_backend shadowc_plan backend/spirv_backend.h fails)
# The siblings: the stage's own and an earlier stage's headers compile with the same flags.
shadowc_planted_include(spec_sees_dsl shadowc_spec dsl/parser.h compiles)
shadowc_planted_include(plan_sees_spec shadowc_plan spec/filter_spec.h compiles)
shadowc_planted_include(emit_sees_plan shadowc_emit plan/planner.h compiles)
shadowc_planted_include(driver_sees_emit shadowc_driver emit/filter_emitter.h compiles)
shadowc_planted_include(driver_sees_backend shadowc_driver backend/spirv_backend.h compiles)
