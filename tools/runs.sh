# runs.sh: what the validation scripts share, sourced by them (not run on its own).
#   vcsph_run DIR [vcsph run arguments...]   runs $VCSPH (default build/vcsph) into DIR with
#       $threads threads: the terminal output goes to DIR/run.txt, the exit status to DIR/exit
#       (3: breakdown), "wall user system" seconds to DIR/time.txt; THREADS, when set,
#       overrides $threads (to run a queue on one core while the other stays free)
#   vcsph_resume DIR                         continues the run in DIR from DIR/checkpoint.h5 (a
#       run stopped by a signal or the end of a working session) to its t_end, with the same
#       files as vcsph_run; the terminal output of each piece is appended to DIR/run.txt
#   for_each_run JOBS FUNCTION RUN...        calls FUNCTION with each RUN's words, at most
#       JOBS at a time, and says how long they took
#   us_per_particle_step DIR                 the run's cost from DIR/log.txt, or -
# vcsph run "$@" with the threads, files and exit status of vcsph_run, the terminal output
# appended to DIR/run.txt
vcsph_timed() {
  local dir=$1 status=0
  shift
  local TIMEFORMAT='%R %U %S'
  { time OMP_NUM_THREADS=${THREADS:-$threads} "${VCSPH:-build/vcsph}" run "$@" --quiet \
      >>"$dir/run.txt" 2>&1 || status=$?; } 2>"$dir/time.txt"
  echo $status >"$dir/exit"
  return 0
}

vcsph_run() {
  local dir=$1
  shift
  mkdir -p "$dir"
  : >"$dir/run.txt"
  vcsph_timed "$dir" "$@" -o "$dir" --overwrite
}

vcsph_resume() { vcsph_timed "$1" --restart "$1/checkpoint.h5"; }

for_each_run() {
  local jobs=$1 function=$2 start r
  shift 2
  start=$(date +%s)
  for r in "$@"; do
    if [ "$jobs" -gt 1 ]; then
      while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n; done
      $function $r &
    else
      $function $r
    fi
  done
  wait
  echo "$(basename "$0"): $# runs in $(( $(date +%s) - start )) s"
}

us_per_particle_step() {
  local cost
  cost=$(sed -n 's/.*(\([0-9.e+-]*\) particle-steps\/s).*/\1/p' "$1/log.txt" | tail -n 1)
  awk -v cost="$cost" 'BEGIN { if (cost > 0) printf "%.2f", 1e6 / cost; else printf "-" }'
}
