# tools/migrate-scenario (fsi-migrate-scenario): an old-format file comes out with the
# step limits as doublings, everything else as it stood; --keep-old-defaults adds
# "method": "chapter"; the result loads; bad input exits 2.
# Inputs: -DMIGRATE -DSOURCE_DIR -DBINARY_DIR.
set(_dir ${BINARY_DIR}/test_tmp/migrate_scenario)
file(REMOVE_RECURSE ${_dir})
file(MAKE_DIRECTORY ${_dir})
file(WRITE ${_dir}/old.json "{\n  \"name\": \"old_contact\",\n  \"contact\": {\"gamma_c\": 800, \"dist0_m\": 1e-2},\n  \"numerics\": {\"time_step_s\": 5e-4, \"time_step_max_s\": 2e-3, \"time_step_wall_zone_max_s\": 1e-3}\n}\n")
function(migrate want_rc out)
  execute_process(COMMAND ${MIGRATE} ${ARGN} RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
  message("fsi-migrate-scenario ${ARGN} -> ${_rc}: ${_out}${_err}")
  if(NOT _rc EQUAL want_rc)
    message(FATAL_ERROR "expected exit code ${want_rc}, got ${_rc}")
  endif()
  set(${out} "${_out}${_err}" PARENT_SCOPE)
endfunction()

migrate(0 _new ${_dir}/old.json)
foreach(_want "\"time_step_max_doublings\": 2" "\"time_step_wall_zone_doublings\": 1" "\"name\": \"old_contact\""
        "\"contact\": {\"gamma_c\": 800, \"dist0_m\": 1e-2}")
  string(FIND "${_new}" "${_want}" _at)
  if(_at LESS 0)
    message(FATAL_ERROR "migrated file lacks ${_want}")
  endif()
endforeach()
foreach(_gone "time_step_max_s" "method")
  string(FIND "${_new}" "${_gone}" _at)
  if(NOT _at LESS 0)
    message(FATAL_ERROR "migrated file still has ${_gone}")
  endif()
endforeach()

migrate(0 _kept ${_dir}/old.json --keep-old-defaults)
string(FIND "${_kept}" "\"method\": \"chapter\"" _at)
if(_at LESS 0)
  message(FATAL_ERROR "--keep-old-defaults did not add \"method\": \"chapter\"")
endif()
file(WRITE ${_dir}/kept.json "${_kept}")
# The migrated file migrates to itself.
migrate(0 _again ${_dir}/kept.json --keep-old-defaults)
if(NOT _again STREQUAL _kept)
  message(FATAL_ERROR "migrating a migrated file changed it:\n${_again}")
endif()

# Bad input: no file, an unknown option, a step limit below the step (names the key).
migrate(2 _e)
migrate(2 _e ${_dir}/old.json --bogus)
migrate(2 _e ${_dir}/missing.json)
file(WRITE ${_dir}/bad.json "{\"numerics\": {\"time_step_s\": 2e-3, \"time_step_max_s\": 1e-3}}\n")
migrate(2 _e ${_dir}/bad.json)
string(FIND "${_e}" "/numerics/time_step_max_s" _at)
if(_at LESS 0)
  message(FATAL_ERROR "the error does not name the key: ${_e}")
endif()
