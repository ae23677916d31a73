# cmake -DBUILD_DIR=... -DPREFIX=... -DPYTHON=... -DSITE=... -P run_installed.cmake
# Installs the build into PREFIX and imports the installed package with only its site folder on
# PYTHONPATH: the extension must find the installed libmassprops by its relative RPATH.
file(REMOVE_RECURSE "${PREFIX}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${PREFIX}"
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "install failed: ${rc}")
endif()
if(IS_ABSOLUTE "${SITE}")
  message(FATAL_ERROR "MASSPROPS_PYTHON_INSTALL_DIR is absolute; this test needs a relative one")
endif()
execute_process(
  COMMAND "${CMAKE_COMMAND}" -E env "PYTHONPATH=${PREFIX}/${SITE}" --unset=LD_LIBRARY_PATH
          "${PYTHON}" -c
          "import massprops, os; assert massprops.__file__.startswith(os.environ['PYTHONPATH']), massprops.__file__; print(massprops.__version__, massprops.UnitInertia.solid_sphere(1.0))"
  WORKING_DIRECTORY "${PREFIX}"
  RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "importing the installed package failed: ${rc}")
endif()
