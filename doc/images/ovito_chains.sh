#!/usr/bin/env bash
# The picture of doc/ovito.md: examples/pile (750 discs settled under gravity) run with the
# OVITO lines of doc/ovito.md section 1 added (fix_modify contacts pairs, a custom dump of the
# spheres, a local dump of the contacts labelled BONDS), then its force chains drawn from those
# two files alone by examples/common/plot_bed.py.
#   bash doc/images/ovito_chains.sh [OUTDIR]     (default out/ovito; about 10 s)
# HARDCONTACT_LMP: another launcher (default build/lmp_hardcontact).
set -euo pipefail
PY=/usr/bin/python3; [ -x "$PY" ] || PY=python3
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
LMP="${HARDCONTACT_LMP:-$ROOT/build/lmp_hardcontact}"
OUT="$(mkdir -p "${1:-$ROOT/out/ovito}" && cd "${1:-$ROOT/out/ovito}" && pwd)"
[ -x "$LMP" ] || { echo "ovito_chains: no launcher at $LMP: build first (bash .ci/build.sh)" >&2; exit 1; }

"$PY" "$ROOT/examples/pile/make_data.py" "$OUT/data.pile" >/dev/null
# the example's deck, with the lines of doc/ovito.md after the fix and before the run
sed -e '/^fix  *hc all hardcontact/a fix_modify      hc contacts pairs' \
    -e '/^run /i dump            spheres all custom ${dump_every} spheres.dump id type radius x y z vx vy vz f_hc[1] f_hc[2] f_hc[3] f_hc[4]\
dump_modify     spheres sort id\
dump            chains all local ${dump_every} chains.dump f_hc[1] f_hc[2] f_hc[3] f_hc[4] f_hc[5] f_hc[6]\
dump_modify     chains label BONDS' \
    "$ROOT/examples/pile/in.pile" >"$OUT/in.pile.ovito"
grep -q "^fix_modify      hc contacts pairs" "$OUT/in.pile.ovito" \
  || { echo "ovito_chains: examples/pile/in.pile has no 'fix hc all hardcontact' line any more" >&2; exit 1; }
(cd "$OUT" && "$LMP" -in in.pile.ovito -var data data.pile -log log.lammps -screen none)
grep -q "ITEM: NUMBER OF BONDS" "$OUT/chains.dump"
"$PY" "$ROOT/examples/common/plot_bed.py" "$ROOT/doc/images/ovito_chains.png" \
  "$OUT:spheres.dump:chains.dump:hard:examples/pile at 0.4 s - spheres.dump + chains.dump (contacts pairs, label BONDS)"
