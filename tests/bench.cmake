# rfir-bench: a smoke run in a tiny configuration; checks that the table, the
# JSON and the plots are complete and that bad options are rejected. No timing
# assertions.
if(TARGET rfir-bench)
  rfir_add_test(test_bench_smoke SOURCES test_bench_smoke.cpp LIBS)
  add_dependencies(test_bench_smoke rfir-bench rfir-sim rfir-slam rfir-import rfir-plain-ps)
endif()

# rfir-plain-ps and rfir_plain: the plain reference as a whole program.
if(TARGET rfir-plain-ps)
  rfir_add_test(test_plain_ps SOURCES test_plain_ps.cpp LIBS rfir_plain)
  add_dependencies(test_plain_ps rfir-plain-ps rfir-sim rfir-import)
endif()
