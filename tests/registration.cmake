# Class registration must not depend on the order of the library's sources
# (static initialisation follows it): the same test against the library and
# against its sources linked in reverse order.
rfir_add_test(test_registration_order
  SOURCES test_registration_order.cpp
  LIBS rfir_observations mrpt::io)
get_target_property(rfir_obs_sources rfir_observations SOURCES)
list(REVERSE rfir_obs_sources)
list(TRANSFORM rfir_obs_sources PREPEND ${CMAKE_SOURCE_DIR}/observations/)
rfir_add_test(test_registration_reversed
  SOURCES ${rfir_obs_sources} test_registration_order.cpp
  LIBS mrpt::obs mrpt::math mrpt::poses mrpt::io)
target_include_directories(test_registration_reversed PRIVATE
  ${CMAKE_SOURCE_DIR}/observations/include)
