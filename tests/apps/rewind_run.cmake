# tools/rewind-run: a tiny drop run (fsi-movie, checkpoints every 2 steps) rewound to step 4
# with a halved time step goes on from there with --continue at that step; bad requests
# (physics keys, a missing checkpoint, a value fsi-step refuses, an fsi-movie still writing
# the run) change nothing; fsi-sketch
# draws checkpoints from before and after the rewind.
# Inputs: -DMOVIE -DSTEP -DSKETCH -DSOURCE_DIR -DBINARY_DIR.
set(_dir ${BINARY_DIR}/test_tmp/rewind_run)
file(REMOVE_RECURSE ${_dir})
file(MAKE_DIRECTORY ${_dir})
set(_scenario ${SOURCE_DIR}/tests/data/tiny_drop.json)
set(_run ${_dir}/run)
include(${CMAKE_CURRENT_LIST_DIR}/run_tools.cmake)
function(rewind want)
  run_tool(rewind-run ${want} ${ARGN})
  set(_rewind_out "${_tool_out}" PARENT_SCOPE)
endfunction()
function(movie)
  run_movie(${_scenario} ${_run} ${ARGN})
endfunction()
function(expect_checkpoints want)
  file(GLOB _found RELATIVE ${_run}/checkpoints ${_run}/checkpoints/step_*.ckpt)
  list(SORT _found)
  if(NOT "${_found}" STREQUAL "${want}")
    message(FATAL_ERROR "checkpoints ${_found}, want ${want}")
  endif()
endfunction()

movie()
expect_checkpoints("step_000002.ckpt;step_000004.ckpt;step_000006.ckpt;step_000008.ckpt;step_000010.ckpt")

# Refused, nothing changed.
rewind(2 ${_run} 4 --set /fluid/density_kgpm3=2)
rewind(2 ${_run} four)
rewind(3 ${_run} 5)
rewind(1 ${_run} 4 --set /numerics/time_step_s=-1)
if(NOT _rewind_out MATCHES "time_step_s")
  message(FATAL_ERROR "the refused time step is not named: ${_rewind_out}")
endif()
expect_checkpoints("step_000002.ckpt;step_000004.ckpt;step_000006.ckpt;step_000008.ckpt;step_000010.ckpt")
if(EXISTS ${_run}/REWOUND.txt)
  message(FATAL_ERROR "a refused rewind wrote REWOUND.txt")
endif()

# An fsi-movie still writing the run is found however its OUTDIR was written: a stand-in
# named fsi-movie, started in the run's parent folder with the relative path "run".
file(WRITE ${_dir}/fsi-movie "#!/bin/sh\nsleep 60\n")
file(CHMOD ${_dir}/fsi-movie PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
execute_process(COMMAND sh -c "cd '${_dir}' && { ./fsi-movie scenario.json run > /dev/null 2>&1 & echo $! > writer.pid; }")
execute_process(COMMAND sleep 0.5)
rewind(3 ${_run} 4 --set /numerics/time_step_s=0.005)
execute_process(COMMAND sh -c "kill $(cat '${_dir}/writer.pid')")
if(NOT _rewind_out MATCHES "still writing")
  message(FATAL_ERROR "a running fsi-movie started with a relative OUTDIR was not found: ${_rewind_out}")
endif()
expect_checkpoints("step_000002.ckpt;step_000004.ckpt;step_000006.ckpt;step_000008.ckpt;step_000010.ckpt")

rewind(0 ${_run} 4 --set /numerics/time_step_s=0.005)
expect_checkpoints("step_000002.ckpt;step_000004.ckpt")
file(READ ${_run}/summary.json _summary)
if(NOT _summary MATCHES "\"final\": false")
  message(FATAL_ERROR "the rewound run's summary is still final")
endif()
file(READ ${_run}/REWOUND.txt _note)
if(NOT _note MATCHES "rewound to step 4 \\(t = 0.04")
  message(FATAL_ERROR "REWOUND.txt: ${_note}")
endif()
file(GLOB _backup ${_run}/rewound-*/step_000010.ckpt)
if(NOT _backup)
  message(FATAL_ERROR "the later checkpoints were not kept in rewound-*/")
endif()

# The old time step no longer fits the rewritten checkpoint; the new one goes on from t = 0.04.
execute_process(COMMAND ${MOVIE} ${_scenario} ${_run} --continue --no-png --no-video --no-vtu
    --quiet RESULT_VARIABLE _rc ERROR_VARIABLE _err)
if(_rc EQUAL 0 OR NOT _err MATCHES "fingerprint")
  message(FATAL_ERROR "continuing with the old time step was not refused: exit ${_rc}: ${_err}")
endif()
movie(--continue --set /numerics/time_step_s=0.005 --end-time 0.06)
file(STRINGS ${_run}/functionals.csv _rows)
list(GET _rows -1 _last)
string(REPLACE "," ";" _last "${_last}")
list(GET _last 0 _last_step)
list(GET _last 1 _last_time)
if(NOT _last_step EQUAL 8 OR _last_time LESS 0.0599 OR _last_time GREATER 0.0601)
  message(FATAL_ERROR "after the rewind: last row step ${_last_step} at t = ${_last_time}, want step 8 at 0.06")
endif()

# fsi-sketch draws the whole run: step 2 was written with the old time step and belongs to
# the scenario kept in rewound-*/scenario.json, the others to the run's scenario.json.
execute_process(COMMAND ${SKETCH} ${_run}/scenario.json ${_dir}/contours.png --size 320x240
    --contours ${_run}/checkpoints RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
if(NOT _rc EQUAL 0 OR NOT _out MATCHES "contours at t = 0, 0.02, 0.04, 0.05, 0.06 ")
  message(FATAL_ERROR "fsi-sketch of the rewound run: exit ${_rc}: ${_out}${_err}")
endif()
