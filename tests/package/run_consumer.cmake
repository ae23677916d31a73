# cmake -DBUILD_DIR=... -DWORK_DIR=... -DSOURCE_DIR=... -P run_consumer.cmake
# Installs the massprops build into WORK_DIR/prefix, then configures, builds and runs the consumer.
file(REMOVE_RECURSE "${WORK_DIR}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${WORK_DIR}/prefix"
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "install failed: ${rc}")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" -S "${SOURCE_DIR}" -B "${WORK_DIR}/build"
                "-DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix" -DCMAKE_BUILD_TYPE=Release
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "configuring the consumer failed: ${rc}")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" --build "${WORK_DIR}/build" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "building the consumer failed: ${rc}")
endif()
execute_process(COMMAND "${WORK_DIR}/build/consumer" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the consumer failed: ${rc}")
endif()

# The package config's massprops_add_test() (docs/ci.md), when FIXTURE_DIR is given: the fixture
# description package of tools/colcon_test.sh configured against the same prefix, its ctests run
# (XACRO_DIR's stand-in xacro on PATH): 'urdf' fails on arm.urdf's bad link, 'robot' (the xacro
# with its argument) passes, and each wrote its JUnit report under test_results/<package>/.
if(DEFINED FIXTURE_DIR)
  set(fixture "${WORK_DIR}/fixture")
  execute_process(COMMAND "${CMAKE_COMMAND}" -S "${FIXTURE_DIR}" -B "${fixture}"
                  "-DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix" RESULT_VARIABLE rc OUTPUT_QUIET)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "configuring the fixture description package failed: ${rc}")
  endif()
  set(ENV{PATH} "${XACRO_DIR}:$ENV{PATH}")
  foreach(test urdf robot)
    execute_process(COMMAND "${CMAKE_CTEST_COMMAND}" --test-dir "${fixture}" -R "^${test}$"
                    RESULT_VARIABLE rc_${test} OUTPUT_VARIABLE log_${test})
  endforeach()
  if(rc_urdf EQUAL 0 OR NOT rc_robot EQUAL 0)
    message(FATAL_ERROR "massprops_add_test: 'urdf' exited ${rc_urdf} (expected a failure), "
                        "'robot' ${rc_robot} (expected 0)\n${log_urdf}\n${log_robot}")
  endif()
  file(READ "${fixture}/test_results/fixture_description/urdf.xml" junit)
  string(FIND "${junit}" "<testsuite name=\"urdf/arm.urdf\" tests=\"1\" failures=\"1\"" bad)
  string(FIND "${junit}" "<testsuite name=\"urdf/gripper.urdf\" tests=\"1\" failures=\"0\"" clean)
  if(bad EQUAL -1 OR clean EQUAL -1)
    message(FATAL_ERROR "massprops_add_test: unexpected JUnit report\n${junit}")
  endif()
  if(NOT EXISTS "${fixture}/test_results/fixture_description/robot.xml")
    message(FATAL_ERROR "massprops_add_test: the xacro test wrote no JUnit report")
  endif()
endif()
