# The MRPT plugin library: registration, and MRPT's installed rawlog-edit
# reading a project rawlog with it (skipped when rawlog-edit is missing).
rfir_add_test(test_plugin
  SOURCES test_plugin.cpp
  LIBS rfir_appcommon ${CMAKE_DL_LIBS})
add_dependencies(test_plugin rfir_mrpt_plugin)
