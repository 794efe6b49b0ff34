#!/bin/sh
# Every global function of the dimension-generic libraries must carry its _2d / _3d suffix
# (DIM_NAME in the headers): an unsuffixed one is defined in both libraries and the linker
# silently uses one of them for both dimensions.
status=0
for d in 2 3; do
  lib="$1/libvcsph_${d}d.a"
  if [ ! -f "$lib" ]; then
    echo "$lib: missing (build the libraries first)"
    status=1
    continue
  fi
  bad=$(nm --defined-only -g "$lib" | awk '$2 == "T" || $2 == "D" || $2 == "B" { print $3 }' | grep -v "_${d}d\$")
  if [ -n "$bad" ]; then
    echo "$lib: global symbols without the _${d}d suffix (add DIM_NAME renames in their header):"
    echo "$bad"
    status=1
  fi
done
exit $status
