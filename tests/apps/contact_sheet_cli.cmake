# Runs fsi-contact-sheet on goldens (as files and as a folder of them) and on bad
# input (frames of two sizes, a missing file, a bad --grid, no frames), checking exit
# codes (0 written, 2 bad input) and the sheet's size.
set(_g ${SOURCE_DIR}/tests/golden)
set(_out ${BINARY_DIR}/image-test-output/contact-sheet.png)
set(_frames ${_g}/field_vy_contour.png ${_g}/field_vmag_mesh.png ${_g}/field_p_fixed_range.png
  ${_g}/field_umag_zoom_stretched.png ${_g}/colorbar_cool_warm.png)
string(JOIN "|" _fr ${_frames})
# A folder of frames, as a run's frames/ is given.
set(_dir ${BINARY_DIR}/image-test-output/contact-sheet-frames)
file(REMOVE_RECURSE ${_dir})
file(COPY ${_frames} DESTINATION ${_dir})
set(_cases
  "0|${_out}|${_fr}|--grid|3x2|--tile-width|160"
  "0|${_out}|${_dir}"
  "2|${_out}|${_g}/field_vy_contour.png|${_g}/field_two_panels_inset.png"
  "2|${_out}|${SOURCE_DIR}/tests/data/no-such-file.png"
  "2|${_out}|${_fr}|--grid|3by2"
  "2|${_out}")
foreach(_case IN LISTS _cases)
  string(REPLACE "|" ";" _args "${_case}")
  list(POP_FRONT _args _want)
  file(REMOVE ${_out})
  execute_process(COMMAND ${SHEET} ${_args} RESULT_VARIABLE _rc OUTPUT_VARIABLE _o ERROR_VARIABLE _e)
  message("fsi-contact-sheet ${_args} -> ${_rc}: ${_o}${_e}")
  if(NOT _rc EQUAL _want)
    message(FATAL_ERROR "expected exit code ${_want}, got ${_rc}")
  endif()
endforeach()
# The first case again: five 320x240 frames in 160x120 tiles, 3 per row, 8 px gaps.
execute_process(COMMAND ${SHEET} ${_out} ${_frames} --tile-width 160 OUTPUT_VARIABLE _o)
if(NOT _o MATCHES "\\(512x264, 5 of 5 frames\\)")
  message(FATAL_ERROR "unexpected sheet: ${_o}")
endif()
