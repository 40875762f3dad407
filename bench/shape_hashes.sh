#!/usr/bin/env bash
# Prints one line per fill: shape, method, radius spec, seed, disks, sha256 of the CSV.
# Every shapes/*.wkt with all three methods, four radius specs scaled to the shape's size
# (1:4 uniform, 1:1.4 bidisperse, 1:20 lognormal, constant) and two seeds. A refactor that claims
# bit-identical output runs it before and after and diffs the two listings:
#
#   bench/shape_hashes.sh build/release/tools/frontpack > before.txt   # on the old commit
#   bench/shape_hashes.sh build/release/tools/frontpack > after.txt    # on the new one
#   diff before.txt after.txt
set -euo pipefail
tool=${1:-build/release/tools/frontpack}
cd "$(dirname "${BASH_SOURCE[0]}")/.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for shape in shapes/*.wkt; do
  area=$("$tool" info "$shape" | awk '/^ *area:/{print $2}')
  # L: the radius unit, 1/100 of the square root of the area: about 3,000 disks at 1:4.
  L=$(python3 -c "import math; print(repr(math.sqrt($area) / 100))")
  specs=(
    "uniform:$(python3 -c "print(repr(0.5*$L)),print(repr(2*$L))" | paste -sd,)"
    "discrete:$(python3 -c "print(repr($L))"):0.5,$(python3 -c "print(repr(1.4*$L))"):0.5"
    "lognormal:$(python3 -c "print(repr($L))"),1.6,$(python3 -c "print(repr(0.2*$L))"),$(python3 -c "print(repr(4*$L))")"
    "constant:$(python3 -c "print(repr($L))")"
  )
  for method in closed open boundary; do
    for spec in "${specs[@]}"; do
      for seed in 1 7; do
        rc=0
        "$tool" fill "$shape" --method "$method" --radius "$spec" --seed "$seed" -q -o "$tmp/p.csv" || rc=$?
        if [ "$rc" -eq 0 ]; then
          n=$(($(wc -l < "$tmp/p.csv") - 1))
          h=$(sha256sum < "$tmp/p.csv" | cut -c1-16)
        else
          n="exit$rc"; h=-
        fi
        echo "$(basename "$shape" .wkt) $method $spec $seed $n $h"
        rm -f "$tmp/p.csv"
      done
    done
  done
done
