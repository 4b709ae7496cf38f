# Evaluation metrics, tables/JSON, PNG figures, and the rfir-eval program.
rfir_add_test(test_eval
  SOURCES test_eval_metrics.cpp test_eval_plot.cpp test_eval_cli.cpp test_eval_formats.cpp
    test_eval_trajectory.cpp test_eval_scene.cpp
  LIBS rfir_eval)
add_dependencies(test_eval rfir-eval)

# Geometry conventions checked against the simulator, when it is built.
if(TARGET rfir_sim)
  rfir_add_test(test_eval_sim SOURCES test_eval_sim.cpp LIBS rfir_eval rfir_sim)
endif()

# The README's demo and its bar (scripts/demo_run.sh through the programs).
rfir_add_test(test_demo SOURCES test_demo.cpp LIBS rfir_eval)
add_dependencies(test_demo rfir-slam rfir-eval)
