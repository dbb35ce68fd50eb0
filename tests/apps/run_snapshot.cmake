# tools/run-snapshot: a tiny drop run (fsi-movie, checkpoints every 2 steps to step 10)
# saved with picture checkpoints every 0.04 s (4 steps) and restored into a fresh folder goes on
# with --continue exactly as the run that was never interrupted (bit-identical rows);
# a restore never overwrites a run, bad arguments are refused, and saving again after a
# rewind drops the picture checkpoints the rewind took back.
# Inputs: -DMOVIE -DSTEP -DSOURCE_DIR -DBINARY_DIR.
set(_dir ${BINARY_DIR}/test_tmp/run_snapshot)
file(REMOVE_RECURSE ${_dir})
file(MAKE_DIRECTORY ${_dir})
set(_scenario ${SOURCE_DIR}/tests/data/tiny_drop.json)
include(${CMAKE_CURRENT_LIST_DIR}/run_tools.cmake)
function(snapshot want)
  run_tool(run-snapshot ${want} ${ARGN})
endfunction()
function(movie run)
  run_movie(${_scenario} ${run} ${ARGN})
endfunction()
function(expect_files folder pattern want)
  file(GLOB _found RELATIVE ${folder} ${folder}/${pattern})
  list(SORT _found)
  if(NOT "${_found}" STREQUAL "${want}")
    message(FATAL_ERROR "${folder}: ${_found}, want ${want}")
  endif()
endfunction()

movie(${_dir}/whole --end-time 0.14)
movie(${_dir}/run --end-time 0.1)
snapshot(0 save ${_dir}/run ${_dir}/snap --keep-every-s 0.04)
expect_files(${_dir}/snap/checkpoints "*.xz" "step_000004.ckpt.xz;step_000008.ckpt.xz")
file(READ ${_dir}/snap/SNAPSHOT.txt _note)
if(NOT _note MATCHES "step_000010.ckpt")
  message(FATAL_ERROR "SNAPSHOT.txt does not name the latest checkpoint: ${_note}")
endif()

# Refused: bad arguments, a folder that is no run, a restore over a run.
snapshot(2 save ${_dir}/run)
snapshot(2 save ${_dir}/run ${_dir}/snap --keep-every-s 0)
snapshot(2 save ${_dir}/nowhere ${_dir}/snap2)
snapshot(2 restore ${_dir}/nowhere ${_dir}/other)
snapshot(3 restore ${_dir}/snap ${_dir}/run)

snapshot(0 restore ${_dir}/snap ${_dir}/restored)
expect_files(${_dir}/restored/checkpoints "step_*.ckpt" "step_000004.ckpt;step_000008.ckpt;step_000010.ckpt")
movie(${_dir}/restored --continue --end-time 0.14)
file(STRINGS ${_dir}/whole/functionals.csv _whole)
file(STRINGS ${_dir}/restored/functionals.csv _restored)
if(NOT "${_whole}" STREQUAL "${_restored}")
  message(FATAL_ERROR "the restored run did not go on as the uninterrupted one:\n${_restored}\nwant\n${_whole}")
endif()

# After a rewind to step 6 the picture checkpoint of step 8 is no longer the run's.
execute_process(COMMAND env FSI_STEP=${STEP} ${BASH} ${SOURCE_DIR}/tools/rewind-run ${_dir}/run 6
  RESULT_VARIABLE _rc OUTPUT_QUIET ERROR_QUIET)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "rewind-run: exit ${_rc}")
endif()
snapshot(0 save ${_dir}/run ${_dir}/snap --keep-every-s 0.04)
expect_files(${_dir}/snap/checkpoints "*.xz" "step_000004.ckpt.xz")
