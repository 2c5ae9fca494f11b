# The one command-line test harness (issue 13). Runs sreh-twin and checks the
# contract of interfaces.md: the exit code; for exit 2 (bad input) one line on
# stderr starting "sreh-twin: " and nothing on stdout; optional regular
# expressions for stdout and stderr; optionally that stderr names FILE:LINE:COL.
#   -DCMD="<sreh-twin>;arg;arg" -DEXIT=<code> [-DSTDOUT_MATCH=re] [-DSTDERR_MATCH=re] [-DWHERE=FILE]
execute_process(COMMAND ${CMD} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL EXIT)
  message(FATAL_ERROR "exit ${rc}, expected ${EXIT}\nstdout: ${out}\nstderr: ${err}")
endif()
if(EXIT EQUAL 2)
  if(NOT err MATCHES "^sreh-twin: ")
    message(FATAL_ERROR "stderr does not say why: ${err}")
  endif()
  if(NOT out STREQUAL "")
    message(FATAL_ERROR "stdout not empty: ${out}")
  endif()
endif()
if(DEFINED WHERE)
  string(FIND "${err}" "${WHERE}:" at)
  if(at EQUAL -1 OR NOT err MATCHES ":[0-9]+:[0-9]+: ")
    message(FATAL_ERROR "stderr does not name ${WHERE}:LINE:COL: ${err}")
  endif()
endif()
if(DEFINED STDOUT_MATCH AND NOT out MATCHES "${STDOUT_MATCH}")
  message(FATAL_ERROR "stdout does not match '${STDOUT_MATCH}':\n${out}")
endif()
if(DEFINED STDERR_MATCH AND NOT err MATCHES "${STDERR_MATCH}")
  message(FATAL_ERROR "stderr does not match '${STDERR_MATCH}':\n${err}")
endif()
