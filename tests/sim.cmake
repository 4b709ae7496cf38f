# rfir_sim: INI handling, sensor models against ground truth, determinism,
# trajectories, kidnapping and odometry noise; the rfir-sim program.
if(TARGET rfir_sim)
  rfir_add_test(test_sim
    SOURCES test_sim_config.cpp test_sim_models.cpp test_sim_outputs.cpp
            test_sim_read_model.cpp test_sim_faults.cpp test_sim_faults_ir.cpp
    LIBS rfir_sim rfir_ir)
  add_dependencies(test_sim rfir-sim)
endif()
# Every stock fault simulation through the text log and back (rfir-import's
# conversions).
if(TARGET rfir_sim)
  rfir_add_test(test_sim_faults_roundtrip
    SOURCES test_sim_faults_roundtrip.cpp
    LIBS rfir_sim rfir_appcommon)
endif()
