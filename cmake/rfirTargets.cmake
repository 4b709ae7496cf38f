# One function per kind of target, so that every library and every program
# gets the same settings: where its headers are, what it links, how it is
# installed and exported (cmake/rfirInstall.cmake), and for programs the
# command-line parser.

# MRPT ships TCLAP as headers under mrpt/tclap/include, with no CMake target:
# found once here, for every program.
find_path(RFIR_TCLAP_DIR mrpt/3rdparty/tclap/CmdLine.h
  HINTS ${MRPT_INCLUDE_DIRS} /usr/include/mrpt/tclap/include
  PATH_SUFFIXES mrpt/tclap/include REQUIRED)
add_library(rfir_tclap INTERFACE)
target_include_directories(rfir_tclap INTERFACE ${RFIR_TCLAP_DIR})

# rfir_add_library(<target> SHARED|STATIC EXPORT <name> [INTERNAL]
#                  SOURCES <files> [PUBLIC <deps>] [PRIVATE <deps>])
# Public headers in <folder>/include (installed under include/), exported as
# rfir::<name>. A library lists the layers below it only (docs/architecture.md;
# scripts/check_layers.sh checks the graph). INTERNAL: the work of one program
# (its run, its experiments), linked by it and the tests, not installed.
function(rfir_add_library target type)
  cmake_parse_arguments(L "INTERNAL" "EXPORT" "SOURCES;PUBLIC;PRIVATE" ${ARGN})
  if(NOT L_EXPORT OR NOT L_SOURCES)
    message(FATAL_ERROR "rfir_add_library(${target}): EXPORT and SOURCES are required")
  endif()
  add_library(${target} ${type} ${L_SOURCES})
  if(EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/include)
    target_include_directories(${target} PUBLIC
      $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>)
  endif()
  target_link_libraries(${target} PUBLIC ${L_PUBLIC} PRIVATE ${L_PRIVATE})
  if(L_INTERNAL)
    add_library(rfir::${L_EXPORT} ALIAS ${target})
  else()
    rfir_install_library(${target} ${L_EXPORT})
  endif()
endfunction()

# rfir_add_program(<name> SOURCES <files> DEPS <libraries>)
# A program folder holds its main and its command line; the work is in the
# libraries it links.
function(rfir_add_program name)
  cmake_parse_arguments(P "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(${name} ${P_SOURCES})
  target_link_libraries(${name} PRIVATE ${P_DEPS} rfir_tclap)
  install(TARGETS ${name} RUNTIME DESTINATION bin)
endfunction()
