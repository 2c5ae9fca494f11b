# `sreh-twin run BAD.yaml` must exit 2 with one line "sreh-twin: FILE:LINE:COL: ..."
# on stderr and nothing on stdout (interfaces.md exit codes). A first line
# "# expect: REGEX" in the file also requires the message to match REGEX
# (issue 12 regression inputs).
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
# One line, no raw control characters (issue 12).
string(REGEX MATCHALL "\n" newlines "${err}")
list(LENGTH newlines n)
if(NOT n EQUAL 1)
  message(FATAL_ERROR "stderr is not one line: ${err}")
endif()
string(ASCII 27 esc)
string(FIND "${err}" "${esc}" raw_escape)
if(NOT raw_escape EQUAL -1)
  message(FATAL_ERROR "stderr holds a raw escape character: ${err}")
endif()
file(STRINGS ${SCENARIO} first LIMIT_COUNT 1)
if(first MATCHES "^# expect: (.*)$")
  set(want "${CMAKE_MATCH_1}")
  if(NOT err MATCHES "${want}")
    message(FATAL_ERROR "stderr does not match '${want}': ${err}")
  endif()
endif()
