# tools/remesh-run: a tiny drop run (fsi-movie, checkpoints every 2 steps) moved onto
# another mesh of the same box goes on from its latest checkpoint with --continue on the
# new mesh; every checkpoint is remeshed (fsi-sketch draws them with the new
# scenario.json), the originals are kept; a mesh reaching beyond the run's domain, or a
# missing mesh file, changes nothing.
# Inputs: -DMOVIE -DSTEP -DSKETCH -DSOURCE_DIR -DBINARY_DIR.
set(_dir ${BINARY_DIR}/test_tmp/remesh_run)
file(REMOVE_RECURSE ${_dir})
file(MAKE_DIRECTORY ${_dir})
set(_scenario ${SOURCE_DIR}/tests/data/tiny_drop.json)
set(_run ${_dir}/run)
include(${CMAKE_CURRENT_LIST_DIR}/run_tools.cmake)
function(remesh want)
  run_tool(remesh-run ${want} ${ARGN})
  set(_remesh_out "${_tool_out}" PARENT_SCOPE)
endfunction()
function(movie scenario)
  run_movie(${scenario} ${_run} ${ARGN})
endfunction()

# The same box, other patch lines (tiny_drop.json has 8 + 8 x 16 patches).
file(READ ${_scenario} _text)
string(REPLACE "\"patches\": 8, \"first_m\": 0.05" "\"patches\": 7, \"first_m\": 0.04" _other "${_text}")
string(REPLACE "\"patches\": 16, \"first_m\": 0.00625" "\"patches\": 13, \"first_m\": 0.01" _other "${_other}")
if(_other STREQUAL _text)
  message(FATAL_ERROR "the test's mesh edit did not apply to ${_scenario}")
endif()
file(WRITE ${_dir}/other_mesh.json "${_other}")
string(REPLACE "\"to_m\": 0.5" "\"to_m\": 0.7" _taller "${_other}")
file(WRITE ${_dir}/taller.json "${_taller}")

movie(${_scenario} --set /numerics/end_time_s=0.06)
file(READ ${_run}/checkpoints/step_000006.ckpt _before HEX)

# Refused, nothing changed.
remesh(2 ${_run} ${_dir}/missing.json)
remesh(2 ${_run} ${_dir}/other_mesh.json --keep-every-s)
remesh(3 ${_run} ${_dir}/taller.json)
if(NOT _remesh_out MATCHES "outside the old mesh")
  message(FATAL_ERROR "the mesh beyond the old domain was not named as the reason: ${_remesh_out}")
endif()
file(READ ${_run}/checkpoints/step_000006.ckpt _after HEX)
if(NOT _after STREQUAL _before OR EXISTS ${_run}/REMESHED.txt)
  message(FATAL_ERROR "a refused remesh changed the run")
endif()

remesh(0 ${_run} ${_dir}/other_mesh.json)
file(GLOB _originals ${_run}/remeshed-*/checkpoints/step_*.ckpt)
list(LENGTH _originals _n)
if(NOT _n EQUAL 3)
  message(FATAL_ERROR "want the 3 original checkpoints kept in remeshed-*/, got ${_n}")
endif()
file(READ ${_run}/REMESHED.txt _note)
if(NOT _note MATCHES "3 checkpoint\\(s\\) up to step_000006.ckpt remeshed")
  message(FATAL_ERROR "REMESHED.txt: ${_note}")
endif()
file(READ ${_run}/scenario.json _json)
if(NOT _json MATCHES "\"patches\": 13")
  message(FATAL_ERROR "scenario.json does not have the new mesh")
endif()

# The run goes on on the new mesh (the checkpoint fits only the new mesh's scenario) ...
movie(${_dir}/other_mesh.json --continue --set /numerics/end_time_s=0.1)
file(STRINGS ${_run}/functionals.csv _rows)
list(LENGTH _rows _n)
if(NOT _n EQUAL 11)
  message(FATAL_ERROR "want the header and 10 steps in functionals.csv, got ${_n} rows")
endif()
# ... and the earlier checkpoints draw with the run's new scenario.
execute_process(COMMAND ${SKETCH} ${_run}/scenario.json ${_dir}/contours.png --contours ${_run}/checkpoints
  RESULT_VARIABLE _rc ERROR_VARIABLE _err)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "fsi-sketch of the remeshed checkpoints: exit ${_rc}: ${_err}")
endif()
