# IR positioning system (thesis chapter 5): sensor model, emitter map,
# localization accuracy on short simulated runs, ID tools.
rfir_add_test(test_ir_map
  SOURCES test_ir_model.cpp test_ir_map.cpp
  LIBS rfir_ir mrpt::maps mrpt::io)
rfir_add_test(test_ir_localize
  SOURCES test_ir_localize.cpp
  LIBS rfir_ir rfir_sim rfir_eval)
rfir_add_test(test_ir_apps
  SOURCES test_ir_apps.cpp
  LIBS rfir_ir rfir_sim rfir_appcommon)
add_dependencies(test_ir_apps rfir-localize rfir-ids rfir-sim)
