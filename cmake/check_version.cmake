# cmake -DBIN=... -DSRC=... -DVERSION=... -DPACKAGE_VERSION_FILE=... -P check_version.cmake
# (the ctest version_everywhere, tests/version.cmake).
# Every program of apps/ (built in BIN) prints VERSION on --version (exit 0),
# and the package version file declares VERSION.
file(GLOB app_dirs LIST_DIRECTORIES true ${SRC}/apps/rfir-*)
set(failures 0)
set(n 0)
foreach(dir ${app_dirs})
  if(NOT IS_DIRECTORY ${dir})
    continue()
  endif()
  get_filename_component(prog ${dir} NAME)
  math(EXPR n "${n} + 1")
  if(NOT EXISTS ${BIN}/${prog})
    message(SEND_ERROR "${prog}: not built in ${BIN}")
    math(EXPR failures "${failures} + 1")
    continue()
  endif()
  execute_process(COMMAND ${BIN}/${prog} --version
    OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
  # TCLAP prints "<program>  version: <version>".
  string(REGEX MATCH "version: ([^ \n]+)" found "${out}")
  if(NOT rc EQUAL 0 OR NOT CMAKE_MATCH_1 STREQUAL VERSION)
    message(SEND_ERROR "${prog} --version: exit ${rc}, says '${CMAKE_MATCH_1}', "
                       "CMake's project(VERSION) is ${VERSION}: ${out}${err}")
    math(EXPR failures "${failures} + 1")
  else()
    message(STATUS "${prog} --version: ${CMAKE_MATCH_1}")
  endif()
endforeach()
if(n LESS 10)
  message(SEND_ERROR "found only ${n} programs under ${SRC}/apps")
endif()
file(READ ${PACKAGE_VERSION_FILE} pv)
string(REGEX MATCH "set\\(PACKAGE_VERSION \"([^\"]+)\"\\)" found "${pv}")
if(NOT CMAKE_MATCH_1 STREQUAL VERSION)
  message(SEND_ERROR "${PACKAGE_VERSION_FILE}: PACKAGE_VERSION '${CMAKE_MATCH_1}', not ${VERSION}")
endif()
