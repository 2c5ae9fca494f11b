# Runs `sreh-twin ARGS...` and checks the exit code (interfaces.md: 0 ok,
# 1 infeasible, 2 bad input), that bad input says why on stderr with nothing
# on stdout, and optionally that stdout matches a regular expression.
#   -DSREH_TWIN=... -DARGS="size|--angle-deg|90|..." -DEXPECT_RC=2 [-DSTDOUT_REGEX=...]
string(REPLACE "|" ";" args_list "${ARGS}")
execute_process(COMMAND ${SREH_TWIN} ${args_list}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL EXPECT_RC)
  message(FATAL_ERROR "exit code ${rc}, want ${EXPECT_RC}; stderr: ${err}")
endif()
if(EXPECT_RC EQUAL 2)
  if(NOT err MATCHES "^sreh-twin: ")
    message(FATAL_ERROR "stderr does not say why: ${err}")
  endif()
  if(NOT out STREQUAL "")
    message(FATAL_ERROR "stdout not empty: ${out}")
  endif()
endif()
if(DEFINED STDOUT_REGEX AND NOT out MATCHES "${STDOUT_REGEX}")
  message(FATAL_ERROR "stdout does not match ${STDOUT_REGEX}: ${out}")
endif()
