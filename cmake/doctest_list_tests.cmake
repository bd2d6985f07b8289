# Writes OUTPUT, a CTest script adding one test per doctest test case of EXECUTABLE, from a single
# `--list-test-cases --reporters=xml` run (cmake/doctest_discovery.cmake). Run with cmake -P.
execute_process(
  COMMAND "${EXECUTABLE}" --list-test-cases --reporters=xml
  WORKING_DIRECTORY "${WORKING_DIRECTORY}"
  OUTPUT_VARIABLE listing
  RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "listing the test cases of ${EXECUTABLE} failed (${status}):\n${listing}")
endif()

# CMake's lists split at semicolons, and every escaped character ends in one: the listing is held
# with semicolons swapped for the unit separator until a name is unescaped.
string(ASCII 31 unit)
string(REPLACE ";" "${unit}" listing "${listing}")

# The XML reporter escapes &, <, " (and may escape > and '); one test case per line.
function(unescape_xml out text)
  string(REPLACE "${unit}" ";" text "${text}")
  string(REPLACE "&quot;" "\"" text "${text}")
  string(REPLACE "&apos;" "'" text "${text}")
  string(REPLACE "&lt;" "<" text "${text}")
  string(REPLACE "&gt;" ">" text "${text}")
  string(REPLACE "&amp;" "&" text "${text}")
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

set(script "")
set(count 0)
string(REGEX MATCHALL "<TestCase [^\n]*/>" cases "${listing}")
foreach(case IN LISTS cases)
  if(NOT case MATCHES " name=\"([^\"]*)\"")
    message(FATAL_ERROR "a test case of ${EXECUTABLE} without a name: ${case}")
  endif()
  unescape_xml(name "${CMAKE_MATCH_1}")
  set(labels ${LABELS})
  if(case MATCHES " testsuite=\"([^\"]*)\"")
    unescape_xml(suite "${CMAKE_MATCH_1}")
    list(APPEND labels "${suite}")
  endif()
  # doctest splits a --test-case filter at commas; an escaped comma is part of the name.
  string(REPLACE "," "\\," filter "${name}")
  string(APPEND script
    "add_test([==[${PREFIX}${name}]==] [==[${EXECUTABLE}]==] [==[--test-case=${filter}]==])\n"
    "set_tests_properties([==[${PREFIX}${name}]==] PROPERTIES WORKING_DIRECTORY [==[${WORKING_DIRECTORY}]==]")
  if(labels)
    string(APPEND script " LABELS [==[${labels}]==]")
  endif()
  string(APPEND script ")\n")
  math(EXPR count "${count} + 1")
endforeach()
if(count EQUAL 0)
  message(FATAL_ERROR "${EXECUTABLE} lists no test case")
endif()
file(WRITE "${OUTPUT}" "${script}")
