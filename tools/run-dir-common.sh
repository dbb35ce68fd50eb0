# Shared by the scripts that change an fsi-movie run folder in place (tools/rewind-run,
# tools/remesh-run): sourced, not run.

# fsi_movie_writes DIR: is an fsi-movie writing into DIR? Its OUTDIR is the second argument
# after the program (also when started through a script named fsi-movie), resolved against
# the process's own working folder: a run started with a relative path counts too.
fsi_movie_writes() {
  local want pid out cwd args i
  want=$(realpath -m -- "$1")
  for pid in $(pgrep -x fsi-movie); do
    mapfile -d '' -t args < "/proc/$pid/cmdline" 2>/dev/null || continue
    cwd=$(readlink "/proc/$pid/cwd" 2>/dev/null) || continue
    for ((i = 0; i + 2 < ${#args[@]}; ++i)); do
      [ "$(basename -- "${args[i]}")" = fsi-movie ] || continue
      out=${args[i + 2]}
      [[ $out = /* ]] || out=$cwd/$out
      [ "$(realpath -m -- "$out")" = "$want" ] && return 0
      break
    done
  done
  return 1
}
