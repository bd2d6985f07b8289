# lightpath_discover_tests(TARGET PREFIX <prefix> [LABELS <label>...]): registers each doctest test
# case of TARGET with CTest as <prefix><name>, labelled with its doctest suite (`statistical`, which
# scripts/test leaves out of the sanitizer stage) and with LABELS. Like doctest's own
# doctest_discover_tests, the list is read from the built binary after each link, so adding a test
# case needs no CMake run; unlike its ADD_LABELS, which runs the binary once more per test case to
# ask its suite (hundreds of starts per build tree, each costly under AddressSanitizer), one XML
# listing gives every name with its suite (cmake/doctest_list_tests.cmake).
function(lightpath_discover_tests target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "PREFIX" "LABELS")
  set(tests_file "${CMAKE_CURRENT_BINARY_DIR}/${target}_tests.cmake")
  set(include_file "${CMAKE_CURRENT_BINARY_DIR}/${target}_include.cmake")
  add_custom_command(TARGET ${target} POST_BUILD
    BYPRODUCTS "${tests_file}"
    COMMAND "${CMAKE_COMMAND}"
            -D "EXECUTABLE=$<TARGET_FILE:${target}>"
            -D "WORKING_DIRECTORY=${CMAKE_CURRENT_BINARY_DIR}"
            -D "PREFIX=${arg_PREFIX}"
            -D "LABELS=${arg_LABELS}"
            -D "OUTPUT=${tests_file}"
            -P "${PROJECT_SOURCE_DIR}/cmake/doctest_list_tests.cmake"
    VERBATIM)
  # Until the first build, the missing list shows as a failing placeholder rather than no tests.
  file(WRITE "${include_file}"
    "if(EXISTS \"${tests_file}\")\n"
    "  include(\"${tests_file}\")\n"
    "else()\n"
    "  add_test(${target}_NOT_BUILT ${target}_NOT_BUILT)\n"
    "endif()\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES "${include_file}")
endfunction()
