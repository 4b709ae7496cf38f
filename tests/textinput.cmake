# Bounded line length and file checks of every text reader (logs, maps, TUM,
# emitter files, INIs).
rfir_add_test(test_text_input
  SOURCES test_text_input.cpp
  LIBS rfir_appcommon rfir_ir rfir_sim rfir_slam rfir_localize_core)
add_dependencies(test_text_input rfir-import)
