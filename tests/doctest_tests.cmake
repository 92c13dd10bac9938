# tf_add_doctest(NAME [NAMED_CHECKS] LABELS label... [FIXTURES fixture...]): the test executable test_NAME from test_NAME.cpp
# (doctest, one main in the support library), each of its TEST_CASEs its own ctest test NAME.CASE, or with
# NAMED_CHECKS (every case made of named checks, tests/support.h) each check NAME.CHECK, labelled with the
# LABELS given here plus the words of the case's TEST_SUITE. The cases are listed when the executable
# is built (its --list-test-cases, tests/list_doctest_cases.cmake), so a new case needs no re-configure.
# Every test runs with the validation layers on (TEXFILTER_VALIDATE=1): any message fails it. A case that
# prints "SKIP: <device> lacks <feature>" (and returns) is reported as skipped, not passed. FIXTURES: every
# test of the executable requires them (FIXTURES_REQUIRED: their setup runs first).
function(tf_add_doctest name)
  cmake_parse_arguments(arg "NAMED_CHECKS" "" "LABELS;FIXTURES" ${ARGN})
  set(target test_${name})
  add_executable(${target} ${target}.cpp)
  target_link_libraries(${target} PRIVATE texfilter_test_support)
  target_compile_options(${target} PRIVATE ${TF_WARNINGS})
  # The test list is written when the executable links: relink when the script that writes it changes.
  set_property(TARGET ${target} APPEND PROPERTY LINK_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/list_doctest_cases.cmake)

  set(tests_file ${CMAKE_CURRENT_BINARY_DIR}/${target}_tests.cmake)
  add_custom_command(
    TARGET ${target} POST_BUILD
    BYPRODUCTS ${tests_file}
    COMMAND ${CMAKE_COMMAND} -D "EXECUTABLE=$<TARGET_FILE:${target}>" -D "PREFIX=${name}."
            -D "LABELS=${arg_LABELS}" -D "ENVIRONMENT=TEXFILTER_VALIDATE=1" -D "NAMED_CHECKS=${arg_NAMED_CHECKS}"
            -D "FIXTURES=${arg_FIXTURES}"
            -D "OUTPUT=${tests_file}"
            -P ${CMAKE_CURRENT_SOURCE_DIR}/list_doctest_cases.cmake
    VERBATIM)
  set(include_file ${CMAKE_CURRENT_BINARY_DIR}/${target}_include.cmake)
  file(WRITE ${include_file}
       "if(EXISTS \"${tests_file}\")\n"
       "  include(\"${tests_file}\")\n"
       "else()\n"
       "  add_test(${name}.NOT_BUILT ${name}.NOT_BUILT)\n"
       "endif()\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${include_file})
endfunction()
