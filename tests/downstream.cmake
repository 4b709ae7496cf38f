# The installed package: install this build into a fresh prefix, build the
# project in tests/downstream against it (find_package(rfir) and rfir::maps
# only), run it, and run an installed program on its stock INI; with the
# Python module, import it from the prefix with the documented PYTHONPATH and
# check that a run from Python equals the installed rfir-slam's.
add_test(NAME downstream_package
  COMMAND ${CMAKE_COMMAND}
    -DRFIR_SOURCE_DIR=${CMAKE_SOURCE_DIR} -DRFIR_BINARY_DIR=${CMAKE_BINARY_DIR}
    -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/downstream
    -DCXX_COMPILER=${CMAKE_CXX_COMPILER} -DCXX_LAUNCHER=${CMAKE_CXX_COMPILER_LAUNCHER}
    "-DCXX_FLAGS=${CMAKE_CXX_FLAGS}" "-DEXE_LINKER_FLAGS=${CMAKE_EXE_LINKER_FLAGS}"
    -DPROJECT_VERSION=${PROJECT_VERSION}
    "-DPYTHON_EXECUTABLE=$<$<TARGET_EXISTS:rfir_python>:${Python3_EXECUTABLE}>"
    -P ${CMAKE_CURRENT_SOURCE_DIR}/downstream/run_downstream.cmake)
set_tests_properties(downstream_package PROPERTIES LABELS downstream TIMEOUT 600)
