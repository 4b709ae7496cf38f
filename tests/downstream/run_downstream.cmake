# cmake -P script of the downstream_package test (see tests/downstream.cmake).
cmake_minimum_required(VERSION 3.16)

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out
    ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${ARGN}\n${out}")
  endif()
  message(STATUS "${what}: ok")
  set(run_output "${out}" PARENT_SCOPE)
endfunction()

function(expect_file f)
  if(NOT EXISTS ${f})
    message(FATAL_ERROR "not installed: ${f}")
  endif()
endfunction()

set(prefix ${WORK_DIR}/prefix)
file(REMOVE_RECURSE ${WORK_DIR})
run("install into ${prefix}" ${CMAKE_COMMAND} --install ${RFIR_BINARY_DIR} --prefix ${prefix})

# The layout a user relies on: headers by namespace path, versioned SONAMEs,
# the package files, the plugin, programs and stock INIs.
string(REGEX MATCH "^[0-9]+\\.[0-9]+" soversion ${PROJECT_VERSION})
foreach(f include/rfir/maps/CRFIDTagParticleMap.h include/rfir/obs/CObservationRFIDReaders.h
    include/rfir/models/tag_particle_filter.h include/rfir/slam/slam_engine.h
    include/rfir/ir/sensor_model.h include/rfir/maps/CIREmitterMap.h
    lib/cmake/rfir/rfirConfig.cmake lib/cmake/rfir/rfirConfigVersion.cmake
    lib/cmake/rfir/rfirTargets.cmake lib/librfir_mrpt_plugin.so bin/rfir-slam
    share/rfir/config_ini/slam_ps.ini share/rfir/config_ini/mrpt_rbpf_slam_rfid.ini)
  expect_file(${prefix}/${f})
endforeach()
foreach(lib observations models io maps slam ir)
  expect_file(${prefix}/lib/librfir_${lib}.so.${PROJECT_VERSION})
  expect_file(${prefix}/lib/librfir_${lib}.so.${soversion})
endforeach()

# One version number: the installed rfir/version.h and an installed
# program's --version say the project's (the package's version file too:
# the ctest version_everywhere).
file(STRINGS ${prefix}/include/rfir/version.h version_line REGEX "define RFIR_VERSION ")
if(NOT version_line STREQUAL "#define RFIR_VERSION \"${PROJECT_VERSION}\"")
  message(FATAL_ERROR "installed rfir/version.h: '${version_line}', not ${PROJECT_VERSION}")
endif()
run("installed rfir-slam --version" ${prefix}/bin/rfir-slam --version)
if(NOT run_output MATCHES "version: ${PROJECT_VERSION}\n")
  message(FATAL_ERROR "installed rfir-slam --version: ${run_output}")
endif()

# Configure and build the downstream project against the prefix only.
set(build ${WORK_DIR}/build)
set(launcher)
if(CXX_LAUNCHER)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${CXX_LAUNCHER})
endif()
run("configure the downstream project" ${CMAKE_COMMAND}
  -S ${RFIR_SOURCE_DIR}/tests/downstream -B ${build} -DCMAKE_BUILD_TYPE=Release
  -DCMAKE_CXX_COMPILER=${CXX_COMPILER} ${launcher} -DCMAKE_PREFIX_PATH=${prefix}
  # The same flags as this build (the sanitizer build's libraries need them).
  "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}" "-DCMAKE_EXE_LINKER_FLAGS=${EXE_LINKER_FLAGS}"
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
file(STRINGS ${build}/CMakeCache.txt rfir_dir REGEX "^rfir_DIR:")
if(NOT rfir_dir STREQUAL "rfir_DIR:PATH=${prefix}/lib/cmake/rfir")
  message(FATAL_ERROR "the package was not found in the prefix: ${rfir_dir}")
endif()
run("build the downstream project" ${CMAKE_COMMAND} --build ${build})
run("run the downstream program" ${build}/app
  ${prefix}/share/rfir/config_ini/mrpt_rbpf_slam_rfid.ini MappingApplication)
message(STATUS "${run_output}")
# It must fail when the tag map is not there, or the check above proves nothing.
file(WRITE ${WORK_DIR}/empty.ini "[MappingApplication]\nrfidTagMap_count = 0\n")
execute_process(COMMAND ${build}/app ${WORK_DIR}/empty.ini RESULT_VARIABLE rc
  OUTPUT_QUIET ERROR_QUIET)
if(rc EQUAL 0)
  message(FATAL_ERROR "the downstream program passed without a tag map")
endif()

# An installed program finds its stock INI (share/rfir/config_ini) by itself.
run("installed rfir-slam with its stock INI" ${prefix}/bin/rfir-slam
  --rawlog ${RFIR_SOURCE_DIR}/datasets/rfid_300mm_4tags_random_90s.rawlog
  --method ps --out-dir ${WORK_DIR}/slam_out)

# The Python module from the prefix (docs/python.md): PYTHONPATH=<prefix>/lib/
# python3/dist-packages, its stock INIs the prefix's, and rfir.slam's path
# the installed rfir-slam's path.tum (same stock INI, seed 1), byte for byte.
if(PYTHON_EXECUTABLE)
  set(pydir ${prefix}/lib/python3/dist-packages)
  expect_file(${pydir}/rfir/__init__.py)
  run("import rfir from the prefix" ${CMAKE_COMMAND} -E env PYTHONPATH=${pydir}
    ${PYTHON_EXECUTABLE} ${RFIR_SOURCE_DIR}/tests/python/check_install.py ${prefix}
    ${RFIR_SOURCE_DIR}/datasets/rfid_300mm_4tags_random_90s.rawlog
    ${WORK_DIR}/slam_out/path.tum ${WORK_DIR}/python_path.tum)
  message(STATUS "${run_output}")
endif()
