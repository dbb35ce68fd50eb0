# Runs fsi-imgdiff on known inputs and checks the exit code of each case:
# 0 same, 1 differ, 2 bad input (missing file, size mismatch, bad option).
set(_g ${SOURCE_DIR}/tests/golden)
set(_cases
  "0|${_g}/plot_log.png|${_g}/plot_log.png"
  "1|${_g}/plot_log.png|${_g}/plot_functionals.png"
  "0|${_g}/plot_log.png|${_g}/plot_functionals.png|--max-bad-fraction|0.5|--threshold|255"
  "2|${_g}/plot_log.png|${SOURCE_DIR}/tests/data/no-such-file.png"
  "2|${_g}/plot_log.png|${SOURCE_DIR}/tests/data/tiny_7x5.png"
  "2|${_g}/plot_log.png|${_g}/plot_log.png|--threshold|many")
foreach(_case IN LISTS _cases)
  string(REPLACE "|" ";" _args "${_case}")
  list(POP_FRONT _args _want)
  execute_process(COMMAND ${IMGDIFF} ${_args} RESULT_VARIABLE _rc OUTPUT_VARIABLE _out
    ERROR_VARIABLE _err)
  message("fsi-imgdiff ${_args} -> ${_rc}: ${_out}${_err}")
  if(NOT _rc EQUAL _want)
    message(FATAL_ERROR "expected exit code ${_want}, got ${_rc}")
  endif()
endforeach()
# The diff image is written where asked.
file(REMOVE ${BINARY_DIR}/image-test-output/imgdiff-diff.png)
execute_process(COMMAND ${IMGDIFF} ${_g}/plot_log.png ${_g}/plot_functionals.png
  --diff ${BINARY_DIR}/image-test-output/imgdiff-diff.png OUTPUT_QUIET)
if(NOT EXISTS ${BINARY_DIR}/image-test-output/imgdiff-diff.png)
  message(FATAL_ERROR "--diff did not write its image")
endif()
