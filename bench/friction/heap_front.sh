#!/usr/bin/env bash
# The heap of examples/heap (800 spheres poured onto a rough floor, mu 0.5, t = 45) by the fix
# at tol 1e-2, 1e-3, 1e-4 and by its soft twin (pair_style granular), each with three seeds of
# fix pour: flank and cone angles (examples/heap/heap_angle.py) and loop times, one process.
# Writes friction_front_heap.csv into bench/results/friction/<host>/ (bench/common.sh).
#   bench/friction/heap_front.sh [--quick]      (--quick: 400 spheres to t = 30, one seed)
set -euo pipefail
# shellcheck source=../common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh" friction_front_heap_ "$@"
HEAP="$ROOT/examples/heap"
SEEDS=(4767548 1234567 7654321); EXTRA=()
[ "$MODE" = quick ] && { SEEDS=(4767548); EXTRA=(-var npour 400 -var tend 30); }
CSV="$RESULTS/friction_front_heap${MODE/full/}.csv"
CSV="${CSV/quick/_quick}"
echo "run,kind,tol,seed,flank_deg,cone_deg,peak,loop_s,steps,it_mean,overlap_max,maxiter_stops,load1" > "$CSV"
for seed in "${SEEDS[@]}"; do
  for tol in 1e-2 1e-3 1e-4 soft; do
    d="$WORK/${tol}_$seed"
    mkdir -p "$d"
    if [ "$tol" = soft ]; then exe="$SOFT_LMP"; deck="$HEAP/in.heap.soft"; args=(); else
      exe="$LMP"; deck="$HEAP/in.heap"; args=(-var tol "$tol"); fi
    (cd "$d" && "$exe" -in "$deck" -var mu 0.5 -var seed "$seed" "${args[@]}" "${EXTRA[@]}" \
       -log log.lammps -echo none -screen none > /dev/null)
    angle=$("$PY" "$HEAP/heap_angle.py" --floor 1.0 "$d/heap.dump")
    "$PY" - "$d/log.lammps" "$tol" "$seed" "$angle" "$(bench_load1)" >> "$CSV" <<'PY'
import re, sys
log, tol, seed, angle, load = sys.argv[1:]
text = open(log).read()
loop = re.findall(r"^Loop time of ([0-9.eE+-]+) on \d+ procs for (\d+) steps", text, re.M)[-1]
m = re.search(r"flank ([0-9.]+) deg", angle)
flank = m.group(1) if m else "nan"
cone = re.search(r"cone ([0-9.]+) deg", angle).group(1)
peak = re.search(r"peak ([0-9.]+)", angle).group(1)
it = ov = stops = ""
if tol != "soft":
    rows, cols = [], None
    for line in text.splitlines():
        w = line.split()
        if w and w[0] == "Step":
            cols = w
            continue
        if cols and len(w) == len(cols) and w[0].isdigit():
            rows.append(dict(zip(cols, w)))
    its = [float(r["f_hc[1]"]) for r in rows if "f_hc[1]" in r][1:]
    it = "%.1f" % (sum(its) / max(1, len(its)))
    ov = "%.3g" % max(float(r["f_hc[7]"]) for r in rows if "f_hc[7]" in r)
    stops = rows[-1].get("f_hc[6]", "")
print(",".join([("hard_tol" + tol) if tol != "soft" else "soft", "soft" if tol == "soft" else "hard",
                tol, seed, flank, cone, peak, loop[0], loop[1], it, ov, stops, load]))
PY
    tail -1 "$CSV"
  done
done
