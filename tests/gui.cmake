# The live view (--gui, docs/live-view.md). Without a display --gui is a
# command-line error (exit 2, nothing written), in every build. With the view
# built: rfir-slam and rfir-localize under xvfb-run record frames that show
# particles, landmarks, sensors and paths (gui_frames_check counts the view's
# colours), their outputs are byte-identical with and without the view, and
# the keys pause, step, resume and close the view (gui_keys).
# Skipped (exit 77) without xvfb-run, and in the sanitizer build.
add_test(NAME gui_no_display
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/gui.sh ${CMAKE_BINARY_DIR}/bin ${CMAKE_SOURCE_DIR}
          no-display)
set_tests_properties(gui_no_display PROPERTIES TIMEOUT 60)
if(RFIR_WITH_GUI)
  add_executable(gui_frames_check gui_frames_check.cpp)
  target_link_libraries(gui_frames_check PRIVATE rfir_view mrpt::img mrpt::system)
  set(gui_sanitized 0)
  if(CMAKE_CXX_FLAGS MATCHES "sanitize=address")
    set(gui_sanitized 1)
  endif()
  foreach(prog slam localize)
    add_test(NAME gui_frames_${prog}
      COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/gui.sh ${CMAKE_BINARY_DIR}/bin
              ${CMAKE_SOURCE_DIR} ${prog} $<TARGET_FILE:gui_frames_check>)
    set_tests_properties(gui_frames_${prog} PROPERTIES TIMEOUT 180 SKIP_RETURN_CODE 77
      ENVIRONMENT "RFIR_GUI_SANITIZED=${gui_sanitized}")
  endforeach()
  add_test(NAME gui_keys
    COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/gui.sh ${CMAKE_BINARY_DIR}/bin
            ${CMAKE_SOURCE_DIR} keys)
  set_tests_properties(gui_keys PROPERTIES TIMEOUT 180 SKIP_RETURN_CODE 77
    ENVIRONMENT "RFIR_GUI_SANITIZED=${gui_sanitized}")
endif()
