# Rawlogs in MRPT's layouts (every action with a movement, observation-only,
# CObservationRFID) read as the project's, and rfir-slam's run on them.
rfir_add_test(test_mrpt_layouts
  SOURCES test_mrpt_layouts.cpp
  LIBS rfir_eval)
add_dependencies(test_mrpt_layouts rfir-slam rfir_mrpt_plugin)
# MRPT's installed rbpf-slam and pf-localization with the plugin preloaded
# (skipped where they are missing), their outputs scored by hand and by
# rfir-eval --path-format mrpt.
rfir_add_test(test_mrpt_apps
  SOURCES test_mrpt_apps.cpp
  LIBS rfir_eval rfir_maps)
add_dependencies(test_mrpt_apps rfir_mrpt_plugin rfir-eval)
