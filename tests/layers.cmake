# The library graph points one way (scripts/check_layers.sh, read from CMake's
# --graphviz in a configure of its own): no library links its own layer or one
# above, no program folder declares a library.
add_test(NAME layers
  COMMAND bash ${CMAKE_SOURCE_DIR}/scripts/check_layers.sh ${CMAKE_BINARY_DIR}/test_out/layers)
set_tests_properties(layers PROPERTIES TIMEOUT 120)
