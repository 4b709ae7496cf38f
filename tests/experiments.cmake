# Smoke test of rfir-experiments: one tiny row end to end (simulate, every
# method, score, JSON / markdown / figure), checked by smoke_check.cmake.
if(TARGET rfir-experiments)
  add_test(NAME experiments_smoke
    COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:rfir-experiments>
            -DOUT=${CMAKE_BINARY_DIR}/test_out/experiments_smoke
            -DCFG=${CMAKE_SOURCE_DIR}/config_ini
            -P ${CMAKE_SOURCE_DIR}/apps/rfir-experiments/smoke_check.cmake)
  set_tests_properties(experiments_smoke PROPERTIES TIMEOUT 180)
  # An unknown row is rejected with a non-zero exit.
  add_test(NAME experiments_bad_row
    COMMAND rfir-experiments --rows no_such_row --out-dir ${CMAKE_BINARY_DIR}/test_out/x)
  set_tests_properties(experiments_bad_row PROPERTIES WILL_FAIL TRUE)
  # --jobs 2, and a manifest run by xargs -P 2 then merged, give --jobs 1's
  # results.json; --merge refuses a missing run or another sweep's
  # (sweep_check.cmake).
  add_test(NAME experiments_sweep
    COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:rfir-experiments>
            -DOUT=${CMAKE_BINARY_DIR}/test_out/experiments_sweep
            -DCFG=${CMAKE_SOURCE_DIR}/config_ini
            -P ${CMAKE_SOURCE_DIR}/apps/rfir-experiments/sweep_check.cmake)
  set_tests_properties(experiments_sweep PROPERTIES TIMEOUT 180)
endif()
