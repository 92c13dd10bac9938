#!/usr/bin/env bash
# What docs/FILTERS.md ("Choosing a filter") shows beyond `texfilter bench`: its pictures, the rows of the
# filter form the bench has no label for (tf_aniso's feline shape), measured the way the bench measures
# (host/bench/metrics.cpp: display-unit RMSE of frame 0 against each truth, flicker over the camera path),
# and the texel reads the includes' header comments quote.
#
# usage: tools/filter_guide.sh [TEXFILTER] [pictures|numbers|counts|all]   (default: build/texfilter, all)
#   pictures  docs/images/filters/*.png: crops of 256x256 renders (plane: 512² checker), magnified 2x by
#             pixel replication, grey (the R channel, 8-bit sRGB), tiled by oiiotool (front.png: README's)
#   numbers   prints, for plane, tunnel and slanted (256x256, checker 512, fragment stage, fine quads, 256
#             samples a pixel, 8 path frames), tf_aniso with 16 probes in the gpu and feline shapes: PSNR
#             against the box and Gaussian truths, flicker against each, texel reads a covered pixel; the gpu
#             rows check the method against `texfilter bench`'s aniso16 rows
#   counts    prints texel reads (texelFetch + hardware lookups) a covered pixel, mean and max, of the
#             multi-tap forms on plane and slanted (256x256, checker 256)
# Reads are `render --view data`'s B channel (the sky holds 0.03, a covered pixel at least 1). A few minutes
# on lavapipe on 2 cores. Temporary files go to a private directory, removed at exit.
set -euo pipefail
cd "$(dirname "$0")/.."
texfilter=${1:-./build/texfilter}
what=${2:-all}
if [[ ! -x $texfilter ]]; then
    echo "no texfilter binary at $texfilter: build it first (tools/build.sh)" >&2
    exit 2
fi
case $what in
pictures | numbers | counts | all) ;;
*) echo "unknown part '$what' (pictures, numbers, counts or all)" >&2; exit 2 ;;
esac
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

texture_size=512
render() { # render NAME SCENE FILTER [flags...]: a 256x256 render of the checker into $work/NAME
    local name=$1 scene=$2 filter=$3
    shift 3
    "$texfilter" render --scene "$scene" --texture checker --texture-size "$texture_size" --filter "$filter" \
        --size 256x256 "$@" -o "$work/$name" >/dev/null
}

# The PFM reader and the bench's display transform, for the Python below.
cat >"$work/guide.py" <<'EOF'
import numpy as np

def read_pfm(path):
    with open(path, "rb") as f:
        kind = f.readline().strip()
        w, h = map(int, f.readline().split())
        scale = float(f.readline())
        data = np.frombuffer(f.read(), dtype="<f4" if scale < 0 else ">f4").astype(np.float64)
    return data.reshape(h, w, 3 if kind == b"PF" else 1)

def reads(path):  # texel reads of the covered pixels of a --view data render
    b = read_pfm(path)[..., 2]
    return b[b >= 1]

def display(linear):  # host/bench/metrics.cpp: clamp to [0, 1], exact sRGB encode, RGB
    c = np.clip(linear[..., :3], 0.0, 1.0)
    return np.where(c <= 0.0031308, 12.92 * c, 1.055 * np.power(c, 1 / 2.4) - 0.055)

def psnr(a, b):
    return min(99.0, -20 * np.log10(np.sqrt(np.mean((display(a) - display(b)) ** 2))))

def flicker(fs, ts):  # RMS of the filter's frame-to-frame change minus the truth's
    f, t = [display(x) for x in fs], [display(x) for x in ts]
    return float(np.sqrt(np.mean(np.square([(f[i + 1] - f[i]) - (t[i + 1] - t[i]) for i in range(len(f) - 1)]))))
EOF

if [[ $what == pictures || $what == all ]]; then
    out=docs/images/filters
    mkdir -p "$out" # each picture written by name: nothing else in the folder is touched
    strip() { # strip OUT NAME...: the crops ($crop) of $work/NAME.png, 2x, in a 2-column mosaic
        local name=$1 size=${crop%%+*} inputs=()
        shift
        for n in "$@"; do
            oiiotool "$work/$n.png" --ch R --cut "$crop" --resample "$((2 * ${size%x*}))x$((2 * ${size#*x}))" \
                -o "$work/$n-crop.png"
            inputs+=("$work/$n-crop.png")
        done
        oiiotool "${inputs[@]}" --mosaic:pad=4 "${columns}x$((($# + columns - 1) / columns))" -o "$out/$name.png"
        echo "$out/$name.png"
    }
    columns=2
    # The plane's far rows (66..113 of 256, towards the horizon: long, thin footprints), where the filters
    # differ; the two truths first.
    crop=160x48+48+66
    render truth-box.png plane ground-truth --pixel-filter box
    render truth-gauss.png plane ground-truth --pixel-filter gaussian
    render hw-trilinear.png plane hw-trilinear
    render brilinear.png plane brilinear
    render aniso.png plane aniso --probes 16
    render sat-assembly.png plane sat-assembly --boxes 4
    render ewa.png plane ewa
    render hw-aniso.png plane hw-aniso --aniso 16
    strip horizon truth-box truth-gauss hw-trilinear brilinear aniso sat-assembly ewa hw-aniso
    # Magnification (zoom: 8 pixels a texel): the analytic truth (the checker's own edges), bilinear, the cubics.
    crop=96x48+80+104
    render zoom-truth.png zoom ground-truth --truth analytic
    render zoom-bilinear.png zoom bilinear
    render zoom-bspline.png zoom bspline
    render zoom-catmull-rom.png zoom catmull-rom
    strip magnify zoom-truth zoom-bilinear zoom-bspline zoom-catmull-rom
    # README's front picture: the plane from the middle to the horizon (rows 62..141) under the Gaussian truth,
    # nearest, trilinear, hardware aniso 16, tf_aniso and tf_ewa, three a row.
    crop=200x80+28+62
    columns=3
    render nearest.png plane nearest
    render trilinear.png plane trilinear
    strip front truth-gauss nearest trilinear hw-aniso aniso ewa
    du -ch "$out"/*.png | tail -n 1
fi

if [[ $what == numbers || $what == all ]]; then
    py=$(tools/python_env.sh | tail -1)
    frames=8
    for scene in plane tunnel slanted; do
        for t in box gaussian; do
            for ((f = 0; f < frames; ++f)); do
                render "$scene-truth-$t-$f.pfm" "$scene" ground-truth --pixel-filter "$t" --frame "$f"
            done
        done
        for shape in gpu feline; do
            for ((f = 0; f < frames; ++f)); do
                render "$scene-$shape-$f.pfm" "$scene" aniso --probes 16 --aniso-shape "$shape" --frame "$f"
            done
            render "$scene-$shape-data.pfm" "$scene" aniso --probes 16 --aniso-shape "$shape" --view data
        done
    done
    PYTHONPATH=$work "$py" - "$work" "$frames" <<'EOF'
import sys
from guide import read_pfm, reads, psnr, flicker

work, frames = sys.argv[1], int(sys.argv[2])
print("scene    shape   PSNR box  PSNR gauss  flicker box  flicker gauss  reads/px")
for scene in ("plane", "tunnel", "slanted"):
    truth = {t: [read_pfm(f"{work}/{scene}-truth-{t}-{i}.pfm") for i in range(frames)] for t in ("box", "gaussian")}
    for shape in ("gpu", "feline"):
        fs = [read_pfm(f"{work}/{scene}-{shape}-{i}.pfm") for i in range(frames)]
        print(f"{scene:8s} {shape:7s} {psnr(fs[0], truth['box'][0]):8.2f} {psnr(fs[0], truth['gaussian'][0]):11.2f}"
              f" {flicker(fs, truth['box']):12.4f} {flicker(fs, truth['gaussian']):14.4f}"
              f" {reads(f'{work}/{scene}-{shape}-data.pfm').mean():9.1f}")
EOF
fi

if [[ $what == counts || $what == all ]]; then
    py=$(tools/python_env.sh | tail -1)
    texture_size=256
    forms=("trilinear" "brilinear" "aniso" "aniso --taps hardware" "aniso --aniso-shape feline" "ewa"
           "ewa --taps hardware" "sat" "sat-assembly")
    names=()
    for scene in plane slanted; do
        for form in "${forms[@]}"; do
            name="$scene ${form//--/}"
            # shellcheck disable=SC2086 # a form is a filter and its flags
            render "${name// /_}.pfm" "$scene" $form --view data
            names+=("$name")
        done
    done
    PYTHONPATH=$work "$py" - "$work" "${names[@]}" <<'EOF'
import sys
from guide import reads

work = sys.argv[1]
print("scene    form                           mean     max")
for name in sys.argv[2:]:
    r = reads(f"{work}/{name.replace(' ', '_')}.pfm")
    scene, form = name.split(" ", 1)
    print(f"{scene:8s} {form:28s} {r.mean():7.1f} {r.max():7.0f}")
EOF
fi
