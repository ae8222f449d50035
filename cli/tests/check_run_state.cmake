# Honest run state and provenance, on the quick gravity column (issue 9, items 2 and 8).
# In: LITUYA, TIMEOUT (coreutils timeout, for MODE signals), SCENE (the column's scene),
# WORK (a scratch folder), MODE:
#   provenance    summary.toml and log.txt record version, commit, dates and the case hash;
#                 the hash changes with a case file; --force sets the earlier output aside.
#   signals       SIGINT and SIGTERM stop a solve with 130 and 143 and completed = false;
#                 SIGKILL leaves state "running" (written before the first step); post refuses
#                 each run unless --allow-incomplete.
#   final_output  a stage whose output_interval is longer than its duration still writes its
#                 state at exactly its duration.
cmake_minimum_required(VERSION 3.20)

# Runs the command; fails unless its exit code matches `expected` (a regular expression:
# "137|Subprocess killed", as execute_process reports a process a signal ended). Leaves stdout
# and stderr in `out` and `err`.
function(expect_exit expected)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE o ERROR_VARIABLE e)
  if(NOT "${code}" MATCHES "^(${expected})$")
    message(FATAL_ERROR "${ARGN}\nexpected exit code ${expected}, got ${code}\n"
                        "--- stdout:\n${o}\n--- stderr:\n${e}")
  endif()
  set(out "${o}" PARENT_SCOPE)
  set(err "${e}" PARENT_SCOPE)
endfunction()

function(expect_match text regex what)
  if(NOT text MATCHES "${regex}")
    message(FATAL_ERROR "${what} does not match '${regex}':\n${text}")
  endif()
endfunction()

# The scene, with its geometry made absolute (the copy lives in WORK) and its one stage
# changed by the key/value pairs given.
function(write_scene file)
  get_filename_component(source_dir "${SCENE}" DIRECTORY)
  file(READ "${SCENE}" text)
  string(REPLACE "geometry = \"column.geo\"" "geometry = \"${source_dir}/column.geo\"" text
                 "${text}")
  foreach(pair ${ARGN})
    string(REPLACE "=" ";" kv "${pair}")
    list(GET kv 0 key)
    list(GET kv 1 value)
    if(text MATCHES "\n${key} = [^\n]*")
      string(REGEX REPLACE "\n${key} = [^\n]*" "\n${key} = ${value}" text "${text}")
    else()
      string(REPLACE "\nduration = " "\n${key} = ${value}\nduration = " text "${text}")
    endif()
  endforeach()
  file(WRITE "${file}" "${text}")
endfunction()

file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
set(case "${WORK}/case")
set(summary "${case}/output/summary.toml")

if(MODE STREQUAL "provenance")
  write_scene("${WORK}/scene.toml")
  expect_exit(0 "${LITUYA}" pre "${WORK}/scene.toml" -o "${case}")
  expect_exit(0 "${LITUYA}" solve "${case}" --threads 1)
  file(READ "${summary}" s)
  expect_match("${s}" "state = 'completed'|state = \"completed\"" "summary.toml")
  expect_match("${s}" "completed = true" "summary.toml")
  expect_match("${s}" "lituya_version = ['\"][0-9]+\\.[0-9]+\\.[0-9]+" "summary.toml")
  expect_match("${s}" "commit = ['\"][^'\"]+['\"]" "summary.toml")
  set(date "[0-9][0-9][0-9][0-9]-[0-9][0-9]-[0-9][0-9]T[0-9][0-9]:[0-9][0-9]:[0-9][0-9]Z")
  expect_match("${s}" "started = ['\"]${date}['\"]" "summary.toml")
  expect_match("${s}" "finished = ['\"]${date}['\"]" "summary.toml")
  expect_match("${s}" "case_hash = ['\"]fnv1a64:[0-9a-f]+['\"]" "summary.toml")
  string(REGEX MATCH "fnv1a64:[0-9a-f]+" first_hash "${s}")
  file(READ "${case}/output/log.txt" log)
  expect_match("${log}" "^lituya [0-9.]+ \\(commit [^)]+\\), started ${date}, case [^\n]* \\(case files ${first_hash}\\)\n"
               "log.txt")
  expect_exit(0 "${LITUYA}" post "${case}")

  # Without --force nothing is touched; with it the earlier output moves to output.previous.
  file(WRITE "${case}/output/earlier.txt" "from the first run\n")
  expect_exit(1 "${LITUYA}" solve "${case}" --threads 1)
  expect_match("${err}" "already holds files" "stderr")
  expect_exit(0 "${LITUYA}" solve "${case}" --threads 1 --force)
  if(EXISTS "${case}/output/earlier.txt" OR NOT EXISTS "${case}/output.previous/earlier.txt"
     OR NOT EXISTS "${case}/output.previous/summary.toml")
    message(FATAL_ERROR "--force did not move the earlier output to output.previous")
  endif()
  file(READ "${summary}" s)
  string(REGEX MATCH "fnv1a64:[0-9a-f]+" same_hash "${s}")
  if(NOT same_hash STREQUAL first_hash)
    message(FATAL_ERROR "the same case files gave ${first_hash}, then ${same_hash}")
  endif()
  # A second --force replaces the older output.previous.
  expect_exit(0 "${LITUYA}" solve "${case}" --threads 1 --force)
  if(EXISTS "${case}/output.previous/earlier.txt")
    message(FATAL_ERROR "--force kept an output.previous older than the last run")
  endif()

  # A changed case file changes the hash (a comment: the run itself is the same).
  file(APPEND "${case}/materials.toml" "# edited\n")
  expect_exit(0 "${LITUYA}" solve "${case}" --threads 1 --force)
  file(READ "${summary}" s)
  string(REGEX MATCH "fnv1a64:[0-9a-f]+" edited_hash "${s}")
  if(edited_hash STREQUAL first_hash)
    message(FATAL_ERROR "editing materials.toml did not change the case hash ${first_hash}")
  endif()

elseif(MODE STREQUAL "signals")
  # A stage long enough to be interrupted (about four minutes if left alone), with outputs
  # every few milliseconds of wall time.
  write_scene("${WORK}/scene.toml" "duration=1000.0" "kinetic_energy_ratio=0.0"
              "output_interval=0.02")
  expect_exit(0 "${LITUYA}" pre "${WORK}/scene.toml" -o "${case}")
  # --preserve-status: timeout's exit code is then lituya's.
  foreach(signal INT TERM)
    if(signal STREQUAL "INT")
      set(code 130)
    else()
      set(code 143)
    endif()
    expect_exit(${code} "${TIMEOUT}" --preserve-status -s ${signal} 3 "${LITUYA}" solve "${case}"
                --threads 1 --force)
    expect_match("${err}" "stopped by SIG${signal} in stage 'gravity' at t = " "stderr")
    file(READ "${summary}" s)
    expect_match("${s}" "state = ['\"]stopped['\"]" "summary.toml after SIG${signal}")
    expect_match("${s}" "completed = false" "summary.toml after SIG${signal}")
    expect_match("${s}" "reason = ['\"]stopped by SIG${signal}" "summary.toml after SIG${signal}")
    # The last state is in the series: the last file the .pvd lists exists.
    file(READ "${case}/output/gravity_points.pvd" pvd)
    string(REGEX MATCHALL "file=\"[^\"]+\"" files "${pvd}")
    list(GET files -1 last)
    string(REGEX REPLACE "file=\"([^\"]+)\"" "\\1" last "${last}")
    if(NOT EXISTS "${case}/output/${last}")
      message(FATAL_ERROR "the .pvd lists ${last}, which was not written")
    endif()
    expect_exit(6 "${LITUYA}" post "${case}")
    expect_match("${err}" "did not complete \\(state \"stopped\": stopped by SIG${signal}" "stderr")
    expect_exit(0 "${LITUYA}" post "${case}" --allow-incomplete --force)
  endforeach()
  # The SIGTERM run set the SIGINT run aside.
  file(READ "${case}/output.previous/summary.toml" previous)
  expect_match("${previous}" "stopped by SIGINT" "output.previous/summary.toml")

  # SIGKILL cannot be caught: the summary written before the first step says "running".
  # timeout re-raises SIGKILL on itself with --preserve-status.
  expect_exit("137|Subprocess killed" "${TIMEOUT}" --preserve-status -s KILL 3 "${LITUYA}" solve "${case}" --threads 1
              --force)
  file(READ "${summary}" s)
  expect_match("${s}" "state = ['\"]running['\"]" "summary.toml after SIGKILL")
  expect_match("${s}" "completed = false" "summary.toml after SIGKILL")
  expect_exit(6 "${LITUYA}" post "${case}")
  expect_match("${err}" "killed or is still running" "stderr")

elseif(MODE STREQUAL "final_output")
  # About 30 steps; the output interval is 100 times the stage.
  write_scene("${WORK}/scene.toml" "duration=0.01" "kinetic_energy_ratio=0.0"
              "output_interval=1.0")
  expect_exit(0 "${LITUYA}" run "${WORK}/scene.toml" -o "${case}" --threads 1)
  file(READ "${case}/output/gravity_points.pvd" pvd)
  expect_match("${pvd}" "timestep=\"0\"[^\n]*\n[^\n]*timestep=\"0.01\"" "gravity_points.pvd")
  file(READ "${summary}" s)
  expect_match("${s}" "simulated_time = 0.01[0-9]*\n" "summary.toml")
else()
  message(FATAL_ERROR "unknown MODE '${MODE}'")
endif()
