# Evaluation metrics, tables/JSON, PNG figures, and the rfir-eval program.
rfir_add_test(test_eval
  SOURCES test_eval_metrics.cpp test_eval_plot.cpp test_eval_cli.cpp
  LIBS rfir_eval)
add_dependencies(test_eval rfir-eval)
