# massprops_add_test(): check a package's robot descriptions as one of its tests (docs/ci.md,
# "colcon test and CMake"). Included by the installed massprops-config.cmake, so that after
# find_package(massprops) any CMake package (ament_cmake ones too) can write:
#
#   if(BUILD_TESTING)
#     find_package(massprops REQUIRED)
#     massprops_add_test(robot urdf/robot.urdf.xacro TARGET gazebo XACRO_ARGS use_gripper:=true)
#   endif()
#
#   massprops_add_test(NAME FILE... [TARGET target] [FAIL_ON error|warning|note]
#                      [PACKAGE_PATH dir...] [XACRO_ARGS name:=value...]
#                      [XACRO_COMMAND command...] [ARGS option...])
#
# It adds the ctest NAME, which runs the installed `massprops check` on the FILEs (relative to
# the calling CMakeLists.txt's folder; folders are searched as `check` searches them) and fails
# when a finding is at or above FAIL_ON (default: error, or fail-on in the package's
# .massprops.toml) or a file cannot be read. It writes the JUnit report to
# ${AMENT_TEST_RESULTS_DIR}/${PROJECT_NAME}/NAME.xml (AMENT_TEST_RESULTS_DIR defaults to
# ${CMAKE_BINARY_DIR}/test_results, as in ament_cmake_test), where `colcon test-result` finds it,
# and prints the findings as text into the test's log. A .xacro FILE (which must be the only FILE)
# is expanded by the xacro route of `check`: `xacro` found on PATH, or XACRO_COMMAND, given the
# XACRO_ARGS. TARGET is `check --target`; PACKAGE_PATH each a `--package-path`; ARGS any other
# options of `check`.

function(massprops_add_test name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "TARGET;FAIL_ON"
                        "PACKAGE_PATH;XACRO_ARGS;XACRO_COMMAND;ARGS")
  set(files ${arg_UNPARSED_ARGUMENTS})
  if(NOT files)
    message(FATAL_ERROR "massprops_add_test(${name}): no FILE to check")
  endif()
  if(NOT TARGET massprops::massprops-cli)
    message(FATAL_ERROR "massprops_add_test(${name}): the massprops::massprops-cli target is "
                        "missing (call find_package(massprops) first)")
  endif()
  set(xacro OFF)
  foreach(file IN LISTS files)
    if(file MATCHES "\\.xacro$")
      set(xacro ON)
    endif()
  endforeach()
  list(LENGTH files file_count)
  if(xacro AND NOT file_count EQUAL 1)
    message(FATAL_ERROR "massprops_add_test(${name}): a .xacro FILE must be the only FILE of its "
                        "test (massprops checks one xacro expansion at a time)")
  endif()
  if(NOT xacro AND (arg_XACRO_ARGS OR arg_XACRO_COMMAND))
    message(FATAL_ERROR "massprops_add_test(${name}): XACRO_ARGS and XACRO_COMMAND need a .xacro "
                        "FILE")
  endif()

  set(options "")
  if(arg_TARGET)
    list(APPEND options --target ${arg_TARGET})
  endif()
  if(arg_FAIL_ON)
    if(NOT arg_FAIL_ON MATCHES "^(error|warning|note)$")
      message(FATAL_ERROR "massprops_add_test(${name}): FAIL_ON must be error, warning or note, "
                          "not '${arg_FAIL_ON}'")
    endif()
    list(APPEND options --fail-on ${arg_FAIL_ON})
  endif()
  foreach(dir IN LISTS arg_PACKAGE_PATH)
    get_filename_component(dir "${dir}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
    list(APPEND options --package-path "${dir}")
  endforeach()
  foreach(xacro_arg IN LISTS arg_XACRO_ARGS)
    list(APPEND options --xacro-arg "${xacro_arg}")
  endforeach()
  if(arg_XACRO_COMMAND)
    list(JOIN arg_XACRO_COMMAND " " xacro_command)
    list(APPEND options --xacro-command "${xacro_command}")
  endif()
  list(APPEND options ${arg_ARGS})

  if(DEFINED AMENT_TEST_RESULTS_DIR)
    set(results_dir "${AMENT_TEST_RESULTS_DIR}/${PROJECT_NAME}")
  else()
    set(results_dir "${CMAKE_BINARY_DIR}/test_results/${PROJECT_NAME}")
  endif()
  # The command's words, each a bracket argument in the generated script (any character is safe
  # there); the tool's path is a generator expression, resolved by file(GENERATE).
  set(words "")
  foreach(word IN LISTS options files)
    string(APPEND words " [==[${word}]==]")
  endforeach()
  set(script "${CMAKE_CURRENT_BINARY_DIR}/massprops_tests/${name}.cmake")
  set(runner "${CMAKE_CURRENT_FUNCTION_LIST_DIR}/massprops_run_test.cmake")
  file(GENERATE OUTPUT "${script}" CONTENT
"set(MASSPROPS_TOOL [==[$<TARGET_FILE:massprops::massprops-cli>]==])
set(MASSPROPS_RESULT_FILE [==[${results_dir}/${name}.xml]==])
set(MASSPROPS_TEST_NAME [==[${name}]==])
set(MASSPROPS_CHECK_ARGS${words})
include([==[${runner}]==])
")
  add_test(NAME ${name} COMMAND ${CMAKE_COMMAND} -P "${script}"
           WORKING_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}")
  set_tests_properties(${name} PROPERTIES LABELS massprops)
endfunction()
