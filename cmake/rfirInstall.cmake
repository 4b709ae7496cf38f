# Installing the libraries as the CMake package rfir (lib/cmake/rfir): each
# library is exported as rfir::<name> (also an ALIAS in the build tree, so
# code reads the same inside and outside), with a versioned SONAME, its public
# headers installed under include/ as laid out in its include/ folder.
include(CMakePackageConfigHelpers)

set(RFIR_INSTALL_CMAKEDIR lib/cmake/rfir)

# rfir_install_library(<target> <export name>)
function(rfir_install_library target name)
  add_library(rfir::${name} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
  get_target_property(type ${target} TYPE)
  if(type STREQUAL "SHARED_LIBRARY")
    # 0.x: every minor release may break the ABI, so the SONAME carries it.
    set_target_properties(${target} PROPERTIES VERSION ${PROJECT_VERSION}
      SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR})
  endif()
  # Users get C++17 from the target, not from their own settings.
  target_compile_features(${target} PUBLIC cxx_std_17)
  target_include_directories(${target} PUBLIC $<INSTALL_INTERFACE:include>)
  install(TARGETS ${target} EXPORT rfirTargets
    LIBRARY DESTINATION lib ARCHIVE DESTINATION lib RUNTIME DESTINATION bin)
  if(EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/include)
    install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/include/ DESTINATION include)
  endif()
endfunction()

# Called once every library is declared (end of the top CMakeLists.txt).
function(rfir_install_package)
  install(EXPORT rfirTargets NAMESPACE rfir:: DESTINATION ${RFIR_INSTALL_CMAKEDIR})
  configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/rfirConfig.cmake.in
    ${PROJECT_BINARY_DIR}/rfirConfig.cmake INSTALL_DESTINATION ${RFIR_INSTALL_CMAKEDIR})
  write_basic_package_version_file(${PROJECT_BINARY_DIR}/rfirConfigVersion.cmake
    VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
  install(FILES ${PROJECT_BINARY_DIR}/rfirConfig.cmake
    ${PROJECT_BINARY_DIR}/rfirConfigVersion.cmake DESTINATION ${RFIR_INSTALL_CMAKEDIR})
endfunction()
