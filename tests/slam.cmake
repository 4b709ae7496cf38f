# rfir_slam: unit tests, and accuracy tests on short simulated runs.
rfir_add_test(test_slam_units
  SOURCES test_slam_units.cpp
  LIBS rfir_slam)
if(TARGET rfir_sim)
  rfir_add_test(test_slam_accuracy
    SOURCES test_slam_accuracy.cpp
    LIBS rfir_slam rfir_sim rfir_eval)
  # End to end through the program (built by the same build).
  rfir_add_test(test_slam_app
    SOURCES test_slam_app.cpp
    LIBS rfir_slam rfir_sim rfir_eval)
  add_dependencies(test_slam_app rfir-slam)
endif()
if(TARGET rfir_sim)
  # The experiments of docs/slam.md: DISABLED_ tests, run by hand.
  rfir_add_test(test_slam_experiments
    SOURCES test_slam_experiments.cpp
    LIBS rfir_slam rfir_sim rfir_eval)
endif()
if(TARGET rfir_sim)
  rfir_add_test(test_graph_smoother
    SOURCES test_graph_smoother.cpp
    LIBS rfir_slam rfir_sim rfir_eval)
endif()
if(TARGET rfir_sim)
  # Loop closure by smoothing at the kidnap check's triggers (issue 12).
  rfir_add_test(test_loop_closure
    SOURCES test_loop_closure.cpp
    LIBS rfir_slam rfir_sim rfir_eval)
endif()
if(TARGET rfir_sim)
  # Ghost reads, slips, dead readers, asynchronous polls (issue 12).
  rfir_add_test(test_slam_robust
    SOURCES test_slam_robust.cpp
    LIBS rfir_slam rfir_sim rfir_eval)
endif()
if(TARGET rfir_sim)
  # The smoother after a kidnapping, with empty polls, on the fault INIs.
  rfir_add_test(test_graph_smoother_robust
    SOURCES test_graph_smoother_robust.cpp
    LIBS rfir_slam rfir_sim rfir_eval)
endif()
# The map correction's algebra (tag_correlation.h) against the Kalman update.
rfir_add_test(test_map_correction
  SOURCES test_map_correction.cpp
  LIBS rfir_slam)
if(TARGET rfir_sim)
  # The per-particle heading drift of [motion] (issue 12: biased odometry).
  rfir_add_test(test_heading_drift
    SOURCES test_heading_drift.cpp
    LIBS rfir_slam rfir_sim rfir_eval)
  # The kidnap check's open runs keep no new tag out of the map (issue 12).
  rfir_add_test(test_floor_mapping
    SOURCES test_floor_mapping.cpp
    LIBS rfir_slam rfir_sim rfir_eval)
endif()
