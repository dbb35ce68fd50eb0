# tools/study-rewind: two tiny drop runs of a "study" (checkpoints every 2 steps, k = 0.01 s)
# go back to their latest checkpoint at or before t = 0.05 s (step 4) with
# backflow_beta = 1; --only picks one run; each run's study-settings.txt gets the setting
# (a line of the same key replaced in place, no duplicates on a second call); bad requests
# change nothing; the rewound run goes on with the new setting.
# Inputs: -DMOVIE -DSTEP -DSOURCE_DIR -DBINARY_DIR.
set(_dir ${BINARY_DIR}/test_tmp/study_rewind)
file(REMOVE_RECURSE ${_dir})
file(MAKE_DIRECTORY ${_dir}/study)
set(_scenario ${SOURCE_DIR}/tests/data/tiny_drop.json)
include(${CMAKE_CURRENT_LIST_DIR}/run_tools.cmake)
function(expect_checkpoints run want)
  file(GLOB _found RELATIVE ${_dir}/study/${run}/checkpoints ${_dir}/study/${run}/checkpoints/step_*.ckpt)
  list(SORT _found)
  if(NOT "${_found}" STREQUAL "${want}")
    message(FATAL_ERROR "${run}: checkpoints ${_found}, want ${want}")
  endif()
endfunction()
function(expect_settings run want)
  file(READ ${_dir}/study/${run}/study-settings.txt _have)
  if(NOT _have STREQUAL want)
    message(FATAL_ERROR "${run}/study-settings.txt: '${_have}', want '${want}'")
  endif()
endfunction()
set(_all "step_000002.ckpt;step_000004.ckpt;step_000006.ckpt;step_000008.ckpt;step_000010.ckpt")

run_movie(${_scenario} ${_dir}/study/a)
run_movie(${_scenario} ${_dir}/study/b)
file(WRITE ${_dir}/study/b/study-settings.txt "/numerics/time_step_wall_zone_doublings=2\n/numerics/backflow_beta=0.5\n")

# Refused, nothing changed.
run_tool(study-rewind 2 ${_dir}/study 0.05)
run_tool(study-rewind 2 ${_dir}/study soon --set /numerics/backflow_beta=1)
run_tool(study-rewind 2 ${_dir}/study 0.05 --set /fluid/density_kgpm3=2)
run_tool(study-rewind 3 ${_dir}/study 0.01 --set /numerics/backflow_beta=1)
if(NOT _tool_out MATCHES "no checkpoint at or before")
  message(FATAL_ERROR "a run without an early enough checkpoint is not named: ${_tool_out}")
endif()
run_tool(study-rewind 1 ${_dir}/study 0.05 --only a --set /numerics/backflow_beta=7)
expect_checkpoints(a "${_all}")
expect_checkpoints(b "${_all}")

run_tool(study-rewind 0 ${_dir}/study 0.05 --only a --set /numerics/backflow_beta=1)
expect_checkpoints(a "step_000002.ckpt;step_000004.ckpt")
expect_checkpoints(b "${_all}")
expect_settings(a "/numerics/backflow_beta=1\n")

run_tool(study-rewind 0 ${_dir}/study 0.05 --set /numerics/backflow_beta=1)
expect_checkpoints(b "step_000002.ckpt;step_000004.ckpt")
expect_settings(a "/numerics/backflow_beta=1\n")
expect_settings(b "/numerics/time_step_wall_zone_doublings=2\n/numerics/backflow_beta=1\n")
if(NOT _tool_out MATCHES "--set /numerics/backflow_beta=1")
  message(FATAL_ERROR "the settings to go on with are not printed: ${_tool_out}")
endif()

# The rewound checkpoint holds the new setting: the run goes on with it, not without.
execute_process(COMMAND ${MOVIE} ${_scenario} ${_dir}/study/a --continue --no-png --no-video --no-vtu
    --quiet RESULT_VARIABLE _rc ERROR_VARIABLE _err)
if(_rc EQUAL 0 OR NOT _err MATCHES "fingerprint")
  message(FATAL_ERROR "continuing without backflow_beta = 1 was not refused: exit ${_rc}: ${_err}")
endif()
run_movie(${_scenario} ${_dir}/study/a --continue --set /numerics/backflow_beta=1 --end-time 0.06)
file(STRINGS ${_dir}/study/a/functionals.csv _rows)
list(GET _rows -1 _last)
if(NOT _last MATCHES "^6,0.06")
  message(FATAL_ERROR "the rewound run did not go on from step 4 to step 6: ${_last}")
endif()
