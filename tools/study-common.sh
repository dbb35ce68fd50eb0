# Shared by tools/study-{materials,contact,stairs}, tools/contact-rest-distances and
# tools/validate-example1 (sourced, not run): checks the apps, runs fsi-movie headless in
# parallel (skipping finished runs) and reads the events of a run's summary.json.
#
# A run is one line "NAME SCENARIO [--set KEY=VALUE ...]"; its output goes to
# $study_out/NAME/{functionals.csv,summary.json,log.txt,study-settings.txt,wall_seconds.txt}
# (log.txt: fsi-movie's messages of every invocation, each after a "=== date" line).
# FSI_MOVIE=path runs another fsi-movie (e.g. a copy, so that rebuilding the tree during
# a long study does not swap the library under running processes). Every run uses the
# failure policy halve_step unless its line sets another: a step Newton cannot finish
# within its budget is retried with k/2, k/4, k/8 before it is accepted and flagged. Checkpoints every
# $study_checkpoint_every steps ($study_out/NAME/checkpoints/, and of the last state when a
# run ends or is stopped by a signal) let a run be inspected, and a run that stopped before
# its end goes on from the latest one when the study is started again (fsi-movie
# --continue), as does a finished run asked for a later end time.
study_checkpoint_every=${study_checkpoint_every:-250}

# fsi-movie stops a run whose body degenerated (relative mass error above this; the
# kLostBodyMassError of apps/common/movie_run.cpp). That last row is not physics: the
# reductions and plots leave rows above it out.
study_degenerate_mass_error=0.5

study_apps_or_die() {
  [ -n "${FSI_STUDY_NO_BUILD:-}" ] || tools/build >/dev/null
  local app
  [ -n "${FSI_MOVIE:-}" ] && [ ! -x "$FSI_MOVIE" ] && { echo "$0: FSI_MOVIE=$FSI_MOVIE is not executable" >&2; exit 3; }
  for app in fsi-movie fsi-plot fsi-sketch; do
    if [ ! -x "build/apps/$app" ]; then
      echo "$0: build/apps/$app is missing (apps/$app.cpp not in this tree or not built);" \
           "build it with tools/build first" >&2
      exit 3
    fi
  done
}

# Options every study script takes; study_common_option OPTION VALUE consumes them.
#   --set KEY=VALUE  passed to every run (fsi-movie --set, e.g. /numerics/cut_snap=3e-2);
#                    repeatable. A run directory records its settings
#                    (study-settings.txt) and is only reused or continued with the same ones.
#   --out DIR        the study's directory instead of out/study-<name>.
study_sets_text=""
study_common_option() {
  case "$1" in
    --set) [ -n "${2:-}" ] || { echo "$0: --set needs KEY=VALUE" >&2; exit 2; }
           study_sets_text+="$2"$'\n' ;;
    --out) [ -n "${2:-}" ] || { echo "$0: --out needs a directory" >&2; exit 2; }
           study_out_option=$2 ;;
    *) return 1 ;;
  esac
}

# study_run_settings [ARGS...]: the settings a run is made with, one per line: the
# values of the --set options of its line, then the study's own (--set).
study_run_settings() {
  local previous=""
  for a in "$@"; do [ "$previous" = --set ] && printf '%s\n' "$a"; previous=$a; done
  printf '%s' "$study_sets_text"
}

# study_physics_settings: the settings on stdin without the solver controls (Newton's
# budget and tolerances, the failure policy). A run may go on with other solver controls,
# as its checkpoints do. The keys are read from the engine's own list (kSolverControlKeys),
# so that the two cannot drift apart.
study_fingerprint_hpp=$(dirname "${BASH_SOURCE[0]}")/../engine/src/io/fingerprint.hpp
study_solver_control_keys=$(awk '/kSolverControlKeys\{/,/\};/' "$study_fingerprint_hpp" 2>/dev/null |
                            grep -o '"[a-z_]*"' | tr -d '"' | paste -sd'|')
[ -n "$study_solver_control_keys" ] ||
  { echo "$0: no solver control keys in $study_fingerprint_hpp (kSolverControlKeys)" >&2; exit 3; }
study_physics_settings() {
  grep -v -E "^/numerics/($study_solver_control_keys)=" || true
}

# study_settings_match DIR [RUN ARGS...]: false (and says why) when DIR holds a run made
# with other --set settings (study-settings.txt; none recorded = no settings) than a run
# with these arguments gets in this study. Solver controls may differ (study_physics_settings).
study_settings_match() {
  local dir=$1 have="" want; shift
  [ -f "$dir/functionals.csv" ] || return 0
  [ -f "$dir/study-settings.txt" ] && have=$(cat "$dir/study-settings.txt")
  want=$(study_run_settings "$@")
  [ "$(study_physics_settings <<< "$have")" = "$(study_physics_settings <<< "$want")" ] && return 0
  echo "$dir was run with settings [${have//$'\n'/ }], this study has [${want//$'\n'/ }]" >&2
  return 1
}

# study_run_one END_TIME NAME SCENARIO [--set ...]: one run unless it already finished.
# wall_seconds.txt adds up the run time of the invocations that ended (a killed one
# leaves no record).
study_run_one() {
  local end_time=$1 name=$2 scenario=$3; shift 3
  local dir="$study_out/$name"
  if study_run_finished "$dir" "$end_time"; then
    echo "reusing $dir"; return 0
  fi
  mkdir -p "$dir"
  study_run_settings "$@" > "$dir/study-settings.txt"
  local sets=() line
  while IFS= read -r line; do [ -n "$line" ] && sets+=(--set "$line"); done <<< "$study_sets_text"
  # A run that stopped (interrupted, killed, machine gone) goes on from its latest checkpoint.
  local go_on=() earlier=0 what="new run"
  if compgen -G "$dir/checkpoints/step_*.ckpt" > /dev/null && [ -f "$dir/functionals.csv" ]; then
    go_on=(--continue); what="continuing from $(ls "$dir"/checkpoints/step_*.ckpt | tail -1)"
    echo "$what: $dir"
    earlier=$(cat "$dir/wall_seconds.txt" 2>/dev/null || echo 0)
  fi
  local start=$SECONDS rc=0
  # log.txt keeps every invocation's messages (a continued run's earlier steps too).
  printf '=== %s: %s\n' "$(date -u '+%Y-%m-%d %H:%M:%S UTC')" "$what" >> "$dir/log.txt"
  # The study's default failure policy first: a run's own --set (e.g. another policy) and
  # the study's --set come after it and win.
  OPENBLAS_NUM_THREADS=1 "${FSI_MOVIE:-build/apps/fsi-movie}" "$scenario" "$dir" \
    --set /numerics/failure_policy='"halve_step"' "$@" "${go_on[@]}" "${sets[@]}" --end-time "$end_time" \
    --checkpoint-every "$study_checkpoint_every" --no-png --no-video --no-vtu --quiet \
    >> "$dir/log.txt" 2>&1 || rc=$?
  echo "$((earlier + SECONDS - start))" > "$dir/wall_seconds.txt"
  if [ "$rc" = 0 ]; then
    echo "finished $dir in $((SECONDS - start)) s"
  elif [ "$rc" = 130 ]; then
    echo "stopped $dir (interrupted): start the study again to continue it from its latest checkpoint" >&2
  else
    echo "FAILED $dir (exit $rc, see $dir/log.txt)" >&2
  fi
}

# study_run_all JOBS END_TIME < lines: the runs, JOBS at a time. With study_only set (a
# comma-separated list of run names, --only) just those; with study_summary_only=1
# (--summary-only) none: the summary then covers the runs that exist.
study_run_all() {
  local jobs=$1 end_time=$2
  export -f study_run_one study_run_finished study_run_settings study_physics_settings
  export study_out FSI_MOVIE study_sets_text study_checkpoint_every study_solver_control_keys
  if [ "${study_summary_only:-0}" = 1 ]; then cat > /dev/null; return 0; fi
  local runs name scenario args refused=0
  runs=$(awk -v only="${study_only:-}" 'BEGIN { n = split(only, o, ","); for (i = 1; i <= n; ++i) keep[o[i]] = 1 }
                                        n == 0 || ($1 in keep)')
  # A run directory is reused or continued only with the settings it was made with.
  while read -r name scenario args; do
    # shellcheck disable=SC2086  # the run's arguments, split into words as xargs does below
    [ -n "$name" ] && ! study_settings_match "$study_out/$name" $args && refused=1
  done <<< "$runs"
  if ((refused)); then
    echo "$0: REFUSED: use the same --set settings, --out DIR for another directory, or remove the run" >&2
    exit 3
  fi
  # Each line becomes the arguments of one study_run_one call (words split by the shell).
  [ -n "$runs" ] && xargs -P "$jobs" -L 1 bash -c 'study_run_one "$0" "$@"' "$end_time" <<< "$runs"
  return 0
}

# study_contacts SUMMARY_JSON: the touch-downs as "wall@time;wall@time..." (fsi-movie's
# "contact_sequence": one entry per touch-down, wall by wall). A summary written before
# that key existed gives its first real contact from "events" (kind, first_time_s, wall
# on separate lines of the pretty-printed JSON).
study_contacts() {
  [ -f "$1" ] || return 0
  if grep -q '"contact_sequence"' "$1"; then
    sed -n -E 's/.*"contact_sequence": *"([^"]*)".*/\1/p' "$1"
    return 0
  fi
  awk '/"kind": *"real_contact"/ { inside = 1; next }
       inside && /"first_time_s"/ { t = $2; sub(/,$/, "", t) }
       inside && /"wall"/ { w = $2; sub(/,$/, "", w); printf "%s@%.4f\n", w, t; exit }
       inside && /^ *}/ { inside = 0 }' "$1"
}

# study_run_finished DIR [END_TIME]: the run in DIR ended (its final summary, not
# interrupted) and, with END_TIME, reached it or stopped for a reason of its own (e.g. the
# body degenerated): a finished run asked for a later end time is not finished.
study_run_finished() {
  [ -f "$1/summary.json" ] && grep -q '"final": *true' "$1/summary.json" &&
    ! grep -q '"interrupted": *true' "$1/summary.json" || return 1
  # Reached END_TIME as fsi-movie counts it (apps/common/movie_run.cpp): within half a base
  # step (numerics.time_step_s of the run's scenario.json; halved steps can end just short).
  local half_step
  half_step=$(awk -F: '/"time_step_s"/ { gsub(/[^0-9.eE+-]/, "", $2); print 0.5 * $2; exit }' "$1/scenario.json" 2>/dev/null)
  [ -z "${2:-}" ] || ! grep -q '"stop_reason": *""' "$1/summary.json" ||
    awk -v end="$2" -v half="${half_step:-0}" -F: '/"simulated_time_s"/ { gsub(/[^0-9.eE+-]/, "", $2); ok = ($2 + 0 >= end - half - 1e-6) }
                         END { exit !ok }' "$1/summary.json"
}

# study_stop_reason SUMMARY_JSON: why the run stopped before its end time (empty if it did not).
study_stop_reason() {
  sed -n -E 's/.*"stop_reason": *"([^"]*)".*/\1/p' "$1"
}

# study_stopped_early DIR: true (and says why) when the run in DIR stopped before its end
# time, e.g. because the body degenerated: it has no rest distance or final position.
study_stopped_early() {
  local why
  why=$(study_stop_reason "$1/summary.json")
  [ -n "$why" ] && echo "$1: $why"
}

# study_bounce DIR: first_rebound_max,second_rebound_max,rest_distance of the run in DIR
# (tools/study-bounce.awk; a run stopped early has no rest distance and no rebound that
# was still rising when it stopped).
study_bounce() {
  local stopped=0 reduced
  [ -n "$(study_stop_reason "$1/summary.json")" ] && stopped=1
  reduced=$(awk -v max_mass_error="$study_degenerate_mass_error" -v stopped_early="$stopped" \
            -f tools/study-bounce.awk "$1/functionals.csv")
  ((stopped)) && reduced="${reduced%,*},"
  echo "$reduced"
}

# study_settings_note: one line naming the --set settings of this study (empty if none).
study_settings_note() {
  [ -n "$study_sets_text" ] && echo "settings (--set): ${study_sets_text//$'\n'/ }"
  return 0
}

# study_json_value JSON OBJECT KEY: the number KEY of the object OBJECT in a scenario
# JSON (one key per line, as fsi-movie's scenario.json, or one object per line, as the
# scenario files in assets/), printed as %g.
study_json_value() {
  awk -v object="\"$2\"" -v key="\"$3\"" '
    index($0, object ":") { inside = 1 }
    inside && index($0, key ":") {
      s = substr($0, index($0, key ":") + length(key) + 1); sub(/^ */, "", s)
      match(s, /^[-+0-9.eE]+/); printf "%g\n", substr(s, 1, RLENGTH) + 0; exit
    }
    inside && /}/ && !index($0, object) { inside = 0 }' "$1"
}

# study_walls JSON: the scenario's walls as "AX,AY,BX,BY;..." (tools/landings.awk's -v
# walls), from either layout of a scenario JSON (the numbers of the "walls" array, four
# per wall).
study_walls() {
  awk '!started { i = index($0, "\"walls\""); if (!i) next; started = 1; $0 = substr($0, i + 7) }
       { for (k = 1; k <= length($0); ++k) {
           ch = substr($0, k, 1)
           if (ch == "[") ++depth
           else if (ch == "]") { if (--depth == 0) { done = 1; break } }
           else if (depth > 0 && ch ~ /[-+0-9.eE]/) num = num ch
           if (depth > 0 && ch !~ /[-+0-9.eE]/ && num != "") { v[++n] = num + 0; num = "" }
         }
         if (done) exit }
       END { for (k = 1; k + 3 <= n; k += 4) printf "%s%g,%g,%g,%g", (k > 1 ? ";" : ""), v[k], v[k+1], v[k+2], v[k+3]; print "" }' "$1"
}

# study_landings DIR JSON: the landings of the run in DIR (tools/landings.awk with the walls
# and dist_0 of the scenario JSON) as "wall@time;wall@time...".
study_landings() {
  awk -f tools/landings.awk -v walls="$(study_walls "$2")" -v dist0="$(study_json_value "$2" contact dist0_m)" \
      -v max_mass_error="$study_degenerate_mass_error" "$1/functionals.csv" |
    awk -F, '{ printf "%s%s@%s", (NR > 1 ? ";" : ""), $1, $2 } END { print "" }'
}

# study_first_contact_time SUMMARY_JSON: time of the first real contact (empty if none).
study_first_contact_time() {
  study_contacts "$1" | awk -F';' 'NF { split($1, a, "@"); print a[2] }'
}

# study_xmin_args END_TIME XMIN: "--xmin XMIN" when the runs reach past it (a zoom on the
# contact interval), nothing for short runs.
study_xmin_args() {
  awk -v e="$1" -v x="$2" 'BEGIN { if (e > x + 0.1) print "--xmin", x }'
}

# study_plot_window END_TIME FILE COLUMN XMIN MIN_END YLABEL TITLE CURVES...: COLUMN over
# time from XMIN on into FILE, for a study run past MIN_END (a shorter one would give an
# empty axis) and with curves; degenerated rows are left out, as in every study plot.
study_plot_window() {
  local end_time=$1 file=$2 column=$3 xmin=$4 min_end=$5 ylabel=$6 title=$7; shift 7
  [ $# -gt 0 ] && awk -v t="$end_time" -v min="$min_end" 'BEGIN { exit !(t > min) }' || return 0
  build/apps/fsi-plot "$file" --x time_s --y "$column" \
    --skip-above mass_error="$study_degenerate_mass_error" --xmin "$xmin" \
    --ylabel "$ylabel" --title "$title" "$@"
}
