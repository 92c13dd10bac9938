#!/usr/bin/env bash
# bench --footprints --quick end to end on this machine's device: bench.json, bench.csv and tables.md hold a row
# for every (texture, truth, filter, bucket), with a finite PSNR and noise floor and the bucket's lookups (checked
# with the standard library only: always asserted); then, in tools/.venv, tools/bench_report.py draws its two
# figures. When the venv cannot be made here (tools/python_env.sh exits 3) that second half is skipped, saying so.
# One of the textures is an image file (written here), so the photos' pooled rows are checked too.
#
# usage: bench_footprints.sh TEXFILTER REPO_ROOT
set -euo pipefail
if [[ $# -ne 2 ]]; then
    echo "usage: $0 TEXFILTER REPO_ROOT" >&2
    exit 2
fi
texfilter=$(realpath "$1")
root=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# A 48x32 picture with detail at every scale: a PPM, which every image-I/O build reads.
python3 - "$work/photo.ppm" <<'EOF'
import sys
w, h = 48, 32
rows = []
for y in range(h):
    for x in range(w):
        rows.append(f"{(x * 37 + y * 11) % 256} {(x * x + 3 * y) % 256} {((x ^ y) * 8) % 256}")
with open(sys.argv[1], "x") as f:
    f.write(f"P3\n{w} {h}\n255\n" + "\n".join(rows) + "\n")
EOF

filters=ewa,ewa-hw,hw-aniso16,hw-trilinear,trilinear,aniso16,aniso16-hw,sat-assembly,ref-ewa
"$texfilter" bench --footprints --quick --textures "checker,zoneplate,$work/photo.ppm" --filters "$filters" \
    --out "$work/fp"

python3 - "$work/fp" "$filters" "$work/photo.ppm" <<'EOF'
import csv, json, math, os, sys
out, filters, photo = sys.argv[1], sys.argv[2].split(","), sys.argv[3]
bench = json.load(open(os.path.join(out, "bench.json")))
assert bench["kind"] == "footprints", bench.get("kind")
buckets = [(b["axis"], b["name"]) for b in bench["config"]["buckets"]]
majors = [n for a, n in buckets if a == "major"]
anisos = [n for a, n in buckets if a == "anisotropy"]
assert majors == ["<1", "1-2", "2-4", "4-8", "8-16", "16-32", "32-64", "64-128", "128-256"], majors
assert anisos == ["1-2", "2-4", "4-8", "8-16", ">16"], anisos
assert [n for a, n in buckets if a == "major-isotropic"] == majors
rows = list(csv.DictReader(open(os.path.join(out, "bench.csv"))))
assert len(rows) == len(bench["rows"]), (len(rows), len(bench["rows"]))
textures = ["checker", "zoneplate", photo, "photos"]
seen = {}
for r in rows:
    key = (r["texture"], r["truth"], r["label"], r["axis"], r["bucket"])
    assert key not in seen, f"row {key} twice"
    seen[key] = r
problems = []
for texture in textures:
    for truth in ("box", "gaussian"):
        for axis in ("major", "anisotropy", "major-isotropic"):
            for label in filters:
                total = 0
                for a, name in buckets:
                    if a != axis:
                        continue
                    r = seen.get((texture, truth, label, axis, name))
                    if r is None:
                        problems.append(f"no row {texture} {truth} {label} {axis} {name}")
                        continue
                    for key in ("psnr", "floor_psnr"):
                        if not r[key] or not math.isfinite(float(r[key])):
                            problems.append(f"{texture} {truth} {label} {name}: {key} '{r[key]}'")
                    if int(r["lookups"]) < 1 and axis != "major-isotropic":
                        problems.append(f"{texture} {name}: no lookups")
                    if label != "ref-ewa" and not r["fetches"]:  # the device's shaders count their work
                        problems.append(f"{texture} {label} {name}: no fetch count")
                    total += int(r["lookups"])
                # Every lookup lies in exactly one bucket of each full axis ("photos" pools the one file here).
                if axis != "major-isotropic" and total != bench["config"]["lookups"]:
                    problems.append(f"{texture} {truth} {label} {axis}: buckets hold {total} of "
                                    f"{bench['config']['lookups']} lookups")
tables = open(os.path.join(out, "tables.md")).read()
for texture in textures:
    if f"{texture}, gaussian truth, PSNR (dB) by anisotropy" not in tables:
        problems.append(f"tables.md has no table for {texture}")
if problems:
    print("\n".join(problems[:40]), file=sys.stderr)
    sys.exit(1)
print(f"bench_footprints: {len(rows)} rows, every (texture, truth, filter, bucket) present and finite")
EOF

status=0
python=$("$root/tools/python_env.sh" | tail -1) || status=$?
if [[ $status -eq 3 ]]; then
    echo "bench_footprints: SKIPPED the figures: tools/python_env.sh cannot make tools/.venv here"
    exit 0
elif [[ $status -ne 0 ]]; then
    echo "bench_footprints: tools/python_env.sh failed (exit $status)" >&2
    exit 1
fi
"$python" "$root/tools/bench_report.py" "$work/fp"
for figure in footprints_major.png footprints_anisotropy.png footprints_major-isotropic.png; do
    [[ -s $work/fp/$figure ]] || { echo "bench_footprints: tools/bench_report.py wrote no $figure" >&2; exit 1; }
done
echo "bench_footprints: complete"
