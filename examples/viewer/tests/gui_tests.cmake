# The viewer's tests. Its gui tier (CTest label `gui`): the real window under xvfb-run on Mesa
# llvmpipe. scripts/run-tests.sh runs every label, this one included.
find_program(PRISM_XVFB_RUN xvfb-run)
set(_gui ${CMAKE_CURRENT_SOURCE_DIR}/tests)
set(_work ${CMAKE_CURRENT_BINARY_DIR}/gui-tests)
# The catalogue panel's variant logic (label unit: no window, no context).
find_package(GTest REQUIRED)
add_executable(viewer_variant_choice_tests ${_gui}/test_variant_choice.cpp ${CMAKE_CURRENT_SOURCE_DIR}/variant_choice.cpp)
target_include_directories(viewer_variant_choice_tests PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(viewer_variant_choice_tests PRIVATE prism_render GTest::gtest_main)
add_test(NAME example.viewer_variant_choice COMMAND viewer_variant_choice_tests)
set_tests_properties(example.viewer_variant_choice PROPERTIES LABELS unit)
# The named parameters of keys, panels and scripts (label unit: no window, no context).
add_executable(viewer_actions_tests ${_gui}/test_viewer_actions.cpp ${CMAKE_CURRENT_SOURCE_DIR}/viewer_actions.cpp)
target_include_directories(viewer_actions_tests PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(viewer_actions_tests PRIVATE prism_scene_core prism_render GTest::gtest_main)
target_compile_definitions(viewer_actions_tests PRIVATE PRISM_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
add_test(NAME example.viewer_actions COMMAND viewer_actions_tests)
set_tests_properties(example.viewer_actions PROPERTIES LABELS unit)
# The command line without a display (label gui; tests/README.md): --help/--version exit 0,
# usage errors exit 2. One test per case, through prism::test::runCommand.
include(GoogleTest)
add_executable(viewer_cli_tests ${_gui}/test_cli.cpp)
target_link_libraries(viewer_cli_tests PRIVATE prism_test_core GTest::gtest_main)
target_compile_definitions(viewer_cli_tests PRIVATE PRISM_VIEWER="$<TARGET_FILE:viewer>"
                                                    PRISM_VIEWER_TEST_TMP="${_work}/cli")
add_dependencies(viewer_cli_tests viewer)
gtest_discover_tests(viewer_cli_tests TEST_PREFIX "example." DISCOVERY_TIMEOUT 60 NO_PRETTY_VALUES
                     PROPERTIES LABELS gui TIMEOUT 60 ENVIRONMENT_MODIFICATION "DISPLAY=unset:")
if(PRISM_XVFB_RUN)
  add_test(NAME example.viewer_smoke COMMAND ${PRISM_XVFB_RUN} -a $<TARGET_FILE:viewer> --frames 5)
  foreach(check lit panels script reference sampling)
    add_test(NAME example.viewer_${check}
             COMMAND bash ${_gui}/gui_test.sh ${check} $<TARGET_FILE:viewer> ${_work}/${check})
  endforeach()
  set_tests_properties(example.viewer_smoke example.viewer_lit example.viewer_panels example.viewer_script
                       example.viewer_reference example.viewer_sampling PROPERTIES LABELS gui TIMEOUT 120
                       # xvfb-run -a picks a free display by its lock file: two starting at once can collide.
                       RESOURCE_LOCK xvfb_run)
endif()
find_program(PRISM_XVFB Xvfb)
if(PRISM_XVFB)
  # --watch end to end: a broken module edit in a temp copy of the sources is printed and
  # shown in the overlay while the last good program draws; undoing it reloads.
  add_test(NAME example.viewer_watch
    COMMAND bash ${_gui}/watch_smoke.sh $<TARGET_FILE:viewer> ${PROJECT_SOURCE_DIR} ${_work}/watch)
  set_tests_properties(example.viewer_watch PROPERTIES LABELS gui TIMEOUT 180 ENVIRONMENT "LP_NUM_THREADS=2")
endif()
