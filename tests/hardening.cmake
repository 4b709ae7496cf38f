# Corrupt rawlogs: the bounded reader, MRPT's classes guarded, the reproducers
# (tests/data/repro, tests/data/fuzz_crashes) through every program, and a
# truncation / byte-flip sweep.
rfir_add_test(test_rawlog_hardening
  SOURCES test_rawlog_bounded.cpp test_rawlog_hardening.cpp test_checked_classes.cpp
          test_rawlog_finite.cpp test_gz_input.cpp
  LIBS rfir_appcommon)
foreach(prog rfir-import rfir-slam rfir-eval rfir-localize)
  if(TARGET ${prog})
    add_dependencies(test_rawlog_hardening ${prog})
  endif()
endforeach()
