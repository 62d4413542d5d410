# Runs a command and checks its exit code (and, optionally, that its output matches a regular expression).
#   cmake -DEXPECT_CODE=2 [-DEXPECT_REGEX=...] [-DTIMEOUT=seconds] -DCOMMAND="prog;arg1;arg2" -P expect_exit.cmake
# A hang is a failure: the command is killed after TIMEOUT seconds (120 by default).
if(NOT DEFINED TIMEOUT)
  set(TIMEOUT 120)
endif()
execute_process(COMMAND ${COMMAND} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT ${TIMEOUT})
if(NOT "${code}" STREQUAL "${EXPECT_CODE}")
  message(FATAL_ERROR "exit code ${code}, expected ${EXPECT_CODE}\nstdout:\n${out}\nstderr:\n${err}")
endif()
if(DEFINED EXPECT_REGEX AND NOT "${out}${err}" MATCHES "${EXPECT_REGEX}")
  message(FATAL_ERROR "output does not match '${EXPECT_REGEX}'\nstdout:\n${out}\nstderr:\n${err}")
endif()
