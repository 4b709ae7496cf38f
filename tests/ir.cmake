# IR positioning system (thesis chapter 5): sensor model, emitter map,
# localization accuracy on short simulated runs, ID tools.
rfir_add_test(test_ir_map
  SOURCES test_ir_model.cpp test_ir_map.cpp
  LIBS rfir_ir mrpt::maps mrpt::io)
