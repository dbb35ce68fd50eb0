# fsi-sketch: the geometry picture, and --contours drawing the interface of a run's
# checkpoints (made here by fsi-movie on the tiny drop) over it; checkpoints of another
# scenario and bad options are refused with exit code 2 and a message.
# Inputs: -DSKETCH -DMOVIE -DIMGDIFF -DSOURCE_DIR -DBINARY_DIR.
set(_dir ${BINARY_DIR}/test_tmp/sketch_cli)
file(REMOVE_RECURSE ${_dir})
file(MAKE_DIRECTORY ${_dir})
set(_scenario ${SOURCE_DIR}/tests/data/tiny_drop.json)
function(run_sketch want want_text)
  execute_process(COMMAND ${SKETCH} ${_scenario} ${ARGN}
    RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
  message("fsi-sketch ${ARGN} -> ${_rc}: ${_out}${_err}")
  if(NOT _rc EQUAL want)
    message(FATAL_ERROR "fsi-sketch ${ARGN}: exit ${_rc}, want ${want}")
  endif()
  string(FIND "${_out}${_err}" "${want_text}" _at)
  if(_at LESS 0)
    message(FATAL_ERROR "fsi-sketch ${ARGN}: the output should contain '${want_text}'")
  endif()
endfunction()

execute_process(COMMAND ${MOVIE} ${_scenario} ${_dir}/run --checkpoint-every 2 --no-png
    --no-video --no-vtu --quiet RESULT_VARIABLE _rc ERROR_VARIABLE _err)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "fsi-movie for the checkpoints: exit ${_rc}: ${_err}")
endif()

run_sketch(0 "walls" ${_dir}/plain.png --size 320x240)
run_sketch(0 "contours at t = 0, 0.02, 0.04, 0.06, 0.08, 0.1 " ${_dir}/contours.png --size 320x240
           --contours ${_dir}/run/checkpoints)
run_sketch(0 "contours at t = 0, 0.1 " ${_dir}/one.png --size 320x240
           --contours ${_dir}/run/checkpoints/step_000010.ckpt)
# Every 3rd checkpoint (steps 2 and 8) and the last one.
run_sketch(0 "contours at t = 0, 0.02, 0.08, 0.1 " ${_dir}/every.png --size 320x240
           --contours ${_dir}/run/checkpoints --every 3)
execute_process(COMMAND ${IMGDIFF} ${_dir}/plain.png ${_dir}/contours.png RESULT_VARIABLE _differs)
if(NOT _differs EQUAL 1)
  message(FATAL_ERROR "the contours picture should differ from the plain sketch (imgdiff ${_differs})")
endif()

run_sketch(2 "fingerprint" ${_dir}/bad.png --set /solid/mu_pa=4e5 --contours ${_dir}/run/checkpoints)
run_sketch(2 "no such file" ${_dir}/bad.png --contours ${_dir}/no_such_folder)
run_sketch(2 "no step_*.ckpt" ${_dir}/bad.png --contours ${_dir})
run_sketch(2 "--every" ${_dir}/bad.png --contours ${_dir}/run/checkpoints --every 0)
run_sketch(2 "--size" ${_dir}/bad.png --size 5x5)
run_sketch(2 "--bogus" ${_dir}/bad.png --bogus)
