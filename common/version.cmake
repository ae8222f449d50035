# Writes the version header of the Lituya libraries (cmake -P script, run at every build so the
# commit is that of the sources being compiled, not of the last configure).
# In: VERSION, SOURCE_DIR, GIT_EXECUTABLE (may be empty or NOTFOUND), TEMPLATE, OUTPUT.
cmake_minimum_required(VERSION 3.20)
set(LITUYA_VERSION "${VERSION}")
set(LITUYA_COMMIT "unknown")

if(GIT_EXECUTABLE AND EXISTS "${GIT_EXECUTABLE}")
  # Only a checkout whose top is SOURCE_DIR counts: sources unpacked inside some other
  # repository must not report that repository's commit.
  execute_process(
    COMMAND "${GIT_EXECUTABLE}" rev-parse --show-toplevel
    WORKING_DIRECTORY "${SOURCE_DIR}"
    RESULT_VARIABLE top_result
    OUTPUT_VARIABLE top
    OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(top_result EQUAL 0)
    file(REAL_PATH "${top}" top)
    file(REAL_PATH "${SOURCE_DIR}" source)
    if(top STREQUAL source)
      # Without --dirty, describe only reads the repository; `describe --dirty` would refresh
      # the index (taking index.lock), which can collide with a commit running at that moment.
      execute_process(
        COMMAND "${GIT_EXECUTABLE}" describe --always
        WORKING_DIRECTORY "${SOURCE_DIR}"
        RESULT_VARIABLE describe_result
        OUTPUT_VARIABLE describe
        OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
      if(describe_result EQUAL 0 AND NOT describe STREQUAL "")
        set(LITUYA_COMMIT "${describe}")
        # --no-optional-locks: status must not write the index either.
        execute_process(
          COMMAND "${GIT_EXECUTABLE}" --no-optional-locks status --porcelain --untracked-files=no
          WORKING_DIRECTORY "${SOURCE_DIR}"
          RESULT_VARIABLE status_result
          OUTPUT_VARIABLE status
          OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
        if(status_result EQUAL 0 AND NOT status STREQUAL "")
          string(APPEND LITUYA_COMMIT "-dirty")
        endif()
      endif()
    endif()
  endif()
endif()

# configure_file rewrites OUTPUT only when its text changes, so an unchanged commit does not
# recompile provenance.cpp.
configure_file("${TEMPLATE}" "${OUTPUT}" @ONLY)
