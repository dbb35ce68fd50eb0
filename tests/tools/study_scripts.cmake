# The study scripts' shared pieces, without running the engine:
#  - tools/study-bounce.awk on small hand-made CSVs (a real double bounce, the wiggle of a
#    dimple's rim while the ball still approaches, a run that stopped while rising);
#  - tools/study-common.sh's --set/--out: a run directory records its settings, is reused
#    with the same ones, continued to a later end time and refused with other settings
#    (a stub stands in for fsi-movie); tools/validate-example1's rows likewise;
#  - tools/study-shapes' landing, bounce and rotation on a stub run;
#  - tools/study-bodies' gap, mirror error and force-law prediction on a stub run.
# Inputs: -DSOURCE_DIR -DBINARY_DIR.
find_program(AWK NAMES awk mawk gawk REQUIRED)
find_program(BASH bash REQUIRED)
set(_dir ${BINARY_DIR}/tools-test-output/study-scripts)
file(REMOVE_RECURSE ${_dir})
file(MAKE_DIRECTORY ${_dir})

function(expect_bounce csv want)
  execute_process(COMMAND ${AWK} ${ARGN} -f ${SOURCE_DIR}/tools/study-bounce.awk ${_dir}/${csv}
    RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT _rc EQUAL 0 OR NOT _out STREQUAL want)
    message(FATAL_ERROR "study-bounce.awk ${ARGN} ${csv}: got '${_out}' (exit ${_rc}, ${_err}), want '${want}'")
  endif()
endfunction()

set(_head "time_s,min_distance_m,mean_vy_mps,mass_error\n")
# Falls, rebounds to 5 cm, falls, rebounds to 1 cm, settles 2 mm up (at rest from t = 8:
# the last row at or before t_end - 0.25 s is t = 8, |v_y| <= 1e-4 m/s from there on).
file(WRITE ${_dir}/bounce.csv "${_head}0,0.1,-0.3,0\n1,0.001,-0.1,0\n2,0.02,0.2,0\n3,0.05,0,0\n4,0.02,-0.2,0\n5,0.001,-0.1,0\n6,0.01,0.1,0\n7,0.004,-0.1,0\n8,0.002,0,0\n8.1,0.002,5e-5,0\n8.3,0.002,-2e-6,0\n")
expect_bounce(bounce.csv "5.000000e-02,1.000000e-02,2.000000e-03")
# The same ball sinking slowly at the end (-2e-4 m/s and faster): no rest distance;
# nor when the slow rows do not span the window (the ball stopped only 0.1 s before the end).
file(WRITE ${_dir}/sinking.csv "${_head}0,0.1,-0.3,0\n1,0.001,-0.1,0\n2,0.02,0.2,0\n3,0.05,0,0\n4,0.003,-0.2,0\n5,0.0029,-2e-4,0\n5.3,0.0028,-3e-4,0\n")
expect_bounce(sinking.csv "5.000000e-02,,")
file(WRITE ${_dir}/stopping.csv "${_head}0,0.1,-0.3,0\n1,0.003,-0.2,0\n2,0.0029,-2e-3,0\n2.1,0.0029,0,0\n2.2,0.0029,0,0\n")
expect_bounce(stopping.csv ",,")
# The distance under a deforming rim rises 0.6 mm while the ball still moves down: no rebound.
file(WRITE ${_dir}/wiggle.csv "${_head}0,0.1,-0.3,0\n1,0.0026,-0.11,0\n2,0.0032,-0.11,0\n3,0,-0.11,0\n4,0,0,0\n4.5,0,0,0\n")
expect_bounce(wiggle.csv ",,0.000000e+00")
# Rising in the last row: a rebound cut short by the end time, but not when the run stopped
# early; the degenerated last row (mass error 1.9 > 0.5) is skipped either way; a rising
# ball is not at rest (no rest distance).
file(WRITE ${_dir}/rising.csv "${_head}0,0.1,-0.3,0\n1,0.001,-0.1,0\n2,0.003,0.1,0\n3,7.5,-0.5,1.9\n")
expect_bounce(rising.csv "3.000000e-03,,")
expect_bounce(rising.csv ",," -v stopped_early=1)

# tools/landings.awk: the ball over wall 1 (the lower of two floors) comes within dist0 =
# 1e-2 (closest 5e-3 at t = 1), rises 3 cm (leaves; its rebound: the centroid 3 cm up),
# comes back (8e-3 at t = 3), hops only 1.5 cm (< 2 dist0: the same landing, now over wall
# 0) and ends closest, 4e-3 at t = 5, still within reach (no rebound yet); the degenerated
# last row is skipped.
file(WRITE ${_dir}/landings.csv "time_s,min_distance_m,centroid_x_m,centroid_y_m,mass_error
0,0.05,0.5,1.05,0\n1,0.005,0.5,1.0,0\n2,0.03,0.5,1.03,0\n3,0.008,0.5,1.0,0\n4,0.015,0.5,1.8,0\n5,0.004,0.5,1.8,0\n6,0,0.5,9,1.9\n")
execute_process(COMMAND ${AWK} -f ${SOURCE_DIR}/tools/landings.awk -v "walls=0,2,1,2;0,0.6,1,0.6" -v dist0=1e-2
    ${_dir}/landings.csv
  RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
set(_want "1,1.0000,5.0000e-03,1.0000,2.0000,1,3.0000e-02\n0,5.0000,4.0000e-03,3.0000,,1>0,\n")
if(NOT _rc EQUAL 0 OR NOT _out STREQUAL _want)
  message(FATAL_ERROR "landings.awk: got '${_out}' (exit ${_rc}, ${_err}), want '${_want}'")
endif()
execute_process(COMMAND ${AWK} -f ${SOURCE_DIR}/tools/landings.awk -v walls=0,1 -v dist0=1e-2 ${_dir}/landings.csv
  RESULT_VARIABLE _rc ERROR_VARIABLE _err)
if(_rc EQUAL 0 OR NOT _err MATCHES "wall 0 is not AX,AY,BX,BY")
  message(FATAL_ERROR "landings.awk took a bad wall list: exit ${_rc}, ${_err}")
endif()

# tools/group-contacts.awk: three touches of wall 4 within 0.1 s of each other are one
# item, a touch of wall 4 0.5 s later and one of wall 6 are their own; nothing stays nothing.
file(WRITE ${_dir}/contacts.txt "4@11.6472;4@11.6492;4@11.7200;4@12.2;6@12.25\n")
execute_process(COMMAND ${AWK} -f ${SOURCE_DIR}/tools/group-contacts.awk ${_dir}/contacts.txt
  RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
set(_want "4@11.6472..11.7200 (3 touch-downs);4@12.2000;6@12.2500\n")
if(NOT _rc EQUAL 0 OR NOT _out STREQUAL _want)
  message(FATAL_ERROR "group-contacts.awk: got '${_out}' (exit ${_rc}, ${_err}), want '${_want}'")
endif()
file(WRITE ${_dir}/no_contacts.txt "\n")
execute_process(COMMAND ${AWK} -f ${SOURCE_DIR}/tools/group-contacts.awk ${_dir}/no_contacts.txt
  RESULT_VARIABLE _rc OUTPUT_VARIABLE _out)
if(NOT _rc EQUAL 0 OR NOT _out STREQUAL "\n")
  message(FATAL_ERROR "group-contacts.awk on no contacts: got '${_out}' (exit ${_rc})")
endif()

# study_run_finished: a run that ended within half a base step of its end time is
# finished (fsi-movie stops there; halved steps can end just short of it), one that ended
# further short is not.
file(MAKE_DIRECTORY ${_dir}/short)
file(WRITE ${_dir}/short/scenario.json "{\n  \"numerics\": {\n    \"time_step_s\": 0.0005,\n    \"time_step_max_doublings\": 2\n  }\n}\n")
file(WRITE ${_dir}/short/summary.json "{\n  \"final\": true,\n  \"interrupted\": false,\n  \"stop_reason\": \"\",\n  \"simulated_time_s\": 3.9999375\n}\n")
execute_process(COMMAND ${BASH} -c
    "source '${SOURCE_DIR}/tools/study-common.sh' && study_run_finished '${_dir}/short' 4.0 && ! study_run_finished '${_dir}/short' 4.001"
  RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "study_run_finished and a run 6.25e-5 s short of 4.0 s (k = 5e-4 s): exit ${_rc} ${_out}${_err}")
endif()

# A stub fsi-movie: records its arguments, writes a run finished at its --end-time (with
# a checkpoint, so that a later end time continues it).
set(_stub ${_dir}/fake-fsi-movie)
file(WRITE ${_stub} "#!/usr/bin/env bash
dir=$2; printf '%s\\n' \"$@\" >> \"$dir/calls.txt\"
end=0; previous=; for a in \"$@\"; do [ \"$previous\" = --end-time ] && end=$a; previous=$a; done
mkdir -p \"$dir/checkpoints\"; : > \"$dir/checkpoints/step_000002.ckpt\"
printf 'step,time_s,min_distance_m,mean_vy_mps,mass_error,bottom_y_m,centroid_x_m,centroid_y_m,right_x_m\\n0,0,0.1,-0.3,0,1.9,0.5,2,0.6\\n1,0.05,0.001,-0.1,0,1.8,0.6,1.9,0.7\\n2,0.1,0.02,0.2,0,1.82,0.7,1.92,0.8\\n' > \"$dir/functionals.csv\"
printf '{\\n  \"final\": true,\\n  \"stop_reason\": \"\",\\n  \"simulated_time_s\": %s,\\n  \"contact_sequence\": \"\"\\n}\\n' \"$end\" > \"$dir/summary.json\"
")
file(CHMOD ${_stub} PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
set(_run d0_1e-2_g800)
# run_tool(SCRIPT WANT_RC ARGS...): tools/SCRIPT with the stub, headless, 0.1 s.
function(run_tool script want_rc)
  execute_process(COMMAND env FSI_STUDY_NO_BUILD=1 FSI_MOVIE=${_stub}
      ${BASH} ${SOURCE_DIR}/tools/${script} --jobs 1 --end-time 0.1 ${ARGN}
    RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
  message("${script} ${ARGN} -> ${_rc}\n${_out}${_err}")
  if(NOT _rc EQUAL want_rc)
    message(FATAL_ERROR "${script} ${ARGN}: exit ${_rc}, want ${want_rc}")
  endif()
  set(_study_err "${_err}" PARENT_SCOPE)
endfunction()
macro(run_study want_rc)
  run_tool(study-contact ${want_rc} --only ${_run} --out ${_dir}/study ${ARGN})
endmacro()
set(_calls ${_dir}/study/${_run}/calls.txt)
run_study(0 --set /numerics/cut_snap=3e-2)
file(STRINGS ${_calls} _args)
list(FIND _args /numerics/cut_snap=3e-2 _found)
if(_found EQUAL -1)
  message(FATAL_ERROR "the run was not given --set /numerics/cut_snap=3e-2: ${_args}")
endif()
run_study(0 --set /numerics/cut_snap=3e-2)  # finished with these settings: reused
file(STRINGS ${_calls} _args_again)
if(NOT _args_again STREQUAL _args)
  message(FATAL_ERROR "a finished run with the same settings was run again")
endif()
if(NOT EXISTS ${_dir}/study/${_run}/wall_seconds.txt)
  message(FATAL_ERROR "the run's time was not recorded (wall_seconds.txt)")
endif()
# A later end time goes on from the finished run's last checkpoint.
run_study(0 --set /numerics/cut_snap=3e-2 --end-time 0.2)
file(STRINGS ${_calls} _args_later)
list(LENGTH _args _n_before)
list(SUBLIST _args_later ${_n_before} -1 _later_call)
list(FIND _later_call --continue _continued)
list(FIND _later_call 0.2 _later_end)
if(_continued EQUAL -1 OR _later_end EQUAL -1)
  message(FATAL_ERROR "a finished run asked for a later end time was not continued to it: ${_later_call}")
endif()
set(_args ${_args_later})
run_study(3)  # other settings (none): refused, the run left as it was
if(NOT _study_err MATCHES "cut_snap=3e-2.*REFUSED")
  message(FATAL_ERROR "a run made with other settings was not refused: ${_study_err}")
endif()
file(STRINGS ${_calls} _args_again)
if(NOT _args_again STREQUAL _args)
  message(FATAL_ERROR "a run made with other settings was run again")
endif()
run_study(2 --set)  # --set without a value: usage error
run_study(0 --summary-only)  # the summary leaves the run with other settings out
file(READ ${_dir}/study/summary.csv _summary)
if(NOT _summary STREQUAL "dist0,gamma_c,real_contact_time,first_rebound_max,rest_distance\n")
  message(FATAL_ERROR "the summary of a study without settings holds a run made with some: ${_summary}")
endif()

# tools/study-stairs: the cases' own solver control (accept_flagged_reduction) comes after
# the study's default halve_step, and a run recorded with other solver controls (rho_f =
# 1000 once ran with accept_and_flag) goes on with the new ones, is not
# refused and stays in the summary: solver controls do not change the problem.
file(MAKE_DIRECTORY ${_dir}/stairs/rho1000)
file(WRITE ${_dir}/stairs/rho1000/study-settings.txt "/numerics/failure_policy=accept_and_flag\n")
file(WRITE ${_dir}/stairs/rho1000/functionals.csv "step,time_s\n0,0\n")
run_tool(study-stairs 0 --only rho1000 --out ${_dir}/stairs)
file(STRINGS ${_dir}/stairs/rho1000/calls.txt _args)
list(FIND _args /numerics/failure_policy="halve_step" _default_at)
list(FIND _args /numerics/accept_flagged_reduction=1e-4 _own_at)
if(_default_at EQUAL -1 OR _own_at LESS_EQUAL _default_at)
  message(FATAL_ERROR "rho1000's accept_flagged_reduction does not follow the default halve_step: ${_args}")
endif()
if(_study_err MATCHES "REFUSED")
  message(FATAL_ERROR "a run made with other solver controls was refused: ${_study_err}")
endif()
file(STRINGS ${_dir}/stairs/summary.csv _summary)
list(LENGTH _summary _rows)
if(NOT _rows EQUAL 2 OR _study_err MATCHES "left out")
  message(FATAL_ERROR "study-stairs left its rho1000 run out of the summary: ${_summary} ${_study_err}")
endif()
# Physics settings still count: a run recorded with another cut_snap is refused.
file(WRITE ${_dir}/stairs/rho1000/study-settings.txt "/numerics/cut_snap=1e-2\n")
run_tool(study-stairs 3 --only rho1000 --out ${_dir}/stairs)

# tools/validate-example1 makes its runs the same way: a row's own settings (mesh, time
# step, with the chapter's method 4225:1e-3's cut_snap) are passed and recorded, and --set
# on top is refused.
macro(run_validate want_rc)
  run_tool(validate-example1 ${want_rc} --only 4225:1e-3 --method chapter --out ${_dir}/validate ${ARGN})
endmacro()
run_validate(0)
file(STRINGS ${_dir}/validate/n4225_k1e-3/study-settings.txt _settings)
if(NOT _settings STREQUAL "/method=chapter;/numerics/cavitation_pressure_pa=-1e4;/mesh/refinements=0;/numerics/time_step_s=1e-3;/numerics/cut_snap=3e-2")
  message(FATAL_ERROR "validate-example1 recorded the settings '${_settings}'")
endif()
file(STRINGS ${_dir}/validate/n4225_k1e-3/calls.txt _args)
foreach(_want /method=chapter /mesh/refinements=0 /numerics/time_step_s=1e-3 /numerics/cut_snap=3e-2)
  list(FIND _args ${_want} _found)
  if(_found EQUAL -1)
    message(FATAL_ERROR "validate-example1 did not pass --set ${_want}: ${_args}")
  endif()
endforeach()
run_validate(3 --set /numerics/cavitation_pressure_pa=-3e4)
# With the default numerics (no --method) a row is the shipped scenario with its mesh and step only.
run_tool(validate-example1 0 --only 4225:1e-3 --out ${_dir}/validate-fsi)
file(STRINGS ${_dir}/validate-fsi/n4225_k1e-3/study-settings.txt _settings)
if(NOT _settings STREQUAL "/mesh/refinements=0;/numerics/time_step_s=1e-3")
  message(FATAL_ERROR "validate-example1 with the default numerics recorded the settings '${_settings}'")
endif()
run_tool(validate-example1 2 --method exact)

# tools/contact-rest-distances: the static balance of the penalty force against the
# ball's weight lands on the chapter's rest distances (3.18e-3, 1.77e-3, 1.21e-3 m) within 3 %.
execute_process(COMMAND ${BASH} ${SOURCE_DIR}/tools/contact-rest-distances --csv ${_dir}/rest.csv
  RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "contact-rest-distances: exit ${_rc}: ${_out}${_err}")
endif()
# Each chapter row: |static - chapter| <= 3 % of the chapter's; prints how many rows passed.
execute_process(COMMAND ${AWK} -F, "NR > 1 && $4 != \"\" { n += ($3 - $4) ^ 2 <= (0.03 * $4) ^ 2 } END { print n + 0 }"
    ${_dir}/rest.csv
  OUTPUT_VARIABLE _passed OUTPUT_STRIP_TRAILING_WHITESPACE)
if(NOT _passed EQUAL 3)
  file(READ ${_dir}/rest.csv _rest)
  message(FATAL_ERROR "the static rest gaps are not within 3 % of the chapter's three (${_passed} are):\n${_rest}")
endif()

# study_json_value reads a number of one object in either layout of a scenario JSON.
file(WRITE ${_dir}/pretty.json "{\n  \"fluid\": {\n    \"density_kgpm3\": 150.0,\n    \"viscosity_m2ps\": 0.001\n  },\n  \"solid\": {\n    \"density_kgpm3\": 1000.0\n  },\n  \"contact\": {\n    \"gamma_c\": 10000.0,\n    \"dist0_m\": 0.01\n  }\n}\n")
file(WRITE ${_dir}/compact.json "{\n  \"solid\": {\"density_kgpm3\": 1000},\n  \"walls\": [\n    [[0, 2.8], [0, 1.4]],\n    [[0, 1.4], [1.2, 1.0]]\n  ],\n  \"fluid\": {\"density_kgpm3\": 300},\n  \"contact\": {\"gamma_c\": 5e3, \"dist0_m\": 1e-2}\n}\n")
execute_process(COMMAND ${BASH} -c "source '${SOURCE_DIR}/tools/study-common.sh' && for f in pretty compact; do \
    printf '%s,%s,%s;' $(study_json_value ${_dir}/$f.json fluid density_kgpm3) \
      $(study_json_value ${_dir}/$f.json contact gamma_c) $(study_json_value ${_dir}/$f.json solid density_kgpm3); done"
  OUTPUT_VARIABLE _values RESULT_VARIABLE _rc)
if(NOT _rc EQUAL 0 OR NOT _values STREQUAL "150,10000,1000;300,5000,1000;")
  message(FATAL_ERROR "study_json_value: got '${_values}' (exit ${_rc}), want '150,10000,1000;300,5000,1000;'")
endif()
# study_walls reads the walls of either layout (fsi-movie's pretty scenario.json: one
# number per line; the assets' compact one).
file(WRITE ${_dir}/pretty_walls.json "{\n  \"walls\": [\n    [\n      [\n        0.0,\n        2.8\n      ],\n      [\n        0.0,\n        1.4\n      ]\n    ],\n    [\n      [\n        0.0,\n        1.4\n      ],\n      [\n        1.2,\n        1.0\n      ]\n    ]\n  ],\n  \"x\": [5, 6]\n}\n")
execute_process(COMMAND ${BASH} -c "source '${SOURCE_DIR}/tools/study-common.sh' && study_walls ${_dir}/pretty_walls.json && study_walls ${_dir}/compact.json"
  OUTPUT_VARIABLE _walls RESULT_VARIABLE _rc)
if(NOT _rc EQUAL 0 OR NOT _walls STREQUAL "0,2.8,0,1.4;0,1.4,1.2,1\n0,2.8,0,1.4;0,1.4,1.2,1\n")
  message(FATAL_ERROR "study_walls: got '${_walls}' (exit ${_rc})")
endif()

# tools/study-shapes: the landing (the first gap below dist_0 until the gap is back above
# it), its smallest gap, the largest gap after that (the bounce) and the rotations, from a
# stub run that lands at t = 1 s, comes within 2 mm and bounces back to 2 cm.
set(_shapes_stub ${_dir}/fake-fsi-movie-shapes)
file(WRITE ${_shapes_stub} "#!/usr/bin/env bash
dir=$2; mkdir -p \"$dir\"
printf 'step,time_s,min_distance_m,mean_vy_mps,mass_error,rotation_rad,converged\\n0,0,0.3,-0.2,0.001,0,1\\n1,1,0.005,-0.1,0.002,-0.1,1\\n2,1.1,0.002,-0.01,0.002,-0.15,1\\n3,1.2,0.02,0.05,0.003,-0.2,1\\n4,1.3,0.015,0.01,0.002,-0.3,1\\n' > \"$dir/functionals.csv\"
printf '{\\n  \"contact\": {\"gamma_c\": 800, \"dist0_m\": 0.01},\\n  \"numerics\": {\"time_step_s\": 0.002}\\n}\\n' > \"$dir/scenario.json\"
printf '{\\n  \"final\": true,\\n  \"stop_reason\": \"\",\\n  \"simulated_time_s\": 1.3,\\n  \"contact_sequence\": \"\"\\n}\\n' > \"$dir/summary.json\"
")
file(CHMOD ${_shapes_stub} PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
execute_process(COMMAND env FSI_STUDY_NO_BUILD=1 FSI_MOVIE=${_shapes_stub}
    ${BASH} ${SOURCE_DIR}/tools/study-shapes --jobs 1 --end-time 1.3 --only ellipse --out ${_dir}/shapes
  RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
file(STRINGS ${_dir}/shapes/summary.csv _rows)
list(GET _rows 1 _row)
if(NOT _rc EQUAL 0 OR NOT _row STREQUAL "ellipse,1.3000,5,0,1.0000,0.002,0.05,0.02,-0.1000,-0.3000,0.003")
  message(FATAL_ERROR "study-shapes: exit ${_rc}, summary row '${_row}'\n${_out}${_err}")
endif()
if(NOT _out MATCHES "ellipse: lands at t = 1.0000 s \\(gap 0.002 m\\), bounces \\(the gap grows to 0.02 m\\), turns by -0.3000 rad, every step converged: yes")
  message(FATAL_ERROR "study-shapes: no verdict of a bounce\n${_out}${_err}")
endif()
message("study-shapes: ${_row}")

# tools/study-bodies: two balls of R = 0.25 m (rho_s = rho_f = 1000 kg/m^3, gamma_c = 2000
# N/m, dist_0 = 0.1 m) enter dist_0 at 0.1988 m/s each, come within 2.6 cm and fly apart.
# The force law's energy balance (with the added mass) puts the stop at 0.02645 m.
set(_bodies_stub ${_dir}/fake-fsi-movie-bodies)
file(WRITE ${_bodies_stub} "#!/usr/bin/env bash
dir=$2; mkdir -p \"$dir\"
printf 'step,time_s,mass_error,body1_centroid_x_m,body1_mean_vx_mps,body1_min_distance_m,body1_min_body_distance_m,body1_mass_error,body2_centroid_x_m,body2_mean_vx_mps,body2_min_distance_m,body2_min_body_distance_m,body2_mass_error,converged\\n0,0,0.004,-0.4,0.3,0.35,0.3,0.004,0.4,-0.3,0.35,0.3,0.004,1\\n1,0.5,0.004,-0.3,0.1988,0.45,0.09,0.004,0.3,-0.1988,0.45,0.09,0.004,1\\n2,0.9,0.005,-0.263,0,0.487,0.026,0.005,0.263000001,0,0.487,0.026,0.003,1\\n3,1.5,0.004,-0.35,-0.13,0.4,0.2,0.004,0.35,0.13,0.4,0.2,0.004,1\\n' > \"$dir/functionals.csv\"
printf '{\\n  \"bodies\": [\\n    {\\n      \"radius_m\": 0.25\\n    }\\n  ],\\n  \"fluid\": {\\n    \"density_kgpm3\": 1000\\n  },\\n  \"solid\": {\\n    \"density_kgpm3\": 1000\\n  },\\n  \"contact\": {\\n    \"gamma_c\": 2000,\\n    \"dist0_m\": 0.1,\\n    \"min_dist_fraction\": 0.1\\n  },\\n  \"numerics\": {\"time_step_s\": 0.002}\\n}\\n' > \"$dir/scenario.json\"
printf '{\\n  \"final\": true,\\n  \"stop_reason\": \"\",\\n  \"simulated_time_s\": 1.5,\\n  \"contact_sequence\": \"\"\\n}\\n' > \"$dir/summary.json\"
")
file(CHMOD ${_bodies_stub} PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
execute_process(COMMAND env FSI_STUDY_NO_BUILD=1 FSI_MOVIE=${_bodies_stub}
    ${BASH} ${SOURCE_DIR}/tools/study-bodies --jobs 1 --end-time 1.5 --only two_balls_collide --out ${_dir}/bodies
  RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
file(STRINGS ${_dir}/bodies/summary.csv _rows)
list(GET _rows 1 _row)
if(NOT _rc EQUAL 0 OR NOT _row STREQUAL "two_balls_collide,1.5000,4,0,0.026,0.35,0.005,2,0,1e-09")
  message(FATAL_ERROR "study-bodies: exit ${_rc}, summary row '${_row}'\n${_out}${_err}")
endif()
if(NOT _out MATCHES "two_balls_collide: enter dist_0 at 0.1988 m/s each, stop 0.026 m apart against 0.02645 m from the force law's energy balance \\(within 20 %\\), fly apart, every step converged, mirror error 1e-09 m: yes")
  message(FATAL_ERROR "study-bodies: no verdict of a stop at the predicted gap\n${_out}${_err}")
endif()
message("study-bodies: ${_row}")
