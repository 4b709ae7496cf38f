# The manual's links: every relative link of docs/, the README, the
# changelog and datasets/README.md resolves, and every citation [n] links to
# its entry of docs/bibliography.md (scripts/check_links.sh).
add_test(NAME docs_links
  COMMAND bash ${CMAKE_SOURCE_DIR}/scripts/check_links.sh ${CMAKE_SOURCE_DIR})
set_tests_properties(docs_links PROPERTIES TIMEOUT 60)
