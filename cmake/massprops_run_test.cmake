# The body of a ctest added by massprops_add_test() (massprops_add_test.cmake), included by its
# generated script, which sets MASSPROPS_TOOL, MASSPROPS_RESULT_FILE, MASSPROPS_TEST_NAME and
# MASSPROPS_CHECK_ARGS. Runs `massprops check --format junit` into the result file, then the same
# check as text into the test's log; fails when the check exits non-zero (findings at the fail
# level: 1; a file that cannot be read: 2).
get_filename_component(result_dir "${MASSPROPS_RESULT_FILE}" DIRECTORY)
file(MAKE_DIRECTORY "${result_dir}")
file(REMOVE "${MASSPROPS_RESULT_FILE}")  # never a stale report of an earlier run
execute_process(COMMAND "${MASSPROPS_TOOL}" check --format junit ${MASSPROPS_CHECK_ARGS}
                OUTPUT_VARIABLE junit ERROR_VARIABLE junit_errors RESULT_VARIABLE status)
if(NOT junit MATCHES "<testsuites")
  # The tool wrote no report (a usage error, no xacro expander, or it did not run): a report of
  # one errored testcase, so that `colcon test-result` shows why.
  string(REPLACE "&" "&amp;" why "massprops check exited ${status}: ${junit_errors}")
  string(REPLACE "<" "&lt;" why "${why}")
  string(REPLACE ">" "&gt;" why "${why}")
  string(REPLACE "\"" "&quot;" message "${why}")
  string(REPLACE "\n" " " message "${message}")
  set(junit "<?xml version=\"1.0\" encoding=\"UTF-8\"?>
<testsuites name=\"massprops check\" tests=\"1\" failures=\"0\" errors=\"1\" skipped=\"0\">
  <testsuite name=\"${MASSPROPS_TEST_NAME}\" tests=\"1\" failures=\"0\" errors=\"1\" skipped=\"0\">
    <testcase name=\"massprops check\" classname=\"massprops.${MASSPROPS_TEST_NAME}\">
      <error message=\"${message}\">${why}</error>
    </testcase>
  </testsuite>
</testsuites>
")
endif()
file(WRITE "${MASSPROPS_RESULT_FILE}" "${junit}")
execute_process(COMMAND "${MASSPROPS_TOOL}" check --color never ${MASSPROPS_CHECK_ARGS})
message("massprops: JUnit report: ${MASSPROPS_RESULT_FILE}")
if(NOT status EQUAL 0)
  message(FATAL_ERROR "massprops check exited ${status} (1: findings at the fail level; 2: a file "
                      "could not be read or the check could not run) ${junit_errors}")
endif()
