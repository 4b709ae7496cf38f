# Simulated rawlogs (every stock sim INI, shortened) through the text log and
# back: identical observations and header, no lossy export.
if(TARGET rfir_sim)
  rfir_add_test(test_roundtrip
    SOURCES test_roundtrip.cpp
    LIBS rfir_sim rfir_appcommon)
endif()
