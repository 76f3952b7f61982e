# tests/ci_sets.cmake - what .ci/test needs to know about the tests beyond
# their labels (issue 36 item 4: the test command within about 10 minutes).
#
# lamina_ci_properties(), called at the end of each CMakeLists.txt that adds
# tests (a test's properties can only be set from its own directory):
# - the `asan` label on the physics / visual / analysis tests that
#   tests/asan_set.tsv marks `asan`: the sanitizer stage runs them with the
#   unit, bad, security, cli and io tests; the others' src/ lines are all run
#   by that set (scripts/ci/asan_set.py measures it; docs/contributing.md);
# - COST from tests/test_costs.tsv (seconds measured on two cores, normal and
#   sanitized build): ctest -j starts the longest tests first even on a clean
#   clone without Testing/Temporary/CTestCostData.txt, so no long test starts
#   last and leaves one core idle at the end of the stage.
set(LAMINA_CI_SETS_DIR ${CMAKE_CURRENT_LIST_DIR})

function(lamina_ci_properties)
  get_property(here DIRECTORY PROPERTY TESTS)
  file(STRINGS ${LAMINA_CI_SETS_DIR}/asan_set.tsv picks REGEX "^[^#].*\tasan$")
  foreach(line IN LISTS picks)
    string(REGEX REPLACE "\tasan$" "" name "${line}")
    if(name IN_LIST here)
      set_property(TEST ${name} APPEND PROPERTY LABELS asan)
    endif()
  endforeach()
  file(STRINGS ${LAMINA_CI_SETS_DIR}/test_costs.tsv costs REGEX "^[^#]")
  foreach(line IN LISTS costs)
    string(REPLACE "\t" ";" fields "${line}")
    list(GET fields 0 name)
    if(LAMINA_SANITIZE OR LAMINA_FUZZ)
      list(GET fields 2 cost)
    else()
      list(GET fields 1 cost)
    endif()
    if(name IN_LIST here)
      set_property(TEST ${name} PROPERTY COST ${cost})
    endif()
  endforeach()
endfunction()
