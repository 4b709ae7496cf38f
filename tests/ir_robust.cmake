# IR localization that is not lost: the simulator's IR
# fault INIs and the raw-window rotation run, localized with the stock INI.
rfir_add_test(test_ir_robust
  SOURCES test_ir_robust.cpp
  LIBS rfir_ir rfir_sim rfir_eval rfir_localize_core)
