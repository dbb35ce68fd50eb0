# docs/scenarios.md must be what fsi-scenario-doc writes from the scenario schema and the
# doc comments of engine/include/fsi/scenario.hpp. After adding or changing a scenario
# key: tools/gen-scenario-doc, and commit docs/scenarios.md.
# Inputs: -DGEN=<fsi-scenario-doc> -DSOURCE_DIR=<repo> -DBINARY_DIR=<build>.
set(_out ${BINARY_DIR}/test_tmp/scenarios.md)
file(MAKE_DIRECTORY ${BINARY_DIR}/test_tmp)
execute_process(COMMAND ${GEN} ${SOURCE_DIR}/engine/include/fsi/scenario.hpp
  OUTPUT_FILE ${_out} ERROR_VARIABLE _err RESULT_VARIABLE _rc)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "fsi-scenario-doc failed (${_rc}):\n${_err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${_out} ${SOURCE_DIR}/docs/scenarios.md
  RESULT_VARIABLE _diff)
if(NOT _diff EQUAL 0)
  execute_process(COMMAND diff -u ${SOURCE_DIR}/docs/scenarios.md ${_out} OUTPUT_VARIABLE _d)
  message(FATAL_ERROR "docs/scenarios.md is out of date with the scenario schema: run "
    "tools/gen-scenario-doc and commit docs/scenarios.md.\n${_d}")
endif()
message("docs/scenarios.md matches the scenario schema")
