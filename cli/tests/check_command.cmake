# Runs LITUYA with ARGS ('|'-separated) and checks its exit code (CODE) and output: STDOUT and
# STDERR are regular expressions that must match, NOT_STDOUT one that must not, and EMPTY names
# the streams that must stay empty (stdout, stderr or both, e.g. "stdout,stderr").
cmake_minimum_required(VERSION 3.20)  # quoted arguments are strings, never variable names
string(REPLACE "|" ";" args "${ARGS}")
execute_process(
  COMMAND "${LITUYA}" ${args}
  RESULT_VARIABLE code
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err)
set(report "lituya ${args}\n--- exit code: ${code}\n--- stdout:\n${out}\n--- stderr:\n${err}")
if(NOT "${code}" STREQUAL "${CODE}")
  message(FATAL_ERROR "expected exit code ${CODE}\n${report}")
endif()
if(NOT "${STDOUT}" STREQUAL "" AND NOT out MATCHES "${STDOUT}")
  message(FATAL_ERROR "stdout does not match '${STDOUT}'\n${report}")
endif()
if(NOT "${STDERR}" STREQUAL "" AND NOT err MATCHES "${STDERR}")
  message(FATAL_ERROR "stderr does not match '${STDERR}'\n${report}")
endif()
if(NOT "${NOT_STDOUT}" STREQUAL "" AND out MATCHES "${NOT_STDOUT}")
  message(FATAL_ERROR "stdout matches '${NOT_STDOUT}', which it must not\n${report}")
endif()
if("${EMPTY}" MATCHES "stdout" AND NOT out STREQUAL "")
  message(FATAL_ERROR "stdout is not empty\n${report}")
endif()
if("${EMPTY}" MATCHES "stderr" AND NOT err STREQUAL "")
  message(FATAL_ERROR "stderr is not empty\n${report}")
endif()
