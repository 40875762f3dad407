#!/usr/bin/env bash
# Prints one line per fill: shape, method, radius spec, seed, disks, sha256 of the CSV.
# Every shapes/*.wkt with all three methods, four radius specs scaled to the shape's size
# (1:4 uniform, 1:1.4 bidisperse, 1:20 lognormal, constant) and two seeds; then the other runs
# (periodic cells, jam, fraction, count, height, per-disk types), every output format, the three
# decks (every file of each) and the JSON summary without its timings. A refactor that claims
# bit-identical output runs it before and after and diffs the two listings:
#
#   bench/shape_hashes.sh build/release/tools/frontpack > before.txt   # on the old commit
#   bench/shape_hashes.sh build/release/tools/frontpack > after.txt    # on the new one
#   diff before.txt after.txt
#
# With HASH_JSON_DIR=DIR each JSON summary is also kept (timings stripped) as DIR/LABEL.json;
# bench/compare_json.py BEFORE_DIR AFTER_DIR then tells keys added from values changed.
set -euo pipefail
if [ -n "${HASH_JSON_DIR:-}" ]; then mkdir -p "$HASH_JSON_DIR"; fi
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

# One line per file an extra run wrote: label, file name, sha256.
extra() {
  local label=$1
  shift
  rm -rf "$tmp/x"
  mkdir -p "$tmp/x"
  rc=0
  (cd "$tmp/x" && "$tool" "$@" -q) || rc=$?
  if [ "$rc" -ne 0 ]; then
    echo "$label exit$rc"
    return
  fi
  [ -f "$tmp/x/s.json" ] && python3 -c '
import json, sys
def strip(v):
    if isinstance(v, dict):
        return {k: strip(x) for k, x in v.items() if "seconds" not in k and k not in ("time", "source")}
    if isinstance(v, list):
        return [strip(x) for x in v]
    return v
d = strip(json.load(open(sys.argv[1])))
json.dump(d, open(sys.argv[1], "w"), indent=1, sort_keys=True)' "$tmp/x/s.json"
  # HASH_JSON_DIR=DIR keeps each summary (timings stripped) as DIR/LABEL.json, to tell added keys from changed ones.
  if [ -n "${HASH_JSON_DIR:-}" ] && [ -f "$tmp/x/s.json" ]; then cp "$tmp/x/s.json" "$HASH_JSON_DIR/$label.json"; fi
  (cd "$tmp/x" && find . -type f | LC_ALL=C sort | while read -r f; do
    echo "$label $f $(sha256sum < "$f" | cut -c1-16)"
  done)
}
tool=$(realpath "$tool")
S=$(pwd)/shapes
for method in closed boundary; do
  extra "periodic-xy-$method" fill --periodic 1,1 --method "$method" --radius uniform:0.01,0.03 --seed 3 -o p.csv --json s.json
  extra "periodic-x-$method" fill --periodic 0,0,1.5,1 --periodic-axes x --method "$method" --radius discrete:0.02:0.5,0.028:0.5 --seed 3 -o p.csv --json s.json
done
extra jam fill "$S/l_shape.wkt" --radius discrete:0.04:0.5,0.056:0.5 --jam --seed 2 -o p.csv --json s.json
extra jam-periodic fill --periodic 1,1 --radius discrete:0.03:0.5,0.042:0.5 --jam --seed 2 -o p.csv --json s.json
extra fraction fill "$S/plate_with_holes.wkt" --radius uniform:0.01,0.03 --fraction 0.6 --seed 4 -o p.csv --json s.json
for method in closed open; do
  extra "count-$method" fill "$S/l_shape.wkt" --method "$method" --radius uniform:0.02,0.04 --count 300 --seed 5 -o p.csv --json s.json
done
extra height fill "$S/annulus.wkt" --radius uniform:0.02,0.05 --height 0.3 --seed 6 -o p.csv --json s.json
extra formats fill "$S/gear.wkt" --radius uniform:0.02,0.06 --types size:0.03,0.045 --seed 8 -o p.csv -o p.txt -o p.data -o p.vtp -o p.svg --json s.json
extra region-types fill "$S/plate_with_holes.wkt" --radius uniform:0.01,0.03 --types "region:$S/l_shape.wkt" --seed 8 -o p.csv --json s.json
for sim in lammps liggghts yade; do
  extra "deck-$sim" fill "$S/annulus.wkt" --radius uniform:0.02,0.05 --seed 9 --deck "$sim" d --density 2500 --json s.json
done
extra deck-periodic fill --periodic 1,1 --radius uniform:0.02,0.04 --seed 9 --deck lammps d --density 1000
extra dxf fill "$S/../tests/data/cad/drum.dxf" --radius uniform:0.02,0.05 --seed 10 -o p.csv --json s.json
"$tool" fill "$S/l_shape.wkt" --seed 11 -q -o "$tmp/st.csv"
extra stats stats "$S/l_shape.wkt" ../st.csv --json s.json
extra check check "$S/l_shape.wkt" ../st.csv --json s.json
