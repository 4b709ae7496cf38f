# The tutorial (docs/tutorial.md) as a user runs it: every sh block of the
# page in a scratch folder against this build (tests/run_tutorial.sh), then
# the files and messages the page names.
add_test(NAME tutorial
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/run_tutorial.sh ${CMAKE_BINARY_DIR} ${CMAKE_SOURCE_DIR})
set_tests_properties(tutorial PROPERTIES TIMEOUT 300)
