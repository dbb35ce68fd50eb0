# tools/campaign:
#  - a short campaign: 3 scenarios on the coarsest mesh (level 0, k = 4e-3 s) to
#    t = 0.012 s (a few steps): summary.csv has the header and one row per scenario, each finished, and the plot; a
#    second call reuses the runs, but continues one whose record says it was interrupted;
#  - the same seed draws the same scenario files and parameters, another seed others;
#    every scenario holds physics, mesh, time step and end time only, and --check finds it
#    inside the envelope (the shipped stairs outside);
#  - the outcomes with a stub fsi-movie: a run killed by a signal is "crashed", one that
#    exits 1 without a stop report is "crashed", one past its --timeout is "stopped";
#  - --slurm writes an array script and a collect script that pass bash -n.
# Inputs: -DMOVIE -DSOURCE_DIR -DBINARY_DIR.
find_program(BASH bash REQUIRED)
set(_dir ${BINARY_DIR}/test_tmp/campaign)
file(REMOVE_RECURSE ${_dir})
file(MAKE_DIRECTORY ${_dir})

function(run_campaign want)
  execute_process(COMMAND env FSI_MOVIE=${_movie} ${BASH} ${SOURCE_DIR}/tools/campaign ${ARGN}
    RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
  message("campaign ${ARGN} -> ${_rc}: ${_out}${_err}")
  if(NOT _rc EQUAL want)
    message(FATAL_ERROR "campaign ${ARGN}: exit ${_rc}, want ${want}")
  endif()
  set(_out "${_out}${_err}" PARENT_SCOPE)
endfunction()

# summary_rows(DIR VAR): the data rows of DIR/summary.csv; checks the header.
function(summary_rows dir var)
  file(STRINGS ${dir}/summary.csv _lines)
  list(GET _lines 0 _header)
  set(_want "seed,index,geometry,radius_m,center_x_m,center_y_m,vx_mps,vy_mps,speed_mps,mu_s_pa,lambda_s_pa,density_ratio,rho_s_kgpm3,rho_f_kgpm3,nu_f_m2ps,gravity_mps2,contact,gamma_c,dist0_m,step_x_m,step_y_m,mesh_level,time_step_s,end_time_s,outcome,reached_time_s,steps,unconverged_steps,min_distance_m,max_mass_error,wall_time_s,stop_reason")
  if(NOT _header STREQUAL _want)
    message(FATAL_ERROR "${dir}/summary.csv header: ${_header}")
  endif()
  list(REMOVE_AT _lines 0)
  set(${var} "${_lines}" PARENT_SCOPE)
endfunction()

# --- a short campaign with the real engine -------------------------------------------
set(_movie ${MOVIE})
run_campaign(0 --count 3 --seed 7 --end-time 0.012 --mesh-level 0 --out ${_dir}/a)
summary_rows(${_dir}/a _rows)
list(LENGTH _rows _n)
if(NOT _n EQUAL 3)
  message(FATAL_ERROR "summary.csv has ${_n} rows, want 3: ${_rows}")
endif()
foreach(_row IN LISTS _rows)
  if(NOT _row MATCHES "^7,[0-2],(floor|ubox|stairs),.*,finished,0\\.01[0-9]*,[1-9][0-9]*,")
    message(FATAL_ERROR "not a finished run of seed 7: ${_row}")
  endif()
endforeach()
# A run stopped by a signal (here: its record says so) goes on from its latest checkpoint;
# the others are reused.
file(READ ${_dir}/a/runs/case_000/campaign-run.txt _record)
string(REPLACE "exit_code=0" "exit_code=130" _record "${_record}")
file(WRITE ${_dir}/a/runs/case_000/campaign-run.txt "${_record}")
run_campaign(0 --count 3 --seed 7 --end-time 0.012 --mesh-level 0 --out ${_dir}/a)
if(NOT _out MATCHES "case_000: continuing" OR NOT _out MATCHES "case_001: reusing")
  message(FATAL_ERROR "the interrupted run did not go on, or another did: ${_out}")
endif()
summary_rows(${_dir}/a _again)
list(GET _again 0 _r0)
if(NOT _r0 MATCHES ",finished,0\\.01[0-9]*,")
  message(FATAL_ERROR "the continued run did not finish: ${_r0}")
endif()
find_program(GNUPLOT gnuplot)
if(GNUPLOT AND NOT EXISTS ${_dir}/a/outcomes.png)
  message(FATAL_ERROR "no outcomes.png")
endif()

# --- the same seed, the same files -----------------------------------------------------
run_campaign(0 --count 3 --seed 7 --end-time 0.012 --mesh-level 0 --out ${_dir}/b --draw-only)
run_campaign(0 --count 3 --seed 8 --end-time 0.012 --mesh-level 0 --out ${_dir}/c --draw-only)
foreach(_f parameters.csv scenarios/case_000.json scenarios/case_001.json scenarios/case_002.json)
  file(READ ${_dir}/a/${_f} _a)
  file(READ ${_dir}/b/${_f} _b)
  file(READ ${_dir}/c/${_f} _c)
  if(NOT _a STREQUAL _b)
    message(FATAL_ERROR "seed 7 drew another ${_f} the second time")
  endif()
  if(_a STREQUAL _c)
    message(FATAL_ERROR "seeds 7 and 8 drew the same ${_f}")
  endif()
endforeach()
foreach(_i 000 001 002)
  file(READ ${_dir}/a/scenarios/case_${_i}.json _s)
  string(JSON _numerics GET "${_s}" numerics)
  string(JSON _n LENGTH "${_numerics}")
  string(JSON _k0 MEMBER "${_numerics}" 0)
  string(JSON _k1 MEMBER "${_numerics}" 1)
  if(NOT _n EQUAL 2 OR NOT "${_k0};${_k1}" STREQUAL "end_time_s;time_step_s")
    message(FATAL_ERROR "case_${_i}: numerics keys other than the step and the end time: ${_numerics}")
  endif()
  string(JSON _method ERROR_VARIABLE _none GET "${_s}" method)
  if(_none STREQUAL "NOTFOUND")
    message(FATAL_ERROR "case_${_i} sets a method: ${_method}")
  endif()
endforeach()

# --- --check: the drawn scenarios lie inside the envelope, the shipped stairs and three balls do not
run_campaign(0 --check ${_dir}/a/scenarios/case_000.json ${_dir}/a/scenarios/case_001.json
             ${_dir}/a/scenarios/case_002.json ${SOURCE_DIR}/assets/scenarios/ball_drop.json)
run_campaign(1 --check ${SOURCE_DIR}/assets/scenarios/stairs/stairs_rho100.json)
if(NOT _out MATCHES "rho_s / rho_f = 10 is outside")
  message(FATAL_ERROR "--check does not name the density ratio: ${_out}")
endif()
run_campaign(1 --check ${SOURCE_DIR}/assets/scenarios/three_balls.json)
if(NOT _out MATCHES "3 bodies: the envelope has one body")
  message(FATAL_ERROR "--check does not name the bodies: ${_out}")
endif()

# --- the outcomes, with a stub engine --------------------------------------------------
# case_000: a finished run; case_001: killed by SIGSEGV; case_002: hangs (--timeout 2);
# case_003: exits 1 without a summary; case_004: stops where its body reaches an open
# boundary (the engine's left_domain event).
set(_movie ${_dir}/stub-movie)
file(WRITE ${_movie} "#!/usr/bin/env bash
case \"$1\" in
  *case_000.json) printf '{\"final\": true, \"stop_reason\": \"\", \"steps\": 2, \"simulated_time_s\": 0.008, \"unconverged_steps\": 0, \"min_distance\": {\"distance_m\": 0.1}}' > \"$2/summary.json\"
                  printf 'time_s,mass_error\\n0.004,1e-3\\n0.008,-2e-3\\n' > \"$2/functionals.csv\" ;;
  *case_001.json) echo 'about to fail' >&2; kill -SEGV $$ ;;
  *case_003.json) echo 'fsi-movie: broken' >&2; exit 1 ;;
  *case_004.json) printf '{\"final\": true, \"stop_reason\": \"the engine rejected step 3: the body reached the open boundary at (-1, -0.5) m\", \"steps\": 2, \"simulated_time_s\": 0.008, \"unconverged_steps\": 0, \"events\": [{\"kind\": \"left_domain\", \"first_time_s\": 0.012, \"where_m\": [-1, -0.5]}]}' > \"$2/summary.json\"
                  exit 1 ;;
  *) exec sleep 20 ;;
esac
")
file(CHMOD ${_movie} PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
run_campaign(0 --count 5 --seed 7 --end-time 0.012 --mesh-level 0 --out ${_dir}/stub --timeout 2 --jobs 5)
summary_rows(${_dir}/stub _rows)
list(GET _rows 0 _r0)
list(GET _rows 1 _r1)
list(GET _rows 2 _r2)
list(GET _rows 3 _r3)
list(GET _rows 4 _r4)
if(NOT _r4 MATCHES ",left_domain,0\\.008,2,0,.*,\"the engine rejected step 3: the body reached the open boundary at \\(-1, -0\\.5\\) m\"$")
  message(FATAL_ERROR "case 4 (left the domain): ${_r4}")
endif()
if(NOT _r0 MATCHES ",finished,0\\.008,2,0,0\\.1,0\\.002,[0-9.]+,\"\"$")
  message(FATAL_ERROR "case 0 (finished): ${_r0}")
endif()
if(NOT _r1 MATCHES ",crashed,,,,,,[0-9.]+,\"killed by signal 11: about to fail\"$")
  message(FATAL_ERROR "case 1 (killed by a signal): ${_r1}")
endif()
if(NOT _r2 MATCHES ",stopped,.*,\"timeout after 2 s\"$")
  message(FATAL_ERROR "case 2 (timeout): ${_r2}")
endif()
if(NOT _r3 MATCHES ",crashed,.*,\"exit 1: fsi-movie: broken\"$")
  message(FATAL_ERROR "case 3 (exit 1): ${_r3}")
endif()
# A run is reused while its scenario is unchanged: the engine is not asked again.
file(READ ${_dir}/stub/summary.csv _first)
file(WRITE ${_movie} "#!/usr/bin/env bash\necho 'asked again' >&2\nexit 1\n")
run_campaign(0 --count 5 --seed 7 --end-time 0.012 --mesh-level 0 --out ${_dir}/stub --timeout 2)
file(READ ${_dir}/stub/summary.csv _again)
if(NOT _first STREQUAL _again)
  message(FATAL_ERROR "the runs were not reused:\n${_first}\n${_again}")
endif()

# --- slurm -----------------------------------------------------------------------------
run_campaign(0 --count 3 --seed 7 --end-time 0.012 --mesh-level 0 --out ${_dir}/slurm --slurm)
file(READ ${_dir}/slurm/campaign.sbatch _sbatch)
if(NOT _sbatch MATCHES "#SBATCH --array=0-2\n" OR NOT _sbatch MATCHES "tools/campaign-run")
  message(FATAL_ERROR "campaign.sbatch: ${_sbatch}")
endif()
foreach(_script campaign.sbatch collect.sbatch)
  execute_process(COMMAND ${BASH} -n ${_dir}/slurm/${_script} RESULT_VARIABLE _rc ERROR_VARIABLE _err)
  if(NOT _rc EQUAL 0)
    message(FATAL_ERROR "${_script} does not pass bash -n: ${_err}")
  endif()
endforeach()
