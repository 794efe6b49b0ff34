#!/bin/bash
# `mpirun -n P vcsph-mpi run` writes the same files, byte for byte, as `vcsph run` on one
# process (docs/mpi.md), for P = 1 to 4: the time series, events, dissipation, loads, every
# snapshot and the XDMF index, the images, the checkpoint, case.ini (log.txt says how many
# threads and differs). Checked on:
#   - a 2D sway run (delta-plus-ALE with EdBC and the volume correction, the defaults; the
#     graphical method's eps_gm; gauges and pressure probes at the walls and inside), with 2
#     threads per process on P = 2 (hybrid);
#   - a 2D heave run with water's surface tension and an eta threshold so low that the switch
#     flips eta 26 times in 0.04 s, with particle images;
#   - a 3D sway run, with probes;
#   - a dam break whose front crosses the whole tank, on 2 and 4 processes (migration into
#     slabs that start empty, the boundaries moving);
#   - 11 processes for a tank of 10 strips of cells: exit 2, nothing written;
#   - a checkpoint written by 3 processes, continued by 2: the files of the run continued by one
#     process from its own checkpoint;
#   - a breakdown in the last process's slab (a tank rolled about its left corner splashes at
#     its right end): exit 3 on every process, one diagnosis, the files of one process;
#   - SIGTERM to every process during the run: exit 4 and a checkpoint, from which 2 processes
#     finish the run as one process does uninterrupted.
# Usage: mpi_run.sh VCSPH VCSPH_MPI (ctest passes the two binaries of the MPI build).
set -u
vcsph=$1 vcsph_mpi=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
failures=0

fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}

# Each run writes into DIR/out, run from DIR: the same output path in case.ini for all.
# one DIR ARGS...: vcsph run ARGS on one process
one() {
  local dir=$1
  shift
  mkdir -p "$dir" && (cd "$dir" && "$vcsph" run "$@" --quiet)
}

# mpi DIR P THREADS ARGS...: vcsph-mpi run on P processes with THREADS threads each, its
# terminal output in DIR/mpi.txt
mpi() {
  local dir=$1 p=$2 threads=$3
  shift 3
  mkdir -p "$dir" && (cd "$dir" && OMP_NUM_THREADS=$threads mpirun --oversubscribe -n "$p" \
    "$vcsph_mpi" run "$@" >mpi.txt 2>&1)
}

# same_files REF DIR WHAT: every file of REF/out (not log.txt, not the lock) equal in DIR/out
same_files() {
  local f n=0
  for f in $(cd "$1/out" && find . -type f ! -name log.txt ! -name .vcsph.lock | sort); do
    n=$((n + 1))
    cmp -s "$1/out/$f" "$2/out/$f" || fail "$3: $f differs from one process's"
  done
  [ "$n" -ge 6 ] || fail "$3: only $n files in $1/out"
}

# The cases; the sound speed is given, so that c0 does not depend on t_end (a restart that
# extends a run keeps its own).
cat >sway.ini <<'EOF'
[case]
name = sway
dim = 2
t_end = 0.05
[tank]
length = 4.0
height = 0.2
[liquid]
height = 0.05
[motion]
type = sway
amplitude = 0.05
period = 0.5
[numerics]
resolution = 8
sound_speed = 10
[probes]
gauges = 0.05, 2.0, 3.95
pressure = 0.0 0.02; 4.0 0.02 d=0.01; 2.0 0.01
[output]
timeseries_every = 0.005
snapshot_every = 0.02
graphical = true
EOF
cat >heave.ini <<'EOF'
[case]
name = heave
dim = 2
t_end = 0.04
[tank]
length = 4.0
height = 0.2
[liquid]
height = 0.05
[fluid]
surface_tension = 0.0727
[motion]
type = heave
amplitude = 0.002
period = 0.01
[model]
eta_threshold = 0.0001
[numerics]
resolution = 8
[output]
timeseries_every = 0.005
snapshot_every = 0.02
image_every = 0.02
EOF

# the sway case in a 3D tank, shorter, its probes moved into it
box3d=(--set case.dim=3 --set tank.length=2.0 --set tank.height=0.15 --set tank.width=0.1
       --set numerics.resolution=5 --set case.t_end=0.03 --set output.snapshot_every=0.015
       --set probes.gauges="0.05, 1.0, 1.95"
       --set probes.pressure="0.0 0.02 0.05; 2.0 0.02 0.05 d=0.01; 1.0 0.01 0.05")
for c in sway heave box3d; do
  case $c in
    box3d) args=("$work/sway.ini" "${box3d[@]}") ;;
    *) args=("$work/$c.ini") ;;
  esac
  one $c/one "${args[@]}" -o out || fail "$c: one process exited $?"
  for p in 1 2 3 4; do
    threads=$([ "$p" = 2 ] && echo 2 || echo 1)
    mpi $c/np$p $p "$threads" "${args[@]}" -o out --quiet ||
      fail "$c: $p processes exited $? ($(tail -n 3 $c/np$p/mpi.txt))"
    same_files $c/one $c/np$p "$c, $p processes x $threads threads"
  done
done
grep -c eta_switch heave/one/out/events.csv | grep -qx 26 || fail "heave: not 26 eta switches"

# A dam break whose front crosses the whole tank in 1 s: the liquid starts in the first two of
# the 16 strips of cells, so on 4 processes three slabs start empty, and every process takes
# particles in turn as the front reaches it (a body of liquid ending in a slab's last cell
# column once made the fold of its sums hand back zeros: NaN at step 108 on 4 processes).
cat >dam.ini <<'EOF'
[case]
name = dam
dim = 2
t_end = 1.0
[tank]
length = 1.0
height = 0.3
[liquid]
height = 0.1
length = 0.08
[numerics]
resolution = 25
[output]
timeseries_every = 0.01
snapshot_every = 0.5
EOF
one dam/one "$work/dam.ini" -o out || fail "dam: one process exited $?"
for p in 2 4; do
  mpi dam/np$p $p 1 "$work/dam.ini" -o out || fail "dam: $p processes exited $?"
  same_files dam/one dam/np$p "a dam break across the tank, $p processes"
  shares=$(sed -n 's/.*particles per process at the end: //p' dam/np$p/out/log.txt)
  [ "$(echo "$shares" | tr ',' '\n' | awk '$1 > 0' | wc -l)" = $p ] ||
    fail "dam, $p processes: not every process holds liquid at the end ($shares)"
done

# more processes than strips of cells: refused before anything is written. A box of fewer
# than 16 cells along x has one strip a cell: the sway tank cut to 0.2 m spans 0.2 m and a
# search radius (2h and the thinnest skin, 4.05 dr) either side, 9.9 radii: 10 cells.
short=(--set tank.length=0.2 --set probes.gauges= --set probes.pressure=)
mpi strips 11 1 "$work/sway.ini" "${short[@]}" -o out
[ $? = 2 ] || fail "11 processes on 10 strips: not exit 2"
grep -q "at most 10 strips" strips/mpi.txt || fail "11 processes on 10 strips: not said"
[ ! -e strips/out ] || fail "11 processes on 10 strips: the folder was made"

# restart on another number of processes
one restart/one "$work/sway.ini" -o out --set case.t_end=0.03 &&
  one restart/one --restart out/checkpoint.h5 --set case.t_end=0.05 ||
  fail "restart: one process exited $?"
mpi restart/split 3 1 "$work/sway.ini" -o out --set case.t_end=0.03 --quiet &&
  mpi restart/split 2 1 --restart out/checkpoint.h5 --set case.t_end=0.05 --quiet ||
  fail "restart: 3 then 2 processes exited $?"
same_files restart/one restart/split "a checkpoint of 3 processes continued by 2"

# a breakdown in the last slab
roll=(--set motion.type=roll --set motion.angle=0.2 --set motion.center="0 0"
      --set motion.period=0.2 --set motion.amplitude=0 --set numerics.sound_speed=auto
      --set numerics.density_bound=0.0057)
one breakdown/one "$work/sway.ini" -o out "${roll[@]}"
[ $? = 3 ] || fail "breakdown: one process did not exit 3"
grep -q "particle id 4477" breakdown/one/out/events.csv || fail "breakdown: not at particle 4477"
mpi breakdown/split 3 1 "$work/sway.ini" -o out "${roll[@]}"
[ $? = 3 ] || fail "breakdown: 3 processes did not exit 3 ($(tail -n 3 breakdown/split/mpi.txt))"
same_files breakdown/one breakdown/split "a breakdown on the last process"
[ "$(grep -c 'vcsph: breakdown at' breakdown/split/mpi.txt)" = 1 ] ||
  fail "breakdown: not one diagnosis"

# SIGTERM to every process once the time loop runs
one signal/one "$work/sway.ini" -o out --set case.t_end=0.3 || fail "signal: one process"
mpi signal/split 3 1 "$work/sway.ini" -o out --set case.t_end=0.3 &
launcher=$!
for _ in $(seq 600); do
  [ "$(wc -l 2>/dev/null <signal/split/out/timeseries.csv || echo 0)" -ge 4 ] && break
  sleep 0.1
done
pkill -TERM -x "$(basename "$vcsph_mpi")"
wait $launcher
status=$?
[ $status = 4 ] || fail "signal: exit $status, not 4 ($(tail -n 3 signal/split/mpi.txt))"
grep -q "stopped by SIGTERM" signal/split/mpi.txt || fail "signal: no word of the stop"
mpi signal/split 2 1 --restart out/checkpoint.h5 --quiet || fail "signal: the restart exited $?"
same_files signal/one signal/split "stopped by SIGTERM, continued by 2 processes"

echo "mpi_run: $failures failures"
[ $failures = 0 ]
