# Text log parser and writer, text log <-> rawlog conversion, rawlog I/O, and
# the rfir-import program.
rfir_add_test(test_import
  SOURCES test_textlog.cpp test_textlog_rules.cpp test_import.cpp test_import_app.cpp
          test_rawlog_io.cpp
  LIBS rfir_appcommon)
add_dependencies(test_import rfir-import)
