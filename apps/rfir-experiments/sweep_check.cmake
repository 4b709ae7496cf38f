# Run by ctest (experiments_sweep): the same small sweep (3 tiny rows, 2 seeds)
# run directly on 1 and on 2 processes, and as a manifest run by xargs -P 2 then
# merged, must give the same results.json bytes (timings are in timings.json)
# and the same results.md but for its timings; --merge must refuse a missing
# run and a run of another sweep, naming the run. -DEXE=... -DOUT=... -DCFG=...
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
set(SWEEP --quick --rows t31_16,range_sweep,kidnap --seeds 2 --config-dir ${CFG}
          --set simulation.max_duration=20)

function(run_ok what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}): ${err}")
  endif()
  set(last_out "${out}" PARENT_SCOPE)
  set(last_err "${err}" PARENT_SCOPE)
endfunction()

# results.md without what changes from run to run: the time sentence of the
# header and the "ms per step" column of the tables.
function(md_numbers dir var)
  file(READ ${dir}/results.md md)
  string(REGEX REPLACE "(Wall|Run) time: [^.]*\\.[^.]*\\." "TIME." md "${md}")
  string(REGEX REPLACE "\\| [0-9.]+ \\| ([^|\n]* / [^|\n]*) \\|\n" "| MS | \\1 |\n"
         md "${md}")
  set(${var} "${md}" PARENT_SCOPE)
endfunction()

function(same_as_j1 dir what)
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/j1/results.json
                          ${dir}/results.json RESULT_VARIABLE diff)
  if(NOT diff EQUAL 0)
    message(FATAL_ERROR "${what}: results.json differs from --jobs 1's")
  endif()
  md_numbers(${OUT}/j1 a)
  md_numbers(${dir} b)
  if(NOT a STREQUAL b)
    message(FATAL_ERROR "${what}: results.md differs from --jobs 1's beyond the timings")
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/j1/img/exp_kidnap.png
                          ${dir}/img/exp_kidnap.png RESULT_VARIABLE diff)
  if(NOT diff EQUAL 0)
    message(FATAL_ERROR "${what}: img/exp_kidnap.png differs from --jobs 1's")
  endif()
endfunction()

run_ok("--jobs 1" ${EXE} ${SWEEP} --out-dir ${OUT}/j1)
file(READ ${OUT}/j1/results.json json)
if(json MATCHES "ms_per_step|wall_seconds" OR NOT EXISTS ${OUT}/j1/timings.json)
  message(FATAL_ERROR "the timings are in results.json, not in timings.json")
endif()
string(REGEX MATCHALL "\"method\":\"PS-SLAM\",\"seed\":[12]," hits "${json}")
list(LENGTH hits n)
if(NOT n EQUAL 8)  # t31_16 2, range_sweep 2 points x 2, kidnap 2
  message(FATAL_ERROR "results.json: ${n} PS-SLAM runs, expected 8")
endif()

run_ok("--jobs 2" ${EXE} ${SWEEP} --jobs 2 --out-dir ${OUT}/j2)
if(NOT last_err MATCHES "\\[6/6\\] [a-z0-9_]+ seed [12]: ")
  message(FATAL_ERROR "--jobs 2: no progress line for the 6th of 6 runs: ${last_err}")
endif()
same_as_j1(${OUT}/j2 "--jobs 2")

run_ok("--manifest" ${EXE} ${SWEEP} --manifest --out-dir ${OUT}/runs)
file(WRITE ${OUT}/manifest.txt "${last_out}")
string(REGEX MATCHALL "[^\n]+--run [a-z0-9_]+:[12] --out-dir [^\n]+" lines "${last_out}")
list(LENGTH lines n)
if(NOT n EQUAL 6 OR EXISTS ${OUT}/runs)
  message(FATAL_ERROR "--manifest: ${n} run lines (expected 6), or it did work")
endif()
run_ok("the manifest under xargs -P 2" xargs -d "\n" -P 2 -I{} sh -c {}
       INPUT_FILE ${OUT}/manifest.txt)
run_ok("--merge" ${EXE} ${SWEEP} --merge ${OUT}/runs --out-dir ${OUT}/merged)
same_as_j1(${OUT}/merged "the manifest merged")

# A run of another sweep (without the --set edit), then a missing run.
execute_process(COMMAND ${EXE} --quick --rows t31_16,range_sweep,kidnap --seeds 2
                        --config-dir ${CFG} --merge ${OUT}/runs --out-dir ${OUT}/other
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(rc EQUAL 0 OR NOT err MATCHES "run t31_16 seed 1 .*another sweep"
   OR EXISTS ${OUT}/other/results.json)
  message(FATAL_ERROR "--merge of another sweep's runs: exit ${rc}: ${err}")
endif()
file(REMOVE_RECURSE ${OUT}/runs/range_sweep/seed2)
execute_process(COMMAND ${EXE} ${SWEEP} --merge ${OUT}/runs --out-dir ${OUT}/merged
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(rc EQUAL 0 OR NOT err MATCHES "range_sweep seed 2: [^\n]*/runs/range_sweep/seed2/run.json")
  message(FATAL_ERROR "--merge with a missing run: exit ${rc}: ${err}")
endif()
