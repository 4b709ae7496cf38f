# Evaluation metrics, tables/JSON, PNG figures, and the rfir-eval program.
rfir_add_test(test_eval
  SOURCES test_eval_metrics.cpp test_eval_plot.cpp test_eval_cli.cpp
  LIBS rfir_eval)
add_dependencies(test_eval rfir-eval)

# Geometry conventions checked against the simulator, when it is built.
if(TARGET rfir_sim)
  rfir_add_test(test_eval_sim SOURCES test_eval_sim.cpp LIBS rfir_eval rfir_sim)
endif()
