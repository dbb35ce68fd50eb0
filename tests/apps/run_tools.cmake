# Shared by the tests of the tools that change run folders (tools/rewind-run,
# tools/remesh-run, tools/run-snapshot): include()d, needs MOVIE, STEP, SOURCE_DIR.
find_program(BASH bash REQUIRED)

# run_tool(TOOL WANT ARGS...): tools/TOOL ARGS with FSI_STEP=${STEP}; fails unless it exits
# with WANT. Its output (stdout and stderr) is left in _tool_out.
function(run_tool tool want)
  execute_process(COMMAND env FSI_STEP=${STEP} ${BASH} ${SOURCE_DIR}/tools/${tool} ${ARGN}
    RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
  message("${tool} ${ARGN} -> ${_rc}: ${_out}${_err}")
  if(NOT _rc EQUAL want)
    message(FATAL_ERROR "${tool} ${ARGN}: exit ${_rc}, want ${want}")
  endif()
  set(_tool_out "${_out}${_err}" PARENT_SCOPE)
endfunction()

# run_movie(SCENARIO RUN ARGS...): fsi-movie into RUN with a checkpoint every 2 steps and no
# pictures, videos or VTK files.
function(run_movie scenario run)
  execute_process(COMMAND ${MOVIE} ${scenario} ${run} --checkpoint-every 2 --no-png --no-video
      --no-vtu --quiet ${ARGN} RESULT_VARIABLE _rc ERROR_VARIABLE _err)
  if(NOT _rc EQUAL 0)
    message(FATAL_ERROR "fsi-movie ${run} ${ARGN}: exit ${_rc}: ${_err}")
  endif()
endfunction()
