# Runs fsi-step on tests/data/fsi_step_script.txt and checks every answer: one JSON line
# per command (blank and comment lines get none, nothing after quit), "ok" answers with
# their keys, "error" answers naming what was wrong, the rendered PNGs on disk, and a
# checkpoint that restores the functionals exactly.
# Inputs: -DSTEP=<fsi-step> -DSOURCE_DIR=<repo> -DBINARY_DIR=<build>.
set(_out ${BINARY_DIR}/test_tmp/fsi_step_script)
file(REMOVE_RECURSE ${_out})
file(MAKE_DIRECTORY ${_out})
file(READ ${SOURCE_DIR}/tests/data/fsi_step_script.txt _script)
string(REPLACE "OUT_DIR" "${_out}" _script "${_script}")
file(WRITE ${_out}/script.txt "${_script}")
execute_process(COMMAND ${STEP} ${SOURCE_DIR}/tests/data/tiny_drop.json
  INPUT_FILE ${_out}/script.txt OUTPUT_VARIABLE _stdout ERROR_VARIABLE _stderr
  RESULT_VARIABLE _rc TIMEOUT 60)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "fsi-step exited with ${_rc}: ${_stderr}")
endif()

# One expectation per answer: "ok|key,key,..." (keys that must be present) or
# "error|text the message must contain".
set(_expect
  "ok|commands"                                  # help
  "ok|t,step,functionals"                        # functionals
  "ok|t,step,converged_steps,unconverged_steps,last_message,last_report,functionals"  # step 3
  "ok|numerics" "ok|numerics" "ok|numerics"      # set x3
  "ok|numerics"                                  # numerics
  "ok|converged_steps"                           # step
  "ok|functionals"                               # functionals (saved below)
  "ok|file,field,width,height,range"             # render p
  "ok|file,range"                                # render zoom
  "ok|file,stretch" "ok|file,stretch"            # render gap, kept aspect and stretched
  "ok|file"                                      # save
  "ok|converged_steps"                           # step 2
  "ok|file"                                      # load
  "ok|functionals"                               # functionals (after load)
  "ok|quality"                                   # quality
  "error|quality"                                # quality with an argument
  "error|bogus"
  "error|step N"
  "error|step N"
  "error|/numerics/time_step_s"
  "error|no_such_key"
  "error|/numerics/newton_budget"
  "error|field"
  "error|zoom"
  "error|stretch"
  "error|no_such_checkpoint"
  "ok|bye")

# Splits stdout into lines by hand: CMake lists mangle JSON's brackets and semicolons.
set(_rest "${_stdout}")
set(_answers 0)
set(_functionals_before_save "")
foreach(_want IN LISTS _expect)
  string(FIND "${_rest}" "\n" _nl)
  if(_nl LESS 0)
    message(FATAL_ERROR "only ${_answers} answers, more expected; stdout:\n${_stdout}\nstderr:\n${_stderr}")
  endif()
  string(SUBSTRING "${_rest}" 0 ${_nl} _line)
  math(EXPR _next "${_nl} + 1")
  string(SUBSTRING "${_rest}" ${_next} -1 _rest)
  math(EXPR _answers "${_answers} + 1")
  string(JSON _type ERROR_VARIABLE _bad TYPE "${_line}")
  if(_bad OR NOT _type STREQUAL "OBJECT")
    message(FATAL_ERROR "answer ${_answers} is not a JSON object: ${_line}")
  endif()
  string(REPLACE "|" ";" _parts "${_want}")
  list(GET _parts 0 _kind)
  list(GET _parts 1 _what)
  if(_kind STREQUAL "ok")
    string(JSON _ok ERROR_VARIABLE _bad GET "${_line}" ok)
    if(_bad OR NOT _ok STREQUAL "ON")
      message(FATAL_ERROR "answer ${_answers} should be ok: ${_line}")
    endif()
    string(REPLACE "," ";" _keys "${_what}")
    foreach(_key IN LISTS _keys)
      string(JSON _v ERROR_VARIABLE _bad GET "${_line}" ${_key})
      if(_bad)
        message(FATAL_ERROR "answer ${_answers} lacks '${_key}': ${_line}")
      endif()
    endforeach()
  else()
    string(JSON _msg ERROR_VARIABLE _bad GET "${_line}" error)
    if(_bad)
      message(FATAL_ERROR "answer ${_answers} should be an error: ${_line}")
    endif()
    string(FIND "${_msg}" "${_what}" _at)
    if(_at LESS 0)
      message(FATAL_ERROR "error ${_answers} should mention '${_what}': ${_msg}")
    endif()
  endif()
  if(_answers EQUAL 3)
    string(JSON _step GET "${_line}" step)
    if(NOT _step EQUAL 3)
      message(FATAL_ERROR "step 3 from step 0 should reach step 3: ${_line}")
    endif()
    # The last step's report: Newton's residual history, starting above where it ended.
    string(JSON _norms ERROR_VARIABLE _bad LENGTH "${_line}" last_report residual_norms)
    if(_bad OR _norms LESS 2)
      message(FATAL_ERROR "last_report should list the residual norms: ${_line}")
    endif()
    math(EXPR _last "${_norms} - 1")
    string(JSON _first GET "${_line}" last_report residual_norms 0)
    string(JSON _final GET "${_line}" last_report residual_norms ${_last})
    if(NOT _final LESS _first)
      message(FATAL_ERROR "the residual should fall within a step: ${_line}")
    endif()
    foreach(_key factorizations newton_iterations seconds events)
      string(JSON _v ERROR_VARIABLE _bad GET "${_line}" last_report ${_key})
      if(_bad)
        message(FATAL_ERROR "last_report lacks '${_key}': ${_line}")
      endif()
    endforeach()
  elseif(_answers EQUAL 9)
    string(JSON _functionals_before_save GET "${_line}" functionals)
  elseif(_answers EQUAL 17)
    string(JSON _after GET "${_line}" functionals)
    if(NOT _after STREQUAL _functionals_before_save)
      message(FATAL_ERROR "load did not restore the saved state:\n${_functionals_before_save}\n${_after}")
    endif()
  endif()
endforeach()
if(NOT _rest STREQUAL "")
  message(FATAL_ERROR "answers after quit (or extra answers): ${_rest}")
endif()

foreach(_png step_frame.png step_zoom.png step_gap.png step_gap_stretched.png)
  if(NOT EXISTS ${_out}/${_png})
    message(FATAL_ERROR "render did not write ${_out}/${_png}")
  endif()
  file(READ ${_out}/${_png} _magic LIMIT 8 HEX)
  if(NOT _magic STREQUAL "89504e470d0a1a0a")
    message(FATAL_ERROR "${_png} is not a PNG (${_magic})")
  endif()
endforeach()
# A 1 m x 5 cm window: letterboxed into a thin strip with the aspect kept, filling the
# plot area when stretched, so the two pictures differ.
file(SHA256 ${_out}/step_gap.png _kept)
file(SHA256 ${_out}/step_gap_stretched.png _stretched)
if(_kept STREQUAL _stretched)
  message(FATAL_ERROR "render stretch=1 drew the same picture as with the aspect kept")
endif()

# --exit-on-error: a script whose "load" fails must not go on stepping from t = 0.
file(WRITE ${_out}/strict.txt "step 1\nload ${_out}/no_such_checkpoint.ckpt\nstep 1\nquit\n")
execute_process(COMMAND ${STEP} ${SOURCE_DIR}/tests/data/tiny_drop.json --exit-on-error
  INPUT_FILE ${_out}/strict.txt OUTPUT_VARIABLE _strict_out ERROR_VARIABLE _strict_err
  RESULT_VARIABLE _strict_rc TIMEOUT 60)
string(REGEX MATCHALL "\n" _strict_lines "${_strict_out}")
list(LENGTH _strict_lines _strict_count)
if(NOT _strict_rc EQUAL 3 OR NOT _strict_count EQUAL 2 OR NOT _strict_out MATCHES "no_such_checkpoint"
   OR NOT _strict_err MATCHES "exit-on-error")
  message(FATAL_ERROR "--exit-on-error should stop after the failed load with exit code 3 "
                      "(got ${_strict_rc}, ${_strict_count} answers):\n${_strict_out}\n${_strict_err}")
endif()
# A scene of two bodies: the step's answer carries each body's functionals.
file(WRITE ${_out}/bodies.txt "step 1\nquit\n")
execute_process(COMMAND ${STEP} ${SOURCE_DIR}/assets/scenarios/bodies/two_balls_collide.json
  INPUT_FILE ${_out}/bodies.txt OUTPUT_VARIABLE _bodies_out ERROR_VARIABLE _bodies_err
  RESULT_VARIABLE _bodies_rc TIMEOUT 60)
if(NOT _bodies_rc EQUAL 0 OR NOT _bodies_out MATCHES "\"bodies\":\\[\\{\"centroid_x_m\":-0\\.4[0-9]*,\"centroid_y_m\"[^]]*\\},\\{\"centroid_x_m\":0\\.4")
  message(FATAL_ERROR "fsi-step's step answer on two bodies has no bodies' functionals (exit ${_bodies_rc}):\n${_bodies_out}\n${_bodies_err}")
endif()
message("fsi-step script: ${_answers} answers as expected")
