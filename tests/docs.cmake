# The manual's links: every relative link of docs/, the README, the
# changelog and datasets/README.md resolves, and every citation [n] links to
# its entry of docs/bibliography.md (scripts/check_links.sh).
add_test(NAME docs_links
  COMMAND bash ${CMAKE_SOURCE_DIR}/scripts/check_links.sh ${CMAKE_SOURCE_DIR})
set_tests_properties(docs_links PROPERTIES TIMEOUT 60)

# The measured numbers of the README and the manual that a quick command
# gives (the demo's table, rfir-ids' counts, the IR odometry level, ...),
# and every program's option table of docs/programs.md (from its --help):
# scripts/docs_numbers.py reruns the commands on this build's programs and
# fails with a diff and the command that rewrites the pages
# (docs/README.md, "How the numbers stay true"). Debian's python3: CI has
# only that one.
add_test(NAME docs_numbers
  COMMAND /usr/bin/python3 ${CMAKE_SOURCE_DIR}/scripts/docs_numbers.py --check
          --bin $<TARGET_FILE_DIR:rfir-slam>)
set_tests_properties(docs_numbers PROPERTIES TIMEOUT 120)

# docs/outputs.md against the files rfir-slam and rfir-localize write and the
# keys of their stats.json, both ways (scripts/check_outputs_doc.py: a PS-SLAM
# run with --smooth on datasets/rfid_kidnap, one with a loop closure on a
# short simulated floor, rfir-localize on datasets/ir_loop_spots; about 5 s).
add_test(NAME docs_outputs
  COMMAND /usr/bin/python3 ${CMAKE_SOURCE_DIR}/scripts/check_outputs_doc.py
          --bin $<TARGET_FILE_DIR:rfir-slam>)
set_tests_properties(docs_outputs PROPERTIES TIMEOUT 120)
