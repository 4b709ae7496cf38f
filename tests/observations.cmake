rfir_add_test(test_observations
  SOURCES test_observations.cpp test_ir_codes.cpp test_ir_decoder.cpp
  LIBS rfir_observations mrpt::io)
