# The command-line conventions shared by every program (rfir/common/cli.h):
# the helpers on their own, then every rfir-* program in bin/ run with
# --help, --version, an unknown option, malformed numbers and a missing
# required option (tests/cli_conventions.sh), then the options every
# program shares (--set, -q, --seed) on real runs.
rfir_add_test(test_cli
  SOURCES test_cli.cpp
  LIBS rfir_appcommon)
add_test(NAME cli_conventions
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli_conventions.sh
          ${CMAKE_BINARY_DIR}/bin ${CMAKE_SOURCE_DIR} basic)
set_tests_properties(cli_conventions PROPERTIES TIMEOUT 600)
# The same script's second part: bad --set edits in every program that takes
# --set, -q on short real runs, --set / --seed of the experiment programs.
add_test(NAME cli_options
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli_conventions.sh
          ${CMAKE_BINARY_DIR}/bin ${CMAKE_SOURCE_DIR} options)
set_tests_properties(cli_options PROPERTIES TIMEOUT 600)
