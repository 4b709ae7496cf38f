# One version number, CMake's project(VERSION): every program's --version and
# the package's version file (rfirConfigVersion.cmake) say it
# (cmake/check_version.cmake). The code has it from rfir/version.h only.
add_test(NAME version_everywhere
  COMMAND ${CMAKE_COMMAND} -DBIN=${CMAKE_BINARY_DIR}/bin -DSRC=${CMAKE_SOURCE_DIR}
          -DVERSION=${PROJECT_VERSION}
          -DPACKAGE_VERSION_FILE=${PROJECT_BINARY_DIR}/rfirConfigVersion.cmake
          -P ${CMAKE_SOURCE_DIR}/cmake/check_version.cmake)
