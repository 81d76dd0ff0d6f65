#!/usr/bin/env bash
# Packs campaign runs for a lent many-core machine (the device tool, docs/performance.md):
# the stripped release binary with the shared libraries it links, one spec per run (one
# point, one seed, so that a run cut off loses only itself) and a runner that works through
# them 16 at a time, seed by seed across every point of every spec (seed 1 of every point
# first: a cut-off campaign is short of its last seeds, never of a point), and stops after a
# given number of seconds, keeping only finished runs.
#   scripts/device-campaign.sh PKG_DIR [--first-seed N] [--last-seed N] SPEC...
# PKG_DIR must be inside the repository (e.g. target/devpkg: carry it). On the device,
# from the repository root:
#   bash target/devpkg/run.sh SECONDS     # records-only archives under $OUT/records.tar
# Back here, each finished run is taken into the campaign with --resume-from:
#   tar xf records.tar -C DIR
#   pressridge campaign --spec SPEC --out runs/X $(for d in DIR/records/NAME-*; do
#       echo --resume-from $d; done) [--threads N]   # runs what is still missing
# Made for issue 30's friction and modulus sets (crates/lab/records/README.md, paper2/).
# The device tool copies the tracked tree with the carried package, 64 MiB in all, and the
# committed records and figures are more than that: untrack them for the call and restore them
# after it (nothing on disk changes; only the index does):
#   git rm -r -q --cached docs/figures crates/lab/records/paper crates/lab/records/paper2 crates/lab/records/speed-vs-error
#   printf '%s\n' docs/figures/ crates/lab/records/paper/ crates/lab/records/paper2/ crates/lab/records/speed-vs-error/ >> .git/info/exclude
#   ... the device call, carry ["target/devpkg"] ...
#   git reset -q && sed -i '/^docs\/figures\/$\|^data\/paper2\?\/$\|^data\/speed-vs-error\/$/d' .git/info/exclude
set -euo pipefail
cd "$(dirname "$0")/.."
pkg=${1:?package directory}; shift
first=1; last=1000
while [[ ${1:-} == --* ]]; do
  case $1 in
    --first-seed) first=$2; shift 2 ;;
    --last-seed) last=$2; shift 2 ;;
    *) echo "device-campaign: unknown option $1" >&2; exit 2 ;;
  esac
done
[ $# -gt 0 ] || { echo "device-campaign: no campaign spec given" >&2; exit 2; }
# The folder is replaced whole: refuse one that is not an earlier package (never wipe
# another folder given by mistake, e.g. the repository itself).
if [ -e "$pkg" ] && [ -n "$(ls -A "$pkg" 2>/dev/null)" ] && [ ! -f "$pkg/jobs.txt" ]; then
  echo "device-campaign: $pkg exists and is not an earlier package (no jobs.txt); give a new folder" >&2
  exit 2
fi
bin=${PRESSRIDGE_BIN:-./target/release/pressridge}
[ -n "${PRESSRIDGE_BIN:-}" ] || cargo build --release --bin pressridge
rm -rf "$pkg" && mkdir -p "$pkg/specs" "$pkg/stage/lib"
cp "$bin" "$pkg/stage/pressridge" && strip "$pkg/stage/pressridge"
# Every shared library but the C runtime's own (the device has those).
for l in $(ldd "$bin" | awk '/=>/{print $3}'); do
  case $(basename "$l") in libc.so*|libm.so*|ld-linux*|libgcc_s*|libresolv*) ;; *) cp -L "$l" "$pkg/stage/lib/" ;; esac
done
# ICU's data library (31 MB, linked through libxml2 by libnetcdf) is replaced by a stub that
# defines its one symbol: a campaign reads and writes no NetCDF, so ICU is never initialised,
# and the package must fit the device's 64 MiB carry beside the repository.
for l in "$pkg"/stage/lib/libicudata.so.*; do
  [ -e "$l" ] || continue
  sym=$(nm -D "$l" | awk '$2 == "R" && $3 ~ /^icudt[0-9]+_dat$/ {print $3}')
  echo "const char $sym[64] = {0};" > "$pkg/icustub.c"
  cc -shared -fPIC -Wl,-soname,"$(basename "$l")" -o "$l" "$pkg/icustub.c" && rm "$pkg/icustub.c"
done
tar cJf "$pkg/pkg.tar.xz" -C "$pkg/stage" pressridge lib && rm -rf "$pkg/stage"
cp scripts/archive-records.sh "$pkg/"
# One spec per (point, seed), named <spec>-p<point>-s<seed>; the run ids are the full
# spec's (the same axis keys and values, the same seed), so --resume-from takes them.
python3 - "$pkg" "$first" "$last" "$@" <<'PY'
import os, sys, tomllib
pkg, first, last, specs = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4:]
def lit(v):
    if isinstance(v, bool): return "true" if v else "false"
    if isinstance(v, str): return '"' + v.replace('\\', '\\\\').replace('"', '\\"') + '"'
    if isinstance(v, list): return "[" + ", ".join(lit(x) for x in v) + "]"
    return repr(v)
jobs = []
for path in specs:
    s = tomllib.load(open(path, "rb"))
    name = os.path.splitext(os.path.basename(path))[0]
    axes = s.get("axis", [])
    points = [[]]
    for a in axes:
        keys = a.get("keys") or [a["key"]]
        vals = a["values"] if "keys" in a else [[v] for v in a["values"]]
        points = [p + [(keys, v)] for p in points for v in vals]
    f0 = s.get("first_seed", 1)
    seeds = [x for x in range(f0, f0 + s["seeds"]) if first <= x <= last]
    here = os.path.abspath(os.path.dirname(path))
    for seed in seeds:
        for i, p in enumerate(points):
            job = f"{name}-p{i}-s{seed:02d}"
            out = {k: v for k, v in s.items() if k not in ("axis", "seeds", "first_seed", "scene")}
            text = "".join(f"{k} = {lit(v)}\n" for k, v in out.items() if not isinstance(v, dict))
            text += f"first_seed = {seed}\nseeds = 1\n"
            if "scene" in s:
                scene = os.path.relpath(os.path.join(here, s["scene"]), os.path.abspath(f"{pkg}/specs"))
                text += f"scene = {lit(scene)}\n"
            for keys, v in p:
                text += f"\n[[axis]]\nkeys = {lit(keys)}\nvalues = [{lit(v)}]\n"
            for k, v in out.items():
                if isinstance(v, dict):
                    text += f"\n[{k}]\n" + "".join(f"{a} = {lit(b)}\n" for a, b in v.items())
            open(f"{pkg}/specs/{job}.toml", "w").write(text)
            jobs.append((seed, job))
jobs.sort(key=lambda j: j[0])
open(f"{pkg}/jobs.txt", "w").write("".join(j + "\n" for _, j in jobs))
print(f"{len(jobs)} runs packed into {pkg}")
PY
cat > "$pkg/job.sh" <<'JOB'
#!/usr/bin/env bash
# One run: its one-point, one-seed spec into its own directory, then its record archived
# (records-only) under $OUT/records/<job>.
job=$1; d=$(dirname "$0")
if "$d/bin/pressridge" campaign --spec "$d/specs/$job.toml" --out "/tmp/w/$job" --threads 1 -q \
  > "/tmp/w/$job.log" 2>&1; then
  bash "$d/archive-records.sh" "/tmp/w/$job" "$OUT/records/$job" \
    "made on a lent device by scripts/device-campaign.sh ($($d/bin/pressridge --version))" > /dev/null
  echo "$job $SECONDS s $(date -u +%T)" >> "$OUT/times.txt"
else
  echo "$job stopped or failed after $SECONDS s: $(tail -c 300 "/tmp/w/$job.log")" >> "$OUT/failed.txt"
fi
JOB
cat > "$pkg/run.sh" <<'RUN'
#!/usr/bin/env bash
# Works through jobs.txt 16 at a time and stops after $1 seconds (default 500): the runs
# in flight then are dropped, every finished one is in $OUT/records.tar.
set -u
d=$(dirname "$0")
mkdir -p "$d/bin" /tmp/w "$OUT/records"
tar xJf "$d/pkg.tar.xz" -C "$d/bin"
export LD_LIBRARY_PATH="$PWD/$d/bin/lib"
{ nproc; lscpu | grep -i 'model name'; date -u; "$d/bin/pressridge" --version; } > "$OUT/info.txt" 2>&1
xargs -P 16 -n 1 bash "$d/job.sh" < "$d/jobs.txt" &
x=$!
( sleep "${1:-500}"; kill $x ) &
w=$!
wait $x
pkill -KILL -f "$d/bin/pressridge"
kill $w 2>/dev/null
sleep 2
echo "stopped $(date -u)" >> "$OUT/info.txt"
cd "$OUT" && tar cf records.tar records && rm -rf records
RUN
chmod +x "$pkg/job.sh" "$pkg/run.sh"
