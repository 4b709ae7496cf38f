# Tag-map estimators (rfir_models) and the MRPT map adapter (rfir_maps).
rfir_add_test(test_models
  SOURCES test_models_likelihood.cpp test_models_filters.cpp test_models_jacobians.cpp
    test_models_random.cpp
  LIBS rfir_models mrpt::config)
rfir_add_test(test_tagmaps
  SOURCES test_tagmaps_map.cpp test_tagmaps_ini.cpp test_tagmaps_accuracy.cpp
          test_tagmaps_reads.cpp test_tagmaps_reseat.cpp test_tagmaps_notread.cpp
          test_tag_estimators.cpp
  LIBS rfir_maps mrpt::maps mrpt::io mrpt::serialization)
