# Writes OUTPUT: one add_test a test case of EXECUTABLE (its ctest reporter's listing, tests/test_main.cpp),
# named PREFIX + the case's name, or one a named check of a case that has them (--tf-list-checks,
# tests/support.h), labelled LABELS + the words of its suite, with ENVIRONMENT, requiring FIXTURES (if any).
# cmake -D EXECUTABLE=... -D PREFIX=... -D LABELS=... -D ENVIRONMENT=... -D NAMED_CHECKS=ON|OFF [-D FIXTURES=...]
#       -D OUTPUT=...
#       -P list_doctest_cases.cmake
cmake_minimum_required(VERSION 3.22) # IN_LIST, bracket arguments
execute_process(COMMAND ${EXECUTABLE} --list-test-cases --reporters=ctest --no-intro=true
                OUTPUT_VARIABLE listing RESULT_VARIABLE result ERROR_VARIABLE errors)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${EXECUTABLE} --list-test-cases failed (${result}): ${errors}")
endif()
# With NAMED_CHECKS (every case of the executable made of named checks, support.h: the listing runs each
# case's setup), one test a check, PREFIX + the check's id.
set(check_listing "")
set(result 0)
if(NAMED_CHECKS)
  execute_process(COMMAND ${EXECUTABLE} --tf-list-checks --no-intro=true --no-version=true
                OUTPUT_VARIABLE check_listing RESULT_VARIABLE result ERROR_VARIABLE errors)
endif()
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${EXECUTABLE} --tf-list-checks failed (${result}): ${errors}")
endif()
string(REPLACE "\n" ";" check_lines "${check_listing}")
string(REPLACE "\n" ";" lines "${listing}")
set(script "")
set(names "")
foreach(line IN LISTS lines)
  if(NOT line MATCHES "^tf-test-case\t([^\t]+)\t(.*)$")
    continue()
  endif()
  set(case "${CMAKE_MATCH_1}")
  string(REPLACE " " ";" suite_labels "${CMAKE_MATCH_2}")
  # doctest's --test-case is a comma-separated list of wildcard patterns: a case name may hold none of them.
  if(case MATCHES "[,*?\\[\\]]")
    message(FATAL_ERROR "${EXECUTABLE}: test case '${case}' has one of , * ? [ ] (doctest filter syntax)")
  endif()
  set(labels ${LABELS} ${suite_labels})
  list(REMOVE_DUPLICATES labels)
  set(runs "") # "test name|extra argument" a ctest test
  foreach(check_line IN LISTS check_lines)
    if(check_line MATCHES "^tf-check\t([^\t]+)\t(.+)$" AND CMAKE_MATCH_1 STREQUAL case)
      list(APPEND runs "${PREFIX}${CMAKE_MATCH_2}|--subcase=${CMAKE_MATCH_2}")
    endif()
  endforeach()
  if(runs STREQUAL "")
    set(runs "${PREFIX}${case}|")
  endif()
  foreach(run IN LISTS runs)
    string(REGEX MATCH "^[^|]+" test "${run}")
    string(REGEX REPLACE "^[^|]+[|]" "" subcase "${run}")
    if(test IN_LIST names)
      message(FATAL_ERROR "${EXECUTABLE}: two tests named '${test}'")
    endif()
    list(APPEND names "${test}")
    string(APPEND script "add_test([==[${test}]==] [==[${EXECUTABLE}]==] [==[--test-case=${case}]==] ${subcase})\n"
           "set_tests_properties([==[${test}]==] PROPERTIES ENVIRONMENT [==[${ENVIRONMENT}]==]"
           " LABELS [==[${labels}]==] SKIP_REGULAR_EXPRESSION [==[SKIP: .* lacks ]==]"
           # A case runs in process, GPU work included: a hung device stops here, not at ctest's 1500 s. The
           # slowest case takes ~12 s on lavapipe with 2 cores.
           " TIMEOUT 300)\n")
    if(FIXTURES)
      string(APPEND script "set_tests_properties([==[${test}]==] PROPERTIES FIXTURES_REQUIRED [==[${FIXTURES}]==])\n")
    endif()
  endforeach()
endforeach()
if(names STREQUAL "")
  message(FATAL_ERROR "${EXECUTABLE} lists no test cases")
endif()
file(WRITE "${OUTPUT}" "${script}")
