# Every INI key of the programs: the reference table in docs and a sweep of
# bad values over the stock INIs, through the loaders in process.
if(TARGET rfir_sim AND TARGET rfir_localize_core)
  rfir_add_test(test_ini_reference
    SOURCES test_ini_reference.cpp ini_keys.cpp
    LIBS rfir_slam rfir_sim rfir_localize_core rfir_appcommon mrpt::io)
endif()
rfir_add_test(test_output_set
  SOURCES test_output_set.cpp
  LIBS rfir_appcommon)
