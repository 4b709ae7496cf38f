# The Python module (mrpt_plugins/python, docs/python.md), with the
# interpreter it was built for (Debian's, not whichever python3 is on PATH):
# python_module runs SLAM, localization, the scoring and the log conversion
# from Python and compares them, file by file, with rfir-slam, rfir-localize,
# rfir-eval and rfir-import; python_docs_example runs docs/python.md's code.
# The installed module is checked by downstream_package (import from the
# prefix with the documented PYTHONPATH).
if(TARGET rfir_python)
  add_test(NAME python_module
    COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${RFIR_PYTHON_BUILD_DIR}
      ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/python/test_rfir.py
      ${CMAKE_BINARY_DIR}/bin ${CMAKE_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/python_module)
  add_test(NAME python_docs_example
    COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${RFIR_PYTHON_BUILD_DIR} MPLBACKEND=Agg
      ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/python/run_docs_example.py
      ${CMAKE_SOURCE_DIR}/docs/python.md ${CMAKE_SOURCE_DIR}
      ${CMAKE_CURRENT_BINARY_DIR}/python_docs_example)
  set_tests_properties(python_module python_docs_example PROPERTIES TIMEOUT 120)
endif()
