# `sreh-twin run BAD.yaml` must exit 2 with one line "sreh-twin: FILE:LINE:COL: ..."
# on stderr and nothing on stdout (interfaces.md exit codes).
execute_process(COMMAND ${SREH_TWIN} run ${SCENARIO} --json
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 2)
  message(FATAL_ERROR "exit code ${rc}, want 2; stderr: ${err}")
endif()
string(REGEX MATCH "${SCENARIO}:[0-9]+:[0-9]+: " where "${err}")
if(where STREQUAL "")
  message(FATAL_ERROR "stderr does not name ${SCENARIO}:LINE:COL: ${err}")
endif()
if(NOT out STREQUAL "")
  message(FATAL_ERROR "stdout not empty: ${out}")
endif()
