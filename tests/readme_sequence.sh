#!/bin/sh
# The README's "Running a case" commands in order, after the run that `make run` makes, each
# as written but for the runs' length (case.t_end = 0.05 s for a run from t = 0, so that the
# sequence takes seconds), in a folder laid out as a clone: every command must exit 0.
# Placeholder lines (`run ...`) are skipped. Usage: readme_sequence.sh VCSPH_BINARY SOURCE_DIR
set -eu
binary=$1 src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir "$work/build"
ln -s "$binary" "$work/build/vcsph"
cp -r "$src/cases" "$work/cases"
cd "$work"
short="--set case.t_end=0.05"
# make run's commands, from the Makefile's recipe with its defaults
sed -n '/^run:/,/^$/p' "$src/Makefile" | sed -n 's/^\t\$(BUILD)\/vcsph/build\/vcsph/p' |
  sed 's/\$(CASE)/cases\/default.ini/; s/\$(RUN_DIR)/out\/default/g' > commands.txt
# then the README's block
sed -n '/^## Running a case/,/^```$/p' "$src/README.md" | sed -n '/^build\/vcsph/p' |
  sed 's/ *#.*//' >> commands.txt
[ "$(wc -l < commands.txt)" -ge 8 ] || { echo "readme_sequence: too few commands found"; exit 1; }
while read -r line; do
  case $line in *...*) continue ;; esac
  case $line in *" run "*--restart*) command=$line ;; *" run "*) command="$line $short" ;; *) command=$line ;; esac
  echo "readme_sequence: $command"
  if ! sh -c "$command" > out.txt 2>&1; then
    echo "readme_sequence: failed: $command"
    cat out.txt
    exit 1
  fi
done < commands.txt
echo "readme_sequence: $(grep -vc '\.\.\.' commands.txt) commands passed"
