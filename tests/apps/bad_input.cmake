# Bad input to fsi-movie and fsi-step: exit code 2 and a message naming the file, key
# or option (plus the usage line), never a crash.
# Inputs: -DMOVIE=<fsi-movie> -DSTEP=<fsi-step> -DSOURCE_DIR=<repo> -DBINARY_DIR=<build>.
set(_d ${SOURCE_DIR}/tests/data)
set(_out ${BINARY_DIR}/test_tmp/apps_bad_input)
file(REMOVE_RECURSE ${_out})
file(MAKE_DIRECTORY ${_out})
file(WRITE ${_out}/a_file "not a folder")
# "program|text the message must contain|arguments..."
set(_cases
  "MOVIE|no_such.json|${_d}/no_such.json|${_out}/m1"
  "MOVIE|bad_syntax.json|${_d}/bad_syntax.json|${_out}/m2"
  "MOVIE|/numerics/time_step_s|${_d}/tiny_drop.json|${_out}/m3|--set|/numerics/time_step_s=-1"
  "MOVIE|/numerics/bogus|${_d}/tiny_drop.json|${_out}/m4|--set|/numerics/bogus=1"
  "MOVIE|/nothing/here|${_d}/tiny_drop.json|${_out}/m5|--set|/nothing/here=1"
  "MOVIE|--set|${_d}/tiny_drop.json|${_out}/m6|--set|numerics"
  "MOVIE|/solid/mu_pa|${_d}/tiny_drop.json|${_out}/m7|--set|/solid/mu_pa=soft"
  "MOVIE|/method|${_d}/tiny_drop.json|${_out}/m7b|--set|/method=book"
  "MOVIE|--frobnicate|${_d}/tiny_drop.json|${_out}/m8|--frobnicate"
  "MOVIE|--size|${_d}/tiny_drop.json|${_out}/m9|--size|12"
  "MOVIE|--field|${_d}/tiny_drop.json|${_out}/m10|--field|q"
  "MOVIE|--zoom|${_d}/tiny_drop.json|${_out}/m11|--zoom|1,2,3"
  "MOVIE|--frame-every|${_d}/tiny_drop.json|${_out}/m12|--frame-every"
  "MOVIE|OUTDIR|${_d}/tiny_drop.json"
  "MOVIE|a_file|${_d}/tiny_drop.json|${_out}/a_file/sub|--end-time|0.01"
  "STEP|no_such.json|${_d}/no_such.json"
  "STEP|--frobnicate|${_d}/tiny_drop.json|--frobnicate"
  "STEP|SCENARIO.json")
foreach(_case IN LISTS _cases)
  string(REPLACE "|" ";" _args "${_case}")
  list(POP_FRONT _args _program _want)
  execute_process(COMMAND ${${_program}} ${_args} RESULT_VARIABLE _rc OUTPUT_VARIABLE _stdout
    ERROR_VARIABLE _stderr TIMEOUT 30 INPUT_FILE /dev/null)
  message("${_program} ${_args} -> ${_rc}: ${_stderr}")
  if(NOT _rc EQUAL 2)
    message(FATAL_ERROR "expected exit code 2, got ${_rc}")
  endif()
  string(FIND "${_stderr}" "${_want}" _at)
  if(_at LESS 0)
    message(FATAL_ERROR "the message should name '${_want}'")
  endif()
  string(FIND "${_stderr}" "usage:" _at)
  if(_at LESS 0 AND NOT _want STREQUAL "a_file")
    message(FATAL_ERROR "the message should come with the usage line")
  endif()
  if(NOT _stdout STREQUAL "")
    message(FATAL_ERROR "nothing may go to stdout on bad input, got: ${_stdout}")
  endif()
endforeach()
