#!/usr/bin/env bash
# Bad input must give a clear error, exit status 2 (1 only for a failed `diff`), no crash, and no
# output file (not even a half-written temporary one).
#
# usage: bad_inputs.sh TEXFILTER GOLDEN_DIR [GROUP...]  (all groups by default; --list names them)
#
# Everything that is not about Vulkan uses --backend reference, so the script is fast and needs no
# GPU. The Vulkan cases fake a machine without a driver through the loader's environment variables;
# the --device case is skipped where no Vulkan device is usable at all.
set -euo pipefail

if [[ ${1:-} == --list ]]; then
    sed -n '/^CASE_GROUPS=(/,/)/p' "$0" | tr -d '()' | sed 's/CASE_GROUPS=//' | tr -s ' \n' '\n' | sed '/^$/d'
    exit 0
fi
if [[ $# -lt 2 ]]; then
    echo "usage: $0 TEXFILTER GOLDEN_DIR [GROUP...]   (or: $0 --list)" >&2
    exit 2
fi
TEXFILTER=$(realpath "$1")
GOLDEN_DIR=$(realpath "$2")
SELECTED=("${@:3}")
# The first line of golden --out's marker (host/io/output_dir.cpp): a directory with it is golden's own.
GOLDEN_MARKER_HEADING="# texfilter golden output directory. texfilter golden removes the files listed here (and only these) when it runs again with this --out."
# With validation on (as for the GPU tests), the loader's own complaints reach stderr as validation
# messages; this script checks the messages a user sees by default.
unset TEXFILTER_VALIDATE

WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
# Relative names from here on, so messages are checked as a user would see them.
cd "$WORK"

passed=0
failed=0
skipped=0
# A hung command must not hang the test suite; ctest's own timeout would not say which case hung.
COMMAND_TIMEOUT=300

pass() {
    echo "PASS  $1"
    passed=$((passed + 1))
}

fail() {
    echo "FAIL  $1: $2"
    if [[ -s stderr ]]; then sed 's/^/      stderr| /' stderr; fi
    failed=$((failed + 1))
}

skip() {
    echo "SKIP  $1: $2"
    skipped=$((skipped + 1))
}

# run_command COMMAND...: runs it with stdout/stderr captured in ./stdout and ./stderr; sets rc.
run_command() {
    rc=0
    timeout "$COMMAND_TIMEOUT" "$@" >stdout 2>stderr || rc=$?
}

# Temporary outputs are named OUT.tmp-XXXXXX; any left behind means a failure path forgot to clean up.
leftover_temporaries() {
    find . -name '*.tmp-*' -print
}

# expect_error DESCRIPTION EXPECTED_SUBSTRING OUTPUT_PATH -- COMMAND...
#   OUTPUT_PATH: the file the command would write, or - where it writes none.
#   Set EXPECT_ONE_LINE=1 in the call's environment to require a one-line message on stderr.
expect_error() {
    local description=$1 expected=$2 output=$3
    shift 4 # the three arguments and --
    run_command "$@"
    local leftovers
    leftovers=$(leftover_temporaries)
    if [[ $rc -eq 124 ]]; then
        fail "$description" "timed out after ${COMMAND_TIMEOUT}s"
    elif [[ $rc -ge 128 ]]; then
        fail "$description" "crashed (exit $rc, signal $((rc - 128)))"
    elif [[ $rc -eq 0 ]]; then
        fail "$description" "exit 0, expected an error"
    elif [[ $rc -ne 2 ]]; then
        fail "$description" "exit $rc, expected 2 (texfilter's exit status for errors)"
    elif ! grep '^texfilter: ' stderr | grep -qF -- "$expected"; then
        fail "$description" "no 'texfilter: ...' line on stderr mentions '$expected'"
    elif grep -q 'internal error' stderr; then
        # An exception that was not turned into a tf::Error: the message was not written for users.
        fail "$description" "reported as an internal error"
    elif [[ ${EXPECT_ONE_LINE:-0} == 1 && $(wc -l <stderr) -ne 1 ]]; then
        fail "$description" "expected a one-line message, got $(wc -l <stderr) lines"
    elif [[ $output != - && -e $output ]]; then
        fail "$description" "left an output file $output"
    elif [[ -n $leftovers ]]; then
        fail "$description" "left temporary files: $leftovers"
    else
        pass "$description"
    fi
    rm -f stdout stderr
}

# expect_exit DESCRIPTION STATUS -- COMMAND...: for commands whose status is a result (diff).
expect_exit() {
    local description=$1 status=$2
    shift 3
    run_command "$@"
    if [[ $rc -eq $status ]]; then
        pass "$description"
    else
        fail "$description" "exit $rc, expected $status"
    fi
    rm -f stdout stderr
}

# expect_success DESCRIPTION OUTPUT_PATH -- COMMAND...: the command works and writes its file.
expect_success() {
    local description=$1 output=$2
    shift 3
    run_command "$@"
    if [[ $rc -ne 0 ]]; then
        fail "$description" "exit $rc, expected 0"
    elif [[ ! -s $output ]]; then
        fail "$description" "did not write $output"
    else
        pass "$description"
    fi
    rm -f stdout stderr
}

# A loader that finds no driver (a prefix for a command). VK_ICD_FILENAMES is the older name of
# VK_DRIVER_FILES; either one replaces the driver search, and VK_ADD_DRIVER_FILES would add one back.
WITHOUT_VULKAN_DRIVER=(env -u VK_ADD_DRIVER_FILES VK_DRIVER_FILES=/nonexistent.json
    VK_ICD_FILENAMES=/nonexistent.json)

# A PNG whose header claims WIDTHxHEIGHT, with a tiny IDAT: only the header check can reject it
# before anything tries to allocate the pixels.
write_png_header_only() {
    python3 - "$1" "$2" "$3" <<'EOF'
import struct, sys, zlib
path, width, height = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff)
ihdr = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)  # 8-bit RGB, no interlace
idat = zlib.compress(b"\0" * 301)  # a few rows' worth: the pixels must never be read
with open(path, "wb") as f:
    f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", idat) + chunk(b"IEND", b""))
EOF
}

# A real WIDTHxHEIGHT grey PNG (valid, every row present), compressed fast.
write_constant_png() {
    python3 - "$1" "$2" "$3" <<'EOF'
import struct, sys, zlib
path, width, height = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff)
compressor = zlib.compressobj(1)
row = b"\0" + b"\x80" * (width * 3)
idat = b"".join([compressor.compress(row) for _ in range(height)] + [compressor.flush()])
ihdr = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
with open(path, "wb") as f:
    f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", idat) + chunk(b"IEND", b""))
EOF
}

REF=(--backend reference --size 16x16)
RENDER=("$TEXFILTER" render --scene zoom --texture checker --filter nearest "${REF[@]}")
SAMPLE=("$TEXFILTER" sample --texture checker --filter bilinear --backend reference)
LOOKUPS_HEADER="u,v,dudx,dvdx,dudy,dvdy"

positive_control() {
    # If this fails, every error below might be failing for the wrong reason.
    expect_success "positive control: reference render" ok.png -- "${RENDER[@]}" -o ok.png
    printf '%s\n0.5,0.5,0.01,0,0,0.01\n' "$LOOKUPS_HEADER" >good.csv
    expect_success "positive control: reference sample" ok.csv -- "${SAMPLE[@]}" --lookups good.csv -o ok.csv
    if [[ ! -s ok.png ]]; then
        echo "the positive control failed; the remaining cases would prove nothing"
        exit 1
    fi
}

bad_texture_files() {
    local render=("$TEXFILTER" render --scene zoom --filter nearest "${REF[@]}")
    expect_error "missing texture file" missing.png out.png -- "${render[@]}" --texture missing.png -o out.png
    touch empty.png
    expect_error "empty texture file" empty.png out.png -- "${render[@]}" --texture empty.png -o out.png
    head -c 4096 /dev/urandom >corrupt.png
    expect_error "corrupt texture file (random bytes)" corrupt.png out.png -- \
        "${render[@]}" --texture corrupt.png -o out.png
    head -c 100 ok.png >truncated.png
    expect_error "truncated PNG texture (100 bytes)" truncated.png out.png -- \
        "${render[@]}" --texture truncated.png -o out.png
    # The last 20 bytes are IEND (12) and the end of the last IDAT, whatever size the PNG has.
    head -c $(($(wc -c <ok.png) - 20)) ok.png >truncated_idat.png
    expect_error "truncated PNG texture (inside IDAT)" truncated_idat.png out.png -- \
        "${render[@]}" --texture truncated_idat.png -o out.png
    mkdir texture_dir.png
    expect_error "directory as texture" texture_dir.png out.png -- "${render[@]}" --texture texture_dir.png -o out.png
    write_png_header_only huge.png 100000 100000
    expect_error "PNG claiming 100000x100000" 100000x100000 out.png -- "${render[@]}" --texture huge.png -o out.png
    write_png_header_only wide.png 16385 2
    expect_error "PNG one texel wider than 16384" 16385x2 out.png -- "${render[@]}" --texture wide.png -o out.png
    # OpenImageIO saturates a PFM side past int to 2147483647: the message quotes the header's own number.
    printf 'PF\n4294967297 1\n-1.0\n' >wide.pfm && head -c 12 /dev/zero >>wide.pfm
    expect_error "PFM claiming 4294967297x1" "wide.pfm: 4294967297x1 exceeds" out.png -- \
        "${render[@]}" --texture wide.pfm -o out.png
}

bad_flag_values() {
    local base=("$TEXFILTER" render --scene zoom --texture checker --filter nearest --backend reference)
    expect_error "--filter bogus" bogus out.png -- \
        "$TEXFILTER" render --scene zoom --texture checker --filter bogus "${REF[@]}" -o out.png
    expect_error "--scene bogus" bogus out.png -- \
        "$TEXFILTER" render --scene bogus --texture checker --filter nearest "${REF[@]}" -o out.png
    expect_error "--wrap bogus" bogus out.png -- "${RENDER[@]}" --wrap bogus -o out.png
    expect_error "--size 0x0" --size out.png -- "${base[@]}" --size 0x0 -o out.png
    expect_error "--size 255x256 (odd)" --size out.png -- "${base[@]}" --size 255x256 -o out.png
    expect_error "--size abc" --size out.png -- "${base[@]}" --size abc -o out.png
    expect_error "--aniso 0" --aniso out.png -- "${RENDER[@]}" --aniso 0 -o out.png
    expect_error "--aniso 17" --aniso out.png -- "${RENDER[@]}" --aniso 17 -o out.png
    expect_error "--texture-size 0" --texture-size out.png -- "${RENDER[@]}" --texture-size 0 -o out.png
    expect_error "--lod-bias nan" --lod-bias out.png -- "${RENDER[@]}" --lod-bias nan -o out.png
    expect_error "--lod-min 5 --lod-max 1" --lod-min out.png -- "${RENDER[@]}" --lod-min 5 --lod-max 1 -o out.png
    expect_error "--backend bogus" --backend out.png -- \
        "$TEXFILTER" render --scene zoom --texture checker --filter nearest --backend bogus -o out.png
    expect_error "unknown flag --frobnicate" --frobnicate out.png -- "${RENDER[@]}" --frobnicate -o out.png
    expect_error "flag given twice" --size out.png -- "${RENDER[@]}" --size 32x32 -o out.png
    expect_error "missing -o" "flag -o" - -- "${RENDER[@]}"
    expect_error "-o without a value (last argument)" "flag -o" - -- "${RENDER[@]}" -o
    # A flag whose value is missing must not swallow the next flag (it said "unexpected argument '1'").
    expect_error "-o followed by a flag" "flag -o needs a value (OUT), but the next argument is the flag --lod-bias" \
        - -- "${RENDER[@]}" -o --lod-bias 1
    expect_error "--size followed by -o" "flag --size needs a value (WxH), but the next argument is the flag -o" \
        out.png -- "${base[@]}" --size -o out.png
    expect_success "--lod-bias -1 (a negative number is a value, not a flag)" negative_bias.png -- \
        "$TEXFILTER" render --scene zoom --texture checker --filter trilinear "${REF[@]}" --lod-bias -1 -o negative_bias.png
    rm -f negative_bias.png
    # An empty --device is part of every device's name: it picked the first one without a word.
    expect_error "info --device ''" "bad value for --device: ''" - -- "$TEXFILTER" info --device ''
    expect_error "render --device= (reference)" "bad value for --device: ''" out.png -- "${RENDER[@]}" --device= -o out.png
    expect_error "sample --device '' (vulkan)" "bad value for --device: ''" out.csv -- \
        "$TEXFILTER" sample --texture checker --filter bilinear --lookups good.csv --device '' -o out.csv
    expect_error "unknown command" frobnicate - -- "$TEXFILTER" frobnicate
    expect_error "unsupported output extension .bmp" out.bmp out.bmp -- "${RENDER[@]}" -o out.bmp
    # The filter suite's options.
    expect_error "--band 1.5" --band out.png -- "${RENDER[@]}" --band 1.5 -o out.png
    expect_error "--probes 0" --probes out.png -- "${RENDER[@]}" --probes 0 -o out.png
    expect_error "--probes 17" --probes out.png -- "${RENDER[@]}" --probes 17 -o out.png
    expect_error "--aniso-shape bogus" --aniso-shape out.png -- "${RENDER[@]}" --aniso-shape bogus -o out.png
    expect_error "--taps bogus" --taps out.png -- "${RENDER[@]}" --taps bogus -o out.png
    expect_error "--alpha 0" --alpha out.png -- "${RENDER[@]}" --alpha 0 -o out.png
    expect_error "--alpha inf" --alpha out.png -- "${RENDER[@]}" --alpha inf -o out.png
    expect_error "--max-aniso 0.5" --max-aniso out.png -- "${RENDER[@]}" --max-aniso 0.5 -o out.png
    expect_error "--boxes 17" --boxes out.png -- "${RENDER[@]}" --boxes 17 -o out.png
    expect_error "--magnify bogus" "unknown reconstruction 'bogus' (expected one of: bilinear, bspline, catmull-rom)" \
        out.png -- "${RENDER[@]}" --magnify bogus -o out.png
    expect_error "--magnify on bilinear" "--magnify is not read by --filter bilinear (it applies to trilinear, aniso and ewa)" out.png -- \
        "$TEXFILTER" render --scene zoom --texture checker --filter bilinear --magnify bspline "${REF[@]}" -o out.png
    # --stochastic / --accumulate: the noise, the filters that take it, the frame count, the combinations.
    local stoch=("$TEXFILTER" render --scene zoom --texture checker --filter trilinear "${REF[@]}")
    expect_error "--stochastic bogus" "bad value for --stochastic: 'bogus' is not a noise (expected white or blue)" \
        out.png -- "${stoch[@]}" --stochastic bogus -o out.png
    expect_error "--stochastic on sat" "--stochastic is not read by --filter sat (it applies to bilinear, trilinear, aniso and ewa)" out.png -- \
        "$TEXFILTER" render --scene zoom --texture checker --filter sat --stochastic white "${REF[@]}" -o out.png
    expect_error "--stochastic with --magnify" "--stochastic reads level 0 bilinearly" out.png -- \
        "${stoch[@]}" --stochastic blue --magnify bspline -o out.png
    expect_error "--accumulate 0" "bad value for --accumulate: 0 (expected 1..4096 frames)" out.png -- \
        "${stoch[@]}" --stochastic white --accumulate 0 -o out.png
    expect_error "--accumulate 4097" "bad value for --accumulate: 4097" out.png -- \
        "${stoch[@]}" --stochastic white --accumulate 4097 -o out.png
    expect_error "--accumulate 99999999999" "bad value for --accumulate: 99999999999 (expected 1..4096" out.png -- \
        "${stoch[@]}" --stochastic white --accumulate 99999999999 -o out.png
    expect_error "--accumulate 2.5" "bad value for --accumulate: '2.5'" out.png -- \
        "${stoch[@]}" --stochastic white --accumulate 2.5 -o out.png
    expect_error "--accumulate without --stochastic" "--accumulate 8 needs --stochastic white|blue" out.png -- \
        "${stoch[@]}" --accumulate 8 -o out.png
    expect_error "--stochastic ewa --taps hardware on the reference" "has no CPU reference" out.png -- \
        "$TEXFILTER" render --scene zoom --texture checker --filter ewa --taps hardware --stochastic white "${REF[@]}" -o out.png
    expect_error "--stochastic nearest on an environment scene" "--stochastic is not read by --filter nearest (it applies to bilinear, trilinear, aniso and ewa)" \
        out.png -- "$TEXFILTER" render --scene skybox --texture checker --filter nearest --stochastic white "${REF[@]}" -o out.png
    # Quad derivatives: bad values, and combinations the mesh scene cannot do.
    expect_error "--stage bogus" --stage out.png -- "${RENDER[@]}" --stage bogus -o out.png
    expect_error "--derivatives bogus" --derivatives out.png -- "${RENDER[@]}" --derivatives bogus -o out.png
    expect_error "mesh in the compute stage" "mesh scene is rasterized" out.png -- \
        "$TEXFILTER" render --scene mesh --texture checker --filter nearest "${REF[@]}" --stage compute -o out.png
    expect_error "mesh with ray differentials" "ray differentials need a ray-cast scene" out.png -- \
        "$TEXFILTER" render --scene mesh --texture checker --filter nearest "${REF[@]}" --derivatives ray -o out.png
    # The camera (X,Y,Z,YAW,PITCH) and the camera path's frame.
    expect_error "--camera with 4 numbers" "--camera: expected 5 comma-separated numbers" out.png -- \
        "${RENDER[@]}" --camera 0,0,0,0 -o out.png
    expect_error "--camera with a word" "--camera: camera YAW 'left' is not a number" out.png -- \
        "${RENDER[@]}" --camera 0,0,0,left,0 -o out.png
    expect_error "--camera nan" "--camera: camera X 'nan' is not a number" out.png -- "${RENDER[@]}" --camera nan,0,0,0,0 -o out.png
    expect_error "--camera pitch 90" "--camera: camera PITCH = 90 degrees" out.png -- \
        "${RENDER[@]}" --camera 0,0,0,0,90 -o out.png
    expect_error "--camera 1e9 away" "--camera: camera Z = 1000000000 is too large" out.png -- \
        "${RENDER[@]}" --camera 0,0,1e9,0,0 -o out.png
    expect_error "--frame -1" --frame out.png -- "${RENDER[@]}" --frame -1 -o out.png
    expect_error "--frame 1000001" --frame out.png -- "${RENDER[@]}" --frame 1000001 -o out.png
    expect_error "--frame 2.5" --frame out.png -- "${RENDER[@]}" --frame 2.5 -o out.png
}

bad_outputs() {
    # A file name the file system cannot hold is refused before the render (it failed at the final rename).
    local long_name
    long_name=$(printf 'n%.0s' {1..300}).png
    expect_error "render -o with a 304-byte file name" "longer than" "$long_name" -- "${RENDER[@]}" -o "$long_name"
    expect_error "build --out ''" "build --out: the directory path is empty" - -- \
        "$TEXFILTER" build --texture checker --texture-size 16 --build cpu --out ''
    expect_error "bench --out ''" "bench --out: the directory path is empty" - -- "$TEXFILTER" bench --quick --out ''
    expect_error "render -o into a missing directory" /nonexistent/dir/out.png /nonexistent/dir/out.png -- \
        "${RENDER[@]}" -o /nonexistent/dir/out.png
    mkdir output_dir.png
    # The rename onto a directory fails after the image was written: the temporary must go.
    expect_error "render -o onto a directory" output_dir.png - -- "${RENDER[@]}" -o output_dir.png
}

bad_lookups() {
    expect_error "sample: missing lookups file" missing.csv out.csv -- \
        "${SAMPLE[@]}" --lookups missing.csv -o out.csv
    touch empty.csv
    expect_error "sample: empty lookups file" empty.csv out.csv -- "${SAMPLE[@]}" --lookups empty.csv -o out.csv
    printf 'x,y\n0.5,0.5\n' >bad_header.csv
    expect_error "sample: wrong header" bad_header.csv:1 out.csv -- \
        "${SAMPLE[@]}" --lookups bad_header.csv -o out.csv
    printf '%s\n0.5,0.5,0,0,0\n' "$LOOKUPS_HEADER" >five_values.csv
    expect_error "sample: a row with 5 values" five_values.csv:2 out.csv -- \
        "${SAMPLE[@]}" --lookups five_values.csv -o out.csv
    printf '%s\n0.5,abc,0,0,0,0\n' "$LOOKUPS_HEADER" >not_a_number.csv
    expect_error "sample: a non-number" "'abc'" out.csv -- "${SAMPLE[@]}" --lookups not_a_number.csv -o out.csv
    mkdir lookups_dir.csv
    expect_error "sample: a directory as lookups file" "is a directory" out.csv -- \
        "${SAMPLE[@]}" --lookups lookups_dir.csv -o out.csv
    # Files that exist but are no regular file (it said "no such lookups file").
    expect_error "sample: /dev/zero as lookups file" "/dev/zero: is a character device, not a regular file" out.csv -- \
        "${SAMPLE[@]}" --lookups /dev/zero -o out.csv
    mkfifo lookups_fifo.csv
    expect_error "sample: a FIFO as lookups file" "lookups_fifo.csv: is a pipe (FIFO), not a regular file" out.csv -- \
        "${SAMPLE[@]}" --lookups lookups_fifo.csv -o out.csv
    rm -f lookups_fifo.csv
    expect_error "sample: --stats with the reference backend" --stats out.csv -- \
        "${SAMPLE[@]}" --lookups good.csv --stats -o out.csv
    expect_error "sample: -o in a missing directory" /nonexistent/dir/out.csv /nonexistent/dir/out.csv -- \
        "${SAMPLE[@]}" --lookups good.csv -o /nonexistent/dir/out.csv
}

# sample --resource and its flags: bad names list the valid ones, flags the kind does not take are named.
sample_resources() {
    local s=("${SAMPLE[@]}" --lookups good.csv)
    expect_success "sample: --resource array --layers 3 --layer 2 (reference)" ok_array.csv -- \
        "${s[@]}" --resource array --layers 3 --layer 2 -o ok_array.csv
    expect_success "sample: --resource shadow --compare greater --dref 0.25 (reference)" ok_shadow.csv -- \
        "${s[@]}" --resource shadow --compare greater --dref 0.25 -o ok_shadow.csv
    expect_error "sample: --resource bogus" "unknown resource 'bogus' (expected one of: combined, separate" out.csv -- \
        "${s[@]}" --resource bogus -o out.csv
    expect_error "sample: --layers with combined" "--layers is for --resource array, separate-array or bindless" \
        out.csv -- "${s[@]}" --layers 4 -o out.csv
    expect_error "sample: --layer with shadow" "--layer is for --resource array" out.csv -- \
        "${s[@]}" --resource shadow --layer 1 -o out.csv
    expect_error "sample: --layers 0" "bad value for --layers: '0'" out.csv -- \
        "${s[@]}" --resource array --layers 0 -o out.csv
    expect_error "sample: --layers 65" "bad value for --layers: '65'" out.csv -- \
        "${s[@]}" --resource separate-array --layers 65 -o out.csv
    expect_error "sample: bindless --layer past the textures" "bad value for --layer: '4'" out.csv -- \
        "${s[@]}" --resource bindless --layers 4 --layer 4 -o out.csv
    expect_error "sample: --layer 1.5" "bad value for --layer: '1.5'" out.csv -- \
        "${s[@]}" --resource array --layer 1.5 -o out.csv
    expect_error "sample: --compare with array" "--compare is for --resource shadow, not --resource array" out.csv -- \
        "${s[@]}" --resource array --compare less -o out.csv
    expect_error "sample: --dref with separate" "--dref is for --resource shadow" out.csv -- \
        "${s[@]}" --resource separate --dref 0.5 -o out.csv
    expect_error "sample: --compare bogus" "unknown compare op 'bogus' (expected one of: never, less" out.csv -- \
        "${s[@]}" --resource shadow --compare bogus -o out.csv
    expect_error "sample: --dref nan" "bad value for --dref: 'nan'" out.csv -- \
        "${s[@]}" --resource shadow --dref nan -o out.csv
    expect_error "sample: --format with a resource kind" "--format r16ui is for --resource combined" out.csv -- \
        "${s[@]}" --resource separate --format r16ui -o out.csv
    expect_error "sample: sat on an array" "--resource array cannot run --filter sat" out.csv -- \
        "$TEXFILTER" sample --texture checker --filter sat --backend reference --lookups good.csv \
        --resource array -o out.csv
    expect_error "sample: hw-aniso on shadow" "--resource shadow cannot run --filter hw-aniso" out.csv -- \
        "$TEXFILTER" sample --texture checker --filter hw-aniso --backend reference --lookups good.csv \
        --resource shadow -o out.csv
    # sample --stochastic: the filters and resource kinds it takes, and a good one.
    expect_success "sample: --stochastic white --accumulate 4 (reference)" ok_stochastic.csv -- \
        "$TEXFILTER" sample --texture checker --filter trilinear --stochastic white --accumulate 4 \
        --backend reference --lookups good.csv -o ok_stochastic.csv
    expect_error "sample: --stochastic on sat" "--stochastic is not read by --filter sat (it applies to bilinear, trilinear, aniso and ewa)" out.csv -- \
        "$TEXFILTER" sample --texture checker --filter sat --stochastic white --backend reference \
        --lookups good.csv -o out.csv
    expect_success "sample: --stochastic on an array (reference)" ok_stochastic_array.csv -- \
        "$TEXFILTER" sample --texture checker --filter trilinear --stochastic blue --resource array \
        --backend reference --lookups good.csv -o ok_stochastic_array.csv
    # The texel-source kinds (atlas, virtual): manual taps only; the hardware sampler only on the atlas.
    local t=("$TEXFILTER" sample --texture checker --backend reference --lookups good.csv)
    expect_success "sample: --resource atlas, hw-trilinear (reference)" ok_atlas.csv -- \
        "${t[@]}" --filter hw-trilinear --resource atlas -o ok_atlas.csv
    expect_success "sample: --resource virtual, ewa (reference)" ok_virtual.csv -- \
        "${t[@]}" --filter ewa --resource virtual -o ok_virtual.csv
    expect_error "sample: sat on an atlas" "--resource atlas cannot run --filter sat: the summed-area table" out.csv -- \
        "${t[@]}" --filter sat --resource atlas -o out.csv
    expect_error "sample: --taps hardware on a virtual texture" "--resource virtual cannot run --taps hardware" \
        out.csv -- "${t[@]}" --filter aniso --taps hardware --resource virtual -o out.csv
    expect_error "sample: hw-bilinear on a virtual texture" "--resource virtual cannot run --filter hw-bilinear" \
        out.csv -- "${t[@]}" --filter hw-bilinear --resource virtual -o out.csv
    expect_error "sample: an atlas past 16384 a side" "a 16384x16384 texture needs an atlas of 32768x32768 texels" \
        out.csv -- "${t[@]}" --filter trilinear --resource atlas --texture-size 16384 -o out.csv
    expect_error "sample: the atlas counts in --memory-budget" "1 lookups and the atlas" out.csv -- \
        "$TEXFILTER" sample --texture checker --texture-size 512 --backend reference --lookups good.csv \
        --filter trilinear --resource atlas --memory-budget 8M -o out.csv
}

# sample --spirv FILE (a lookup shader from another compiler): refused before any work, one message naming the
# file and what is wrong with it; a module with the sample pass's interface runs (glslangValidator makes both).
sample_spirv() {
    local s=("$TEXFILTER" sample --texture checker --filter nearest --lookups good.csv)
    expect_error "sample --spirv: missing file" "missing.spv: cannot open the SPIR-V file" out.csv -- \
        "${s[@]}" --spirv missing.spv -o out.csv
    # refused DESCRIPTION FILE CONTENT EXPECTED: FILE written with printf CONTENT, then refused saying EXPECTED.
    refused() {
        printf "$3" >"$2"
        expect_error "sample --spirv: $1" "$4" out.csv -- "${s[@]}" --spirv "$2" -o out.csv
    }
    refused "empty file" empty.spv '' "empty.spv: empty (expected a SPIR-V module)"
    refused "not whole words" odd.spv 'not spirv' "odd.spv: 9 bytes, not a whole number of 32-bit words"
    refused "no magic number" text.spv 'not a module' "text.spv: not a SPIR-V module (no SPIR-V magic number)"
    refused "the other byte order" swapped.spv '\x07\x23\x02\x03\x00\x05\x01\x00' \
        "swapped.spv: not a SPIR-V module (the other byte order"
    refused "a header and nothing else" header_only.spv \
        '\x03\x02\x23\x07\x00\x05\x01\x00\x00\x00\x00\x00\x05\x00\x00\x00\x00\x00\x00\x00' \
        "header_only.spv: not valid SPIR-V for Vulkan 1.2 ("
    expect_error "sample --spirv: a directory" "is a directory" out.csv -- "${s[@]}" --spirv . -o out.csv
    expect_error "sample --spirv with the reference backend" "--spirv is the device's lookup shader: it needs --backend vulkan" \
        out.csv -- "${s[@]}" --backend reference --spirv empty.spv -o out.csv
    expect_error "sample --spirv with --resource bindless" \
        "--spirv replaces the shader of --resource combined, separate or separate-array, not bindless" out.csv -- \
        "${s[@]}" --resource bindless --spirv empty.spv -o out.csv
    expect_error "sample --spirv with an integer format" "--format r16ui is read through the integer build" out.csv -- \
        "${s[@]}" --format r16ui --spirv empty.spv -o out.csv
    # Modules that are valid SPIR-V but not a sample shader.
    local interface='layout(set = 0, binding = 1, std430) readonly buffer L { float lookups[]; };
layout(set = 0, binding = 2, std430) writeonly buffer R { vec4 results[]; };
layout(set = 0, binding = 3, std430) writeonly buffer S { uvec2 stats[]; };
layout(push_constant, std430) uniform P { int wrapMode; float lodBias, lodMin, lodMax; uint count; } pc;'
    printf '#version 450\nlayout(location = 0) out vec4 c;\nvoid main() { c = vec4(1.0); }\n' >frag.frag
    printf '#version 450\nlayout(local_size_x = 64) in;\n%s\nlayout(set = 0, binding = 7) uniform sampler2D extra;\nvoid main() { results[0] = texelFetch(extra, ivec2(0), 0) + lookups[0]; }\n' \
        "$interface" >binding7.comp
    printf '#version 450\n#extension GL_EXT_samplerless_texture_functions : require\nlayout(local_size_x = 64) in;\n%s\nlayout(set = 0, binding = 0) uniform texture2D t;\nvoid main() { results[0] = vec4(textureSize(t, 0), 0, 0) + lookups[0]; }\n' \
        "$interface" >sampled.comp
    printf '#version 450\nlayout(local_size_x = 64) in;\n%s\nlayout(set = 0, binding = 0) uniform sampler2D t;\nvoid main() { results[0] = vec4(textureSize(t, 0), 0, 0) + lookups[0]; }\n' \
        "$interface" >combined.comp
    printf '#version 450\nlayout(local_size_x = 64) in;\n%s\nvoid main() { uint i = gl_GlobalInvocationID.x; if (i < pc.count) { results[i] = vec4(lookups[6u * i]); stats[i] = uvec2(0u); } }\n' \
        "$interface" >good.comp
    for shader in frag.frag binding7.comp sampled.comp combined.comp good.comp; do
        glslangValidator -V --target-env vulkan1.2 "$shader" -o "${shader%.*}.spv" >/dev/null ||
            fail "sample --spirv: glslangValidator $shader" "the test's own shader does not compile"
    done
    expect_error "sample --spirv: a fragment shader" "frag.spv: has no GLCompute entry point named 'main'" out.csv -- \
        "${s[@]}" --spirv frag.spv -o out.csv
    expect_error "sample --spirv: a binding the pass lacks" \
        "binding7.spv: a resource at binding 7, which the sample pass of --resource combined does not bind" out.csv -- \
        "${s[@]}" --spirv binding7.spv -o out.csv
    expect_error "sample --spirv: a sampled image where the pass binds a combined one" \
        "sampled.spv: binding 0 is a sampled image (2D); the sample pass of --resource combined binds a combined image sampler (2D) there" \
        out.csv -- "${s[@]}" --spirv sampled.spv -o out.csv
    # A module of one kind given to another's pass: named, with the variant to compile.
    expect_error "sample --spirv: a combined module for --resource separate" \
        "combined.spv: binding 0 is a combined image sampler (2D); the sample pass of --resource separate binds a sampled image (2D) there (--resource separate runs shaders/harness/sample.comp.glsl compiled with -DHARNESS_RESOURCE=1)" \
        out.csv -- "${s[@]}" --resource separate --spirv combined.spv -o out.csv
    expect_error "sample --spirv: a separate module for --resource separate-array" \
        "sampled.spv: binding 0 is a sampled image (2D); the sample pass of --resource separate-array binds a sampled image (2D array) there" \
        out.csv -- "${s[@]}" --resource separate-array --spirv sampled.spv -o out.csv
    if "$TEXFILTER" info >/dev/null 2>&1; then
        expect_success "sample --spirv: a module with the pass's interface runs" ok_spirv.csv -- \
            "${s[@]}" --spirv good.spv -o ok_spirv.csv
        expect_success "sample --spirv: a module with --resource separate's interface runs" ok_spirv_separate.csv -- \
            "${s[@]}" --resource separate --spirv sampled.spv -o ok_spirv_separate.csv
    else
        skip "sample --spirv: a module with the pass's interface runs" "no Vulkan device here"
        skip "sample --spirv: a module with --resource separate's interface runs" "no Vulkan device here"
    fi
}

diff_contract() {
    local render=("$TEXFILTER" render --scene zoom --filter nearest --backend reference)
    "${render[@]}" --texture checker --size 16x16 -o a16.png >/dev/null
    "${render[@]}" --texture checker --size 16x16 -o b16.png >/dev/null
    "${render[@]}" --texture checker --size 32x32 -o a32.png >/dev/null
    "${render[@]}" --texture noise --size 16x16 -o noise16.png >/dev/null
    expect_error "diff: missing file" missing.png - -- "$TEXFILTER" diff a16.png missing.png
    expect_error "diff: size mismatch" 32x32 diff.png -- "$TEXFILTER" diff a16.png a32.png -o diff.png
    expect_exit "diff: identical images exit 0" 0 -- "$TEXFILTER" diff a16.png b16.png
    expect_exit "diff: checker vs noise exits 1" 1 -- "$TEXFILTER" diff a16.png noise16.png
}

ground_truth_and_bench_errors() {
    local truth=("$TEXFILTER" render --scene zoom --texture checker --filter ground-truth "${REF[@]}")
    expect_error "render --spp 10 (not a square)" "square" out.png -- "${truth[@]}" --spp 10 -o out.png
    expect_error "render --spp 0" --spp out.png -- "${truth[@]}" --spp 0 -o out.png
    expect_error "render --spp 8192 (over 4096)" --spp out.png -- "${truth[@]}" --spp 8192 -o out.png
    expect_error "render --pixel-filter bogus" bogus out.png -- "${truth[@]}" --pixel-filter bogus -o out.png
    # --truth analytic|texels: only ground-truth takes it, and only checker, zoneplate and grid have a function.
    expect_error "render --truth bogus" "unknown truth 'bogus'" out.png -- "${truth[@]}" --truth bogus -o out.png
    expect_error "render --truth analytic --texture noise" "texture 'noise' has no analytic definition" out.png -- \
        "$TEXFILTER" render --scene zoom --texture noise --filter ground-truth --truth analytic "${REF[@]}" -o out.png
    expect_error "render --truth without --filter ground-truth" "--truth is not read by --filter trilinear (it applies to ground-truth)" out.png -- \
        "$TEXFILTER" render --scene zoom --texture checker --filter trilinear --truth analytic "${REF[@]}" -o out.png
    expect_error "render --truth analytic --scene skybox" "no analytic definition" out.png -- \
        "$TEXFILTER" render --scene skybox --texture checker --texture-size 16 --filter ground-truth --truth analytic \
        "${REF[@]}" -o out.png
    expect_error "view --truth analytic" "not available in the viewer" - -- \
        "$TEXFILTER" view --texture checker --filter ground-truth --truth analytic
    expect_error "view --stochastic white" "--stochastic is not available in the viewer" - -- \
        "$TEXFILTER" view --texture checker --filter trilinear --stochastic white
    expect_error "sample --filter ground-truth" ground-truth out.csv -- \
        "$TEXFILTER" sample --texture checker --filter ground-truth --lookups good.csv --backend reference -o out.csv
    local bench=("$TEXFILTER" bench --quick --scenes zoom)
    expect_error "bench --filters bogus" bogus bench-out -- "${bench[@]}" --filters bogus --out bench-out
    expect_error "bench --scenes bogus" bogus bench-out -- "$TEXFILTER" bench --quick --scenes bogus --out bench-out
    expect_error "bench --spp 10" --spp bench-out -- "${bench[@]}" --spp 10 --out bench-out
    expect_error "bench --frames 0" --frames bench-out -- "${bench[@]}" --frames 0 --out bench-out
    expect_error "bench --flicker-frames 1" --flicker-frames bench-out -- "${bench[@]}" --flicker-frames 1 --out bench-out
    expect_error "bench --lookups-per-pixel 0" --lookups-per-pixel bench-out -- "${bench[@]}" --lookups-per-pixel 0 --out bench-out
    expect_error "bench --lookups-per-pixel 257" --lookups-per-pixel bench-out -- \
        "${bench[@]}" --lookups-per-pixel 257 --out bench-out
    expect_error "bench --mip-build --lookups-per-pixel" --lookups-per-pixel - -- \
        "$TEXFILTER" bench --mip-build --lookups-per-pixel 4
    expect_error "bench --timer bogus" bogus bench-out -- "${bench[@]}" --timer bogus --out bench-out
    expect_error "bench without --out" --out - -- "${bench[@]}"
    # Empty lists ran the default or nothing (exit 0, "0 scenes"), as golden --case '' is refused.
    expect_error "bench --filters ''" "bad value for --filters: ''" bench-out -- "${bench[@]}" --filters '' --out bench-out
    expect_error "bench --scenes ," "bad value for --scenes: ','" bench-out -- \
        "$TEXFILTER" bench --quick --scenes , --out bench-out
    expect_error "bench --scenes zoom," "bad value for --scenes: 'zoom,'" bench-out -- \
        "$TEXFILTER" bench --quick --scenes zoom, --filters nearest --out bench-out
    expect_error "bench --gpu-build --sizes ''" "bad value for --sizes: ''" - -- \
        "$TEXFILTER" bench --gpu-build --sizes '' --repeat 1 --dynamic-size 0
    # --mip-build and --gpu-build are runs of their own: one at a time, and only their flags.
    expect_error "bench --mip-build --gpu-build" "--mip-build, --gpu-build and --footprints are different runs" - -- \
        "$TEXFILTER" bench --mip-build --gpu-build --texture-size 16 --repeat 1
    expect_error "bench --mip-build --out" "bench --mip-build does not take --out" bench-out -- \
        "$TEXFILTER" bench --mip-build --texture-size 16 --repeat 1 --out bench-out
    expect_error "bench --gpu-build --texture-size" "bench --gpu-build does not take --texture-size" - -- \
        "$TEXFILTER" bench --gpu-build --sizes 16 --texture-size 16 --repeat 1 --dynamic-size 0
    expect_error "bench --repeat in the results run" "--repeat is for bench --mip-build and --gpu-build" bench-out -- \
        "${bench[@]}" --filters nearest --repeat 3 --out bench-out
    expect_error "bench --out in a missing directory" "parent directory" missing/bench-out -- \
        "${bench[@]}" --out missing/bench-out
    # An earlier run's results are never overwritten or touched.
    mkdir -p earlier && echo keep >earlier/bench.json
    expect_error "bench --out a non-empty directory" "not an empty directory" - -- "${bench[@]}" --out earlier
    if [[ $(cat earlier/bench.json) != keep || $(ls earlier | wc -l) -ne 1 ]]; then
        fail "bench --out a non-empty directory" "the earlier results were changed"
    fi
    rm -rf earlier
}

# bench --footprints: each flag checked before any work (no device opened, nothing at --out).
footprint_bench_errors() {
    local fp=("$TEXFILTER" bench --footprints --quick --lookups 16)
    expect_error "bench --footprints --textures bogus" "unknown texture 'bogus'" fp-out -- \
        "${fp[@]}" --textures checker,bogus --out fp-out
    expect_error "bench --footprints --textures ''" "bad value for --textures: ''" fp-out -- \
        "${fp[@]}" --textures '' --out fp-out
    expect_error "bench --footprints --textures checker," "bad value for --textures: 'checker,'" fp-out -- \
        "${fp[@]}" --textures checker, --out fp-out
    expect_error "bench --footprints --filters bogus" "unknown label 'bogus'" fp-out -- \
        "${fp[@]}" --filters ewa,bogus --out fp-out
    expect_error "bench --footprints --filters ewa,ewa" "'ewa' is listed twice" fp-out -- \
        "${fp[@]}" --filters ewa,ewa --out fp-out
    expect_error "bench --footprints --lookups 0" --lookups fp-out -- \
        "$TEXFILTER" bench --footprints --quick --lookups 0 --out fp-out
    expect_error "bench --footprints --texture-size 0" --texture-size fp-out -- \
        "${fp[@]}" --texture-size 0 --out fp-out
    echo P3 >photo.ppm && printf '2 2\n255\n0 0 0 0 0 0 0 0 0 0 0 0\n' >>photo.ppm
    expect_error "bench --footprints --texture-size with files only" "--texture-size is not read by --textures" fp-out -- \
        "${fp[@]}" --textures photo.ppm --texture-size 64 --out fp-out
    expect_error "bench --footprints --format bogus" "unknown texture format 'bogus'" fp-out -- \
        "${fp[@]}" --format bogus --out fp-out
    expect_error "bench --footprints --format r32ui with hw-trilinear" "--format r32ui holds integer data" fp-out -- \
        "${fp[@]}" --format r32ui --filters ewa,hw-trilinear --out fp-out
    expect_error "bench --footprints --texture" "bench --footprints does not take --texture" fp-out -- \
        "${fp[@]}" --texture checker --out fp-out
    expect_error "bench --footprints --scenes" "bench --footprints does not take --scenes" fp-out -- \
        "${fp[@]}" --scenes plane --out fp-out
    expect_error "bench --footprints --mip-build" "are different runs" fp-out -- \
        "${fp[@]}" --mip-build --out fp-out
    expect_error "bench --footprints without --out" --out - -- "${fp[@]}"
    expect_error "bench --textures in the results run" "--textures is for bench --footprints" bench-out -- \
        "$TEXFILTER" bench --quick --scenes zoom --textures checker --out bench-out
    expect_error "bench --lookups in the results run" "--lookups is for bench --footprints" bench-out -- \
        "$TEXFILTER" bench --quick --scenes zoom --lookups 9 --out bench-out
    mkdir -p earlier && echo keep >earlier/bench.json
    expect_error "bench --footprints --out a non-empty directory" "not an empty directory" - -- \
        "${fp[@]}" --out earlier
    if [[ $(cat earlier/bench.json) != keep || $(ls earlier | wc -l) -ne 1 ]]; then
        fail "bench --footprints --out a non-empty directory" "the earlier results were changed"
    fi
    rm -rf earlier photo.ppm
}

golden_errors() {
    expect_error "golden --case nonexistent" nonexistent golden-out -- \
        "$TEXFILTER" golden --case nonexistent --out golden-out
    # A texfilter that is not the build tree's (installed or copied) has no checkout to default to: golden
    # --update from it must never rewrite the source tree it was built from.
    mkdir -p copied && cp "$TEXFILTER" copied/texfilter
    expect_error "golden from a copied binary without --golden-dir" "--golden-dir" golden-out -- \
        copied/texfilter golden --update --case "$(awk '!/^#/ && NF { print $1; exit }' "$GOLDEN_DIR/manifest.txt")" \
        --out golden-out
    rm -rf copied
    # A case name becomes --golden-dir/NAME.png: one that is a path (or hidden) is refused as the manifest is
    # read, naming file, line and name, before anything is rendered or written.
    mkdir -p named-golden
    local name
    for name in ../evil "$WORK/evil" sub/evil .evil; do
        printf '%s zoom checker nearest size=16x16 texture-size=16\n' "$name" >named-golden/manifest.txt
        expect_error "golden --update, case name '${name/#"$WORK"/\$WORK}'" "named-golden/manifest.txt:1: case name '$name'" \
            evil.png -- "$TEXFILTER" golden --golden-dir named-golden --update
    done
    [[ -z $(find named-golden -name '*.png') ]] || fail "golden --update with a bad case name" "wrote $(find named-golden -name '*.png')"
    # A read-only golden is refused as render -o refuses a read-only output: kept, and found before any render.
    mkdir -p readonly-golden
    printf '%s zoom checker nearest size=16x16 texture-size=16\n' a b >readonly-golden/manifest.txt
    echo keep >readonly-golden/b.png && chmod 444 readonly-golden/b.png
    expect_error "golden --update a read-only golden" "readonly-golden/b.png: is read-only" readonly-golden/a.png -- \
        "$TEXFILTER" golden --golden-dir readonly-golden --update
    if ! cmp -s readonly-golden/b.png <(echo keep) || [[ $(stat -c %a readonly-golden/b.png) != 444 ]]; then
        fail "golden --update a read-only golden" "the read-only golden was replaced"
    fi
    rm -rf named-golden readonly-golden evil.png
}

vulkan_errors() {
    local no_driver=("${WITHOUT_VULKAN_DRIVER[@]}" "$TEXFILTER")
    EXPECT_ONE_LINE=1 expect_error "render without a Vulkan driver" Vulkan out.png -- \
        "${no_driver[@]}" render --scene zoom --texture checker --filter nearest --size 16x16 --backend vulkan \
        -o out.png
    EXPECT_ONE_LINE=1 expect_error "info without a Vulkan driver" Vulkan - -- "${no_driver[@]}" info
    EXPECT_ONE_LINE=1 expect_error "sample without a Vulkan driver" Vulkan out.csv -- \
        "${no_driver[@]}" sample --texture checker --filter bilinear --lookups good.csv --backend vulkan -o out.csv
    EXPECT_ONE_LINE=1 expect_error "golden without a Vulkan driver" Vulkan golden-out -- \
        "${no_driver[@]}" golden --out golden-out
    EXPECT_ONE_LINE=1 expect_error "bench without a Vulkan driver" Vulkan bench-out -- \
        "${no_driver[@]}" bench --quick --out bench-out

    # --device 99 can only be told apart from "no driver" where a device exists.
    if ! "$TEXFILTER" info >/dev/null 2>&1; then
        skip "--device 99" "no usable Vulkan device here"
        return
    fi
    expect_error "--device 99 (render)" --device out.png -- "$TEXFILTER" render --scene zoom --texture checker \
        --filter nearest --size 16x16 --backend vulkan --device 99 -o out.png
    expect_error "--device 99 (info)" --device - -- "$TEXFILTER" info --device 99
}

# `golden --out` never deletes what it did not make.
golden_output_directory() {
    local case_name
    # awk alone: under pipefail, grep | awk '...; exit' can kill grep with SIGPIPE and the script with it.
    case_name=$(awk '!/^#/ && NF { print $1; exit }' "$GOLDEN_DIR/manifest.txt")
    # A directory of someone else's files, shaped like the repository's golden/: refused, untouched.
    mkdir -p theirs/golden theirs/actual && echo keep >theirs/golden/a.png && echo keep >theirs/actual/b.png
    echo keep >theirs/notes.txt
    expect_error "golden --out a directory it did not make" "was not made by texfilter golden" - -- \
        "$TEXFILTER" golden --case "$case_name" --out theirs
    if [[ $(find theirs -type f | wc -l) -ne 3 || $(cat theirs/golden/a.png theirs/actual/b.png theirs/notes.txt) != \
        $'keep\nkeep\nkeep' ]]; then
        fail "golden --out a directory it did not make" "files in it were changed or removed"
    fi
    # A golden image that is missing, truncated or of another size than its case is found before --out is made.
    mkdir -p bad-golden
    printf 'tiny zoom checker nearest size=16x16 texture-size=16\n' >bad-golden/manifest.txt
    expect_error "golden with a missing golden image" "bad-golden/tiny.png" golden-out -- \
        "$TEXFILTER" golden --golden-dir bad-golden --out golden-out
    head -c 100 ok.png >bad-golden/tiny.png
    expect_error "golden with a truncated golden image" "bad-golden/tiny.png" golden-out -- \
        "$TEXFILTER" golden --golden-dir bad-golden --out golden-out
    write_constant_png bad-golden/tiny.png 8 8
    expect_error "golden with a golden image of another size" "bad-golden/tiny.png: is 8x8" golden-out -- \
        "$TEXFILTER" golden --golden-dir bad-golden --out golden-out
    rm -rf bad-golden
    # A marked directory is reused: the files its marker lists go, a file someone added stays.
    if ! "$TEXFILTER" info >/dev/null 2>&1; then
        skip "golden --out its own marked directory" "no usable Vulkan device here"
        rm -rf theirs
        return
    fi
    mkdir -p ours/actual && echo mine >ours/actual/user.png
    printf '%s\nactual/old.png\nreport.html\n' "$GOLDEN_MARKER_HEADING" >ours/.texfilter-golden
    echo old >ours/actual/old.png && echo old >ours/report.html
    run_command "$TEXFILTER" golden --case "$case_name" --out ours
    if [[ $rc -ne 0 && $rc -ne 1 ]]; then
        fail "golden --out its own marked directory" "exit $rc"
    elif [[ -e ours/actual/old.png || $(cat ours/actual/user.png) != mine || $(cat ours/report.html) == old ]]; then
        fail "golden --out its own marked directory" "listed files kept, or an unlisted file touched"
    else
        pass "golden --out its own marked directory"
    fi
    # A marker that lists a path outside its directory is refused before anything is removed.
    echo keep >outside.txt
    mkdir -p tampered && printf '%s\n../outside.txt\n' "$GOLDEN_MARKER_HEADING" >tampered/.texfilter-golden
    expect_error "golden --out with a tampered marker" "not a file below its directory" - -- \
        "$TEXFILTER" golden --case "$case_name" --out tampered
    [[ -e outside.txt ]] || fail "golden --out with a tampered marker" "removed ../outside.txt"
    # Nor through a symbolic link: a marked directory holding one is refused, the link and its target kept.
    mkdir -p elsewhere linked && echo keep >elsewhere/x.png && ln -s ../elsewhere linked/actual
    printf '%s\nactual/x.png\n' "$GOLDEN_MARKER_HEADING" >linked/.texfilter-golden
    expect_error "golden --out with a marker listing a file through a symlink" "linked/actual is a symbolic link" - -- \
        "$TEXFILTER" golden --case "$case_name" --out linked
    if [[ $(cat elsewhere/x.png 2>/dev/null) != keep || ! -L linked/actual ]]; then
        fail "golden --out with a marker listing a file through a symlink" "removed elsewhere/x.png or the link"
    fi
    # A link the marker does not list is refused too: a failing case would write its images through it.
    mkdir -p unlisted && printf '%s\n' "$GOLDEN_MARKER_HEADING" >unlisted/.texfilter-golden
    ln -s ../elsewhere unlisted/actual
    expect_error "golden --out holding an unlisted symlink" "unlisted/actual is a symbolic link" - -- \
        "$TEXFILTER" golden --case "$case_name" --out unlisted
    if [[ $(cat elsewhere/x.png 2>/dev/null) != keep || ! -L unlisted/actual ]]; then
        fail "golden --out holding an unlisted symlink" "touched elsewhere/x.png or the link"
    fi
    rm -rf theirs ours tampered outside.txt elsewhere linked unlisted
}

# An output is never one of the inputs; read-only files and links behave as documented.
outputs_and_inputs() {
    cp ok.png texture.png
    local texture_sum
    texture_sum=$(cksum <texture.png)
    local render=("$TEXFILTER" render --scene zoom --filter nearest "${REF[@]}" --texture texture.png)
    expect_error "render -o the texture itself" "is the input" - -- "${render[@]}" -o texture.png
    ln -s texture.png link_to_texture.png
    expect_error "render -o a symlink to the texture" "is the input" - -- "${render[@]}" -o link_to_texture.png
    ln texture.png hardlink_to_texture.png
    expect_error "render -o a hard link to the texture" "is the input" - -- "${render[@]}" -o hardlink_to_texture.png
    [[ $(cksum <texture.png) == "$texture_sum" ]] || fail "render -o an input" "the texture was changed"
    cp good.csv lookups.csv
    expect_error "sample -o the lookups file itself" "is the input" - -- \
        "${SAMPLE[@]}" --lookups lookups.csv -o lookups.csv
    cmp -s good.csv lookups.csv || fail "sample -o the lookups file itself" "the lookups file was changed"
    cp ok.png a.png && cp ok.png b.png
    expect_error "diff A B -o A" "is the input" - -- "$TEXFILTER" diff a.png b.png -o a.png
    cmp -s ok.png a.png || fail "diff A B -o A" "A was changed"
    # A read-only output file is refused and kept.
    echo keep >readonly.png && chmod a-w readonly.png
    expect_error "render -o a read-only file" "read-only" - -- "${RENDER[@]}" -o readonly.png
    [[ $(cat readonly.png) == keep ]] || fail "render -o a read-only file" "the read-only file was replaced"
    # A symlinked output is followed: its target is written, the link stays a link.
    echo old >target.png && ln -s target.png output_link.png
    run_command "${RENDER[@]}" -o output_link.png
    if [[ $rc -ne 0 || ! -L output_link.png ]] || cmp -s target.png <(echo old); then
        fail "render -o a symlink" "exit $rc; the link must stay a link and its target be written"
    else
        pass "render -o a symlink"
    fi
    expect_error "render -o a device" "not a regular file" - -- "${RENDER[@]}" -o /dev/null
    mkdir -p out_dir
    expect_error "render -o DIR names the directory" "out_dir: is a directory" - -- "${RENDER[@]}" -o out_dir
    rm -rf texture.png link_to_texture.png hardlink_to_texture.png lookups.csv a.png b.png readonly.png target.png \
        output_link.png out_dir
}

# A prefix that runs a command as an unprivileged user where the script runs as root (root may write
# anywhere), so that permissions bite.
AS_USER=()
if [[ $(id -u) -eq 0 ]]; then
    AS_USER=(setpriv --reuid=nobody --regid=nogroup --clear-groups --)
fi

# Unwritable outputs are found before the work, with the reason; signals leave no litter.
unwritable_outputs() {
    if [[ $(id -u) -eq 0 ]] && ! command -v setpriv >/dev/null; then
        skip "unwritable outputs" "running as root without setpriv"
        return
    fi
    chmod 755 "$WORK"
    mkdir -p locked && chmod 555 locked
    expect_error "render -o in an unwritable directory" "Permission denied" locked/out.png -- \
        "${AS_USER[@]}" "${RENDER[@]}" -o locked/out.png
    expect_error "sample -o in an unwritable directory" "Permission denied" locked/out.csv -- \
        "${AS_USER[@]}" "${SAMPLE[@]}" --lookups good.csv -o locked/out.csv
    expect_error "bench --out in an unwritable directory" "Permission denied" locked/bench -- \
        "${AS_USER[@]}" "$TEXFILTER" bench --quick --scenes zoom --out locked/bench
    expect_error "golden --out in an unwritable directory" "Permission denied" locked/golden -- \
        "${AS_USER[@]}" "$TEXFILTER" golden --out locked/golden
    # Another user's writable file in a sticky directory (as /tmp): only its owner may replace it there, so it
    # is refused before the work (the render ran, then the rename failed).
    if [[ $(id -u) -eq 0 ]]; then # the file root's, the render nobody's
        mkdir -p sticky && chmod 1777 sticky && echo theirs >sticky/out.png && chmod 666 sticky/out.png
        expect_error "render -o another user's file in a sticky directory" "sticky directory" - -- \
            "${AS_USER[@]}" "${RENDER[@]}" -o sticky/out.png
        [[ $(cat sticky/out.png) == theirs ]] || fail "render -o another user's file in a sticky directory" "replaced"
        rm -rf sticky
    else
        skip "render -o another user's file in a sticky directory" "needs root to make a file of another user"
    fi
    # An unreadable input says why, as an unwritable output does.
    cp good.csv unreadable.csv && chmod 000 unreadable.csv
    mkdir -p writable && chmod 777 writable
    expect_error "sample: an unreadable lookups file" "unreadable.csv: cannot open the lookups file (Permission denied)" \
        writable/out.csv -- "${AS_USER[@]}" "${SAMPLE[@]}" --lookups unreadable.csv -o writable/out.csv
    rm -rf unreadable.csv writable
    chmod 700 locked && rmdir locked
    chmod 700 "$WORK"
}

# kill_when_temporary_appears SIGNAL COMMAND...: starts the command, sends SIGNAL once a *.tmp-* exists.
kill_when_temporary_appears() {
    kill_when_seen leftover_temporaries "$@"
}

# kill_when_seen LISTER SIGNAL COMMAND...: as kill_when_temporary_appears, once LISTER (a function) prints anything.
kill_when_seen() {
    local lister=$1 signal=$2
    shift 2
    "$@" >stdout 2>stderr &
    local pid=$! seen=0
    for _ in $(seq 1 3000); do
        if [[ -n $("$lister") ]]; then
            seen=1
            break
        fi
        kill -0 "$pid" 2>/dev/null || break
        sleep 0.01
    done
    kill "-$signal" "$pid" 2>/dev/null || true
    rc=0
    wait "$pid" || rc=$?
    signalled=$seen
}

signals_remove_temporaries() {
    # A large PNG takes seconds to encode: the signal lands while OUT.tmp-PID is being written.
    kill_when_temporary_appears INT "$TEXFILTER" render --scene zoom --texture checker --filter nearest \
        --backend reference --size 2048x2048 -o big.png
    if [[ $signalled -ne 1 ]]; then
        skip "SIGINT during a render's write" "the temporary file never appeared (exit $rc)"
    elif [[ -n $(leftover_temporaries) || -e big.png || $rc -ne 130 ]]; then
        fail "SIGINT during a render's write" "exit $rc (expected 130); left: $(leftover_temporaries) $(ls big.png 2>/dev/null)"
    else
        pass "SIGINT during a render's write"
    fi
    kill_when_temporary_appears TERM "$TEXFILTER" bench --quick --scenes zoom --out bench-signal
    if [[ $signalled -ne 1 ]]; then
        skip "SIGTERM during bench" "the staging directory never appeared (exit $rc)"
    elif [[ -n $(leftover_temporaries) || -e bench-signal || $rc -ne 143 ]]; then
        fail "SIGTERM during bench" "exit $rc (expected 143); left: $(leftover_temporaries)"
    else
        pass "SIGTERM during bench"
    fi
    rm -f stdout stderr
    # An output name at the file system's limit still gets a temporary name within it.
    local long
    long=$(printf 'n%.0s' $(seq 1 $(($(getconf NAME_MAX .) - 4)))).png
    expect_success "render -o a name of NAME_MAX bytes" "$long" -- "${RENDER[@]}" -o "$long"
    rm -f "$long"
}

# sample --backend oiio (OpenImageIO's TextureSystem, host/io/oiio_texture.h): what it cannot run is refused before
# any work, in one line. Its private texture directory goes to $TMPDIR, here the work directory, where
# leftover_temporaries sees it.
OIIO_SAMPLE=(env TMPDIR="$WORK" "$TEXFILTER" sample --texture checker --backend oiio --lookups good.csv)
oiio_peer_refusals() {
    EXPECT_ONE_LINE=1 expect_error "oiio: --filter ewa" "whose modes are --filter trilinear and aniso, not --filter ewa" \
        out.csv -- "${OIIO_SAMPLE[@]}" --filter ewa -o out.csv
    local flag
    for flag in "--probes 4" "--lod-bias 1" "--format rgba8" "--build gpu" "--stats" "--resource separate" \
        "--device 0" "--stochastic white"; do
        # shellcheck disable=SC2086 # the flag and its value, two words
        EXPECT_ONE_LINE=1 expect_error "oiio: $flag" "${flag%% *} is not read by --backend oiio" out.csv -- \
            "${OIIO_SAMPLE[@]}" --filter aniso $flag -o out.csv
    done
    EXPECT_ONE_LINE=1 expect_error "oiio: --oiio-interp cubic" \
        "bad value for --oiio-interp: unknown OpenImageIO interpolation 'cubic'" out.csv -- \
        "${OIIO_SAMPLE[@]}" --filter aniso --oiio-interp cubic -o out.csv
    EXPECT_ONE_LINE=1 expect_error "--oiio-interp without --backend oiio" \
        "--oiio-interp is not read by --backend reference" out.csv -- \
        "${SAMPLE[@]}" --oiio-interp bicubic --lookups good.csv -o out.csv
    EXPECT_ONE_LINE=1 expect_error "render --backend oiio" "bad value for --backend: 'oiio' (expected vulkan or reference)" \
        out.png -- "$TEXFILTER" render --scene zoom --texture checker --filter aniso --backend oiio -o out.png
    EXPECT_ONE_LINE=1 expect_error "oiio: no temporary directory" "no temporary directory: TMPDIR=$WORK/missing" \
        out.csv -- env TMPDIR="$WORK/missing" "$TEXFILTER" sample --texture checker --backend oiio --filter aniso \
        --lookups good.csv -o out.csv
    [[ ! -e missing ]] || fail "oiio: no temporary directory" "$WORK/missing was created"
    EXPECT_ONE_LINE=1 expect_error "oiio: missing texture file" missing.png out.csv -- \
        env TMPDIR="$WORK" "$TEXFILTER" sample --texture missing.png --backend oiio --filter aniso --lookups good.csv \
        -o out.csv
    EXPECT_ONE_LINE=1 expect_error "oiio: missing lookups file" none.csv out.csv -- \
        env TMPDIR="$WORK" "$TEXFILTER" sample --texture checker --backend oiio --filter aniso --lookups none.csv \
        -o out.csv
}

oiio_texture_directories() {
    find . -maxdepth 1 -name 'texfilter-oiio.tmp-*' -print
}

# Nothing of the TextureSystem's texture file outlives a run, finished or ended by a signal.
oiio_peer_temporaries() {
    expect_success "oiio: trilinear sample" oiio.csv -- "${OIIO_SAMPLE[@]}" --filter trilinear -o oiio.csv
    if [[ -n $(leftover_temporaries) || $(wc -l <oiio.csv) -ne 2 ]]; then
        fail "oiio: a finished run leaves nothing" "left: $(leftover_temporaries); $(wc -l <oiio.csv) rows"
    else
        pass "oiio: a finished run leaves nothing"
    fi
    # A 4096² texture takes OIIO a second or more to MIP-map: the signal lands while its directory exists.
    python3 -c 'import random
random.seed(3)
print("u,v,dudx,dvdx,dudy,dvdy")
for _ in range(200000): print("%.6f,%.6f,0.01,0,0,0.003" % (random.random(), random.random()))' >many.csv
    # The output's temporary comes first: wait for the texture's directory itself.
    kill_when_seen oiio_texture_directories TERM env TMPDIR="$WORK" "$TEXFILTER" sample --texture noise \
        --texture-size 4096 --backend oiio --filter aniso --lookups many.csv -o killed.csv
    if [[ $signalled -ne 1 ]]; then
        skip "oiio: SIGTERM while the texture file exists" "its directory never appeared (exit $rc)"
    elif [[ -n $(leftover_temporaries) || -e killed.csv || $rc -ne 143 ]]; then
        fail "oiio: SIGTERM while the texture file exists" \
            "exit $rc (expected 143); left: $(leftover_temporaries) $(ls killed.csv 2>/dev/null)"
    else
        pass "oiio: SIGTERM while the texture file exists"
    fi
    rm -f stdout stderr many.csv
}

# Temporaries are created exclusively under random names: whatever sits at the old predictable names
# (NAME.tmp-PID, DIR.tmp-PID/) is never written, adopted or removed. Each case plants it for the PID the
# command will have: a subshell's $BASHPID is kept by exec.
exclusive_temporaries() {
    cp ok.png input.png && cp good.csv input.csv
    local input_sum csv_sum
    input_sum=$(cksum <input.png)
    csv_sum=$(cksum <input.csv)
    # A link at the render's old temporary name, to its own texture: writing through it destroyed the input.
    run_command bash -c 'ln -s input.png "out.png.tmp-$BASHPID"; echo foreign >"out.exr.tmp-$BASHPID"
        exec "$@" -o out.png' _ "$TEXFILTER" render --scene zoom --texture input.png --filter nearest "${REF[@]}"
    if [[ $rc -ne 0 || $(cksum <input.png) != "$input_sum" || -L out.png || ! -s out.png ]]; then
        fail "render with a link planted at OUT.tmp-PID" "exit $rc; the texture must be unchanged and out.png a new file"
    elif [[ $(find . -maxdepth 1 -name 'out.png.tmp-*' -type l | wc -l) -ne 1 ]]; then
        fail "render with a link planted at OUT.tmp-PID" "the planted link was removed or replaced"
    else
        pass "render with a link planted at OUT.tmp-PID"
    fi
    # The same for sample and its lookups file.
    run_command bash -c 'ln -s input.csv "out.csv.tmp-$BASHPID"; exec "$@"' _ "$TEXFILTER" sample --texture checker \
        --filter bilinear --backend reference --lookups input.csv -o out.csv
    if [[ $rc -ne 0 || $(cksum <input.csv) != "$csv_sum" || -L out.csv || ! -s out.csv ]]; then
        fail "sample with a link planted at OUT.tmp-PID" "exit $rc; the lookups must be unchanged and out.csv a new file"
    else
        pass "sample with a link planted at OUT.tmp-PID"
    fi
    # A file someone left at the old name is neither overwritten nor renamed onto the output.
    run_command bash -c 'echo theirs >"left.png.tmp-$BASHPID"; exec "$@" -o left.png' _ "${RENDER[@]}"
    if [[ $rc -ne 0 || $(cat left.png.tmp-* 2>/dev/null) != theirs ]] || ! cmp -s left.png ok.png; then
        fail "render with a file left at OUT.tmp-PID" "exit $rc; the file must be kept and left.png rendered"
    else
        pass "render with a file left at OUT.tmp-PID"
    fi
    # build --out adopted a foreign DIR.tmp-PID/ and published its files with the results.
    run_command bash -c 'mkdir "built.tmp-$BASHPID" && echo theirs >"built.tmp-$BASHPID/notes.txt"; exec "$@"' _ \
        "$TEXFILTER" build --texture checker --texture-size 16 --build cpu --out built
    if [[ $rc -ne 0 || -e built/notes.txt || ! -s built/build.txt || $(cat built.tmp-*/notes.txt 2>/dev/null) != theirs ]]; then
        fail "build with a directory planted at DIR.tmp-PID" "exit $rc; its file must stay there and not reach built/"
    else
        pass "build with a directory planted at DIR.tmp-PID"
    fi
    # SIGTERM during bench removed a foreign DIR.tmp-PID/ with everything in it.
    if "$TEXFILTER" info >/dev/null 2>&1; then
        bash -c 'mkdir "bench-out.tmp-$BASHPID" && echo theirs >"bench-out.tmp-$BASHPID/keep.txt"
            exec "$@"' _ "$TEXFILTER" bench --quick --scenes zoom --out bench-out >stdout 2>stderr &
        local pid=$! ours=0
        for _ in $(seq 1 3000); do # until bench's own staging directory exists (or it ends)
            if [[ $(find . -maxdepth 1 -name 'bench-out.tmp-*' -type d | wc -l) -ge 2 ]]; then
                ours=1
                break
            fi
            kill -0 "$pid" 2>/dev/null || break
            sleep 0.01
        done
        kill -TERM "$pid" 2>/dev/null || true
        rc=0
        wait "$pid" || rc=$?
        if [[ $ours -ne 1 && ( -e bench-out/keep.txt || $(cat bench-out.tmp-*/keep.txt 2>/dev/null) != theirs ) ]]; then
            fail "SIGTERM during bench beside a foreign DIR.tmp-PID" "bench adopted or removed the foreign folder (exit $rc)"
        elif [[ $ours -ne 1 ]]; then
            skip "SIGTERM during bench beside a foreign DIR.tmp-PID" "bench's staging directory never appeared (exit $rc)"
        elif [[ $rc -ne 143 || $(cat bench-out.tmp-*/keep.txt 2>/dev/null) != theirs ||
            $(find . -maxdepth 1 -name 'bench-out.tmp-*' | wc -l) -ne 1 || -e bench-out ]]; then
            fail "SIGTERM during bench beside a foreign DIR.tmp-PID" "exit $rc; the foreign folder must stay, bench's own go"
        else
            pass "SIGTERM during bench beside a foreign DIR.tmp-PID"
        fi
    else
        skip "SIGTERM during bench beside a foreign DIR.tmp-PID" "no usable Vulkan device here"
    fi
    rm -rf input.png input.csv out.png out.csv out.*.tmp-* left.png left.png.tmp-* built built.tmp-* bench-out \
        bench-out.tmp-* \
        stdout stderr
}

# The output is created (as its temporary) before the work: the file system says whether it can be written,
# not access(), which says yes to root everywhere. The wrong device proves that nothing ran first.
outputs_created_first() {
    if [[ $(id -u) -ne 0 ]]; then
        skip "outputs in /proc as root" "not root: access() already says no there"
    else
        expect_error "render -o /proc/x.exr as root" "/proc/x.exr: cannot create files in /proc" - -- \
            "$TEXFILTER" render --scene zoom --texture checker --filter nearest --device 99 -o /proc/x.exr
        expect_error "build --out /proc/x as root" "/proc/x: cannot create a directory in /proc" - -- \
            "$TEXFILTER" build --texture checker --device 99 --out /proc/x
        expect_error "bench --out /proc/x as root" "/proc/x: cannot create a directory in /proc" - -- \
            "$TEXFILTER" bench --quick --device 99 --out /proc/x
        # A viewer script's screenshots are checked before the window opens (no display is needed to refuse).
        printf 'screenshot /proc/x.png\n' >proc-shot.txt
        expect_error "view --script with a screenshot in /proc as root" "/proc/x.png: cannot create files in /proc" - \
            -- env -u DISPLAY "$TEXFILTER" view --texture checker --script proc-shot.txt
        rm -f proc-shot.txt
    fi
    # A results directory whose name the file system cannot take: refused before the work (it was built, then
    # could not be moved into place).
    local long_dir
    long_dir=$(printf 'n%.0s' $(seq 1 $(($(getconf NAME_MAX .) + 1))))
    expect_error "build --out a name longer than NAME_MAX" "bytes, longer than" - -- \
        "$TEXFILTER" build --texture checker --texture-size 16 --build cpu --out "$long_dir"
    expect_error "bench --out a name longer than NAME_MAX" "bytes, longer than" - -- \
        "$TEXFILTER" bench --quick --device 99 --out "$long_dir"
    # A parent that is a file is named as one.
    expect_error "render -o under a file" "ok.png is a file, not a directory" - -- "${RENDER[@]}" -o ok.png/x.png
    # --out through a link to an empty directory: the link is followed, as -o follows one.
    mkdir -p empty-target && ln -s empty-target out-link
    run_command "$TEXFILTER" build --texture checker --texture-size 16 --build cpu --out out-link
    if [[ $rc -ne 0 || ! -L out-link || ! -s empty-target/build.txt ]]; then
        fail "build --out a link to an empty directory" "exit $rc; the link must stay and its directory get the results"
    else
        pass "build --out a link to an empty directory"
    fi
    expect_error "build --out a link to a directory that is not empty" "out-link (a link to" - -- \
        "$TEXFILTER" build --texture checker --texture-size 16 --build cpu --out out-link
    rm -rf empty-target out-link
    # Two golden runs into one --out: the second is refused while the first holds the directory.
    if command -v flock >/dev/null && "$TEXFILTER" info >/dev/null 2>&1; then
        mkdir -p busy
        local lock_fd
        exec {lock_fd}<busy
        flock -n "$lock_fd" # held by this shell as another run would hold it
        expect_error "golden --out a directory another run is writing" "another texfilter run is writing" - -- \
            "$TEXFILTER" golden --case "$(awk '!/^#/ && NF { print $1; exit }' "$GOLDEN_DIR/manifest.txt")" --out busy
        [[ -z $(ls -A busy) ]] || fail "golden --out a directory another run is writing" "it wrote $(ls -A busy)"
        exec {lock_fd}<&-
        rm -rf busy
    else
        skip "golden --out a directory another run is writing" "no flock(1) or no usable Vulkan device here"
    fi
}

# Truncated images are errors naming the file.
truncated_images() {
    local render=("$TEXFILTER" render --scene zoom --filter nearest "${REF[@]}")
    oiiotool --pattern checker:width=8:height=8 256x256 3 -d uint8 -o whole.jpg
    head -c $(($(wc -c <whole.jpg) / 2)) whole.jpg >half.jpg
    expect_error "JPEG cut in half" half.jpg out.png -- "${render[@]}" --texture half.jpg -o out.png
    oiiotool --pattern checker:width=8:height=8 256x256 3 -d uint8 --compression none -o whole.tif
    head -c $(($(wc -c <whole.tif) / 2)) whole.tif >half.tif
    expect_error "TIFF with a short strip" half.tif out.png -- "${render[@]}" --texture half.tif -o out.png
    expect_success "the whole JPEG (control)" out.png -- "${render[@]}" --texture whole.jpg -o out.png
    rm -f out.png
    # libpng's own "libpng error:" line must not appear beside texfilter's message.
    head -c $(($(wc -c <ok.png) - 20)) ok.png >truncated_idat.png
    EXPECT_ONE_LINE=1 expect_error "truncated PNG: one line on stderr" truncated_idat.png out.png -- \
        "${render[@]}" --texture truncated_idat.png -o out.png
}

# Sizes are checked from headers against the memory budget and the device.
memory_budgets() {
    local render=("$TEXFILTER" render --scene zoom --filter nearest "${REF[@]}")
    write_png_header_only bomb.png 16384 16384
    expect_error "74-byte PNG claiming 16384x16384" "more than a" out.png -- "${render[@]}" --texture bomb.png -o out.png
    # Its opposite: a real 1-bit PNG compresses close to deflate's limit and must not be taken for a bomb.
    python3 - <<'EOF'
import struct, zlib
w = h = 4096
def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff)
compressor = zlib.compressobj(9)
idat = b"".join([compressor.compress(b"\0" * (1 + w // 8)) for _ in range(h)] + [compressor.flush()])
with open("one_bit.png", "wb") as f:
    f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 1, 0, 0, 0, 0)) +
            chunk(b"IDAT", idat) + chunk(b"IEND", b""))
EOF
    expect_success "a 4096x4096 1-bit PNG near deflate's limit (not a bomb)" out.png -- \
        "${render[@]}" --texture one_bit.png -o out.png
    rm -f out.png one_bit.png
    write_constant_png k1024.png 1024 1024
    expect_error "texture over --memory-budget" "memory budget of 1.0 MiB" out.png -- \
        "${render[@]}" --texture k1024.png --memory-budget 1M -o out.png
    expect_success "texture under --memory-budget (control)" out.png -- \
        "${render[@]}" --texture k1024.png --memory-budget 1G -o out.png
    rm -f out.png
    expect_error "--memory-budget bogus" --memory-budget out.png -- \
        "${render[@]}" --texture k1024.png --memory-budget lots -o out.png
    expect_error "--memory-budget past any machine" "'99999999999999999999G' is out of range" out.png -- \
        "${render[@]}" --texture k1024.png --memory-budget 99999999999999999999G -o out.png
    expect_error "diff over --memory-budget" "memory budget" diff.png -- \
        "$TEXFILTER" diff k1024.png k1024.png --memory-budget 1M -o diff.png
    write_constant_png oversize.png 4097 2
    expect_error "sat on a texture over 4096 a side names it" "oversize.png" out.png -- \
        "$TEXFILTER" render --scene zoom --filter sat "${REF[@]}" --texture oversize.png -o out.png
    # The device's own limits, where it reports one the 16384^2 texture's chain (5.3 GiB) exceeds.
    local limit
    limit=$("$TEXFILTER" info 2>/dev/null | sed -n 's/.*maxMemoryAllocationSize \([0-9.]*\) GiB.*/\1/p' | awk 'NR == 1')
    if [[ -n $limit ]] && awk "BEGIN { exit !($limit < 5.3) }"; then
        write_constant_png huge16k.png 16384 16384
        # A generous host budget, so that the device's limit is what refuses it on any machine (nothing is
        # allocated: the device check comes before the decode).
        expect_error "16384x16384 texture over the device's allocation limit" maxMemoryAllocationSize out.png -- \
            "$TEXFILTER" render --scene zoom --filter nearest --size 16x16 --texture huge16k.png \
            --memory-budget 1T -o out.png
    else
        skip "16384x16384 texture over the device's allocation limit" "no device with a limit under 5.3 GiB"
    fi
    rm -f bomb.png k1024.png oversize.png huge16k.png
}

# Extreme lookups finish with a result, HDR and NaN texels for sat, CSV messages.
lookups_and_texels() {
    # One lookup with gradients of 1e100 among good ones: every row answered, all finite (the reference
    # once threw "no texel weighs anything" for ewa and lost the whole batch).
    printf '%s\n0.5,0.5,0.01,0,0,0.01\n0.5,0.5,1e100,0,0,1e100\n0.3,0.7,1e154,1e154,0,1e300\n' "$LOOKUPS_HEADER" >extreme.csv
    local filter
    for filter in "ewa" "aniso --aniso-shape feline" "aniso --taps hardware" "sat"; do
        run_command "$TEXFILTER" sample --texture checker --backend reference --filter $filter --lookups extreme.csv \
            -o extreme_out.csv
        if [[ $rc -ne 0 || $(wc -l <extreme_out.csv) -ne 4 ]] || grep -qiE 'nan|inf' extreme_out.csv; then
            fail "sample --filter $filter with gradients of 1e100..1e300" "exit $rc; every row must be finite"
        else
            pass "sample --filter $filter with gradients of 1e100..1e300"
        fi
        rm -f extreme_out.csv
    done
    # sat needs finite texels: a NaN one is refused, naming the texture, on both backends.
    python3 - <<'EOF'
import struct
with open("nan_texel.pfm", "wb") as f:
    f.write(b"PF\n4 4\n-1.0\n")
    values = [0.5] * 48
    values[5] = float("nan")
    f.write(struct.pack("<48f", *values))
EOF
    for backend in reference vulkan; do
        expect_error "sat with a NaN texel ($backend)" "nan_texel.pfm" out.csv -- "$TEXFILTER" sample --texture nan_texel.pfm \
            --linear --filter sat --backend $backend --lookups good.csv -o out.csv
    done
    # A lookups file with a header and no rows is not bad input: a header-only result (UBSan once found a
    # memcpy from a null pointer here on the Vulkan backend).
    echo "$LOOKUPS_HEADER" >header_only.csv
    run_command "$TEXFILTER" sample --texture checker --filter bilinear --lookups header_only.csv -o header_only_out.csv
    if [[ $rc -ne 0 || $(cat header_only_out.csv 2>/dev/null) != "r,g,b,a" ]]; then
        fail "sample with no lookups (vulkan)" "exit $rc; expected a header-only CSV"
    else
        pass "sample with no lookups (vulkan)"
    fi
    # A UTF-8 byte order mark before the header is accepted.
    printf '\xef\xbb\xbf%s\n0.5,0.5,0.01,0,0,0.01\n' "$LOOKUPS_HEADER" >bom.csv
    expect_success "sample: a lookups file with a UTF-8 BOM" bom_out.csv -- "${SAMPLE[@]}" --lookups bom.csv -o bom_out.csv
    # A megabytes-long garbage row is quoted in a few dozen characters, not echoed whole.
    { echo "$LOOKUPS_HEADER"; head -c 4000000 /dev/zero | tr '\0' 'x'; echo; } >garbage.csv
    EXPECT_ONE_LINE=1 expect_error "sample: a 4 MB garbage row" "garbage.csv:2" out.csv -- \
        "${SAMPLE[@]}" --lookups garbage.csv -o out.csv
    run_command "${SAMPLE[@]}" --lookups garbage.csv -o out.csv
    if [[ $(wc -c <stderr) -gt 300 ]]; then
        fail "sample: a 4 MB garbage row" "$(wc -c <stderr) bytes on stderr"
    fi
    rm -f extreme.csv nan_texel.pfm header_only.csv header_only_out.csv bom.csv bom_out.csv garbage.csv stdout stderr
}

# The same command gives the same bytes.
reproducible_outputs() {
    for ext in png exr pfm; do
        "${RENDER[@]}" -o first.$ext >/dev/null
        sleep 1.1 # a time stamp would now differ
        "${RENDER[@]}" -o second.$ext >/dev/null
        if cmp -s first.$ext second.$ext; then
            pass "two identical .$ext renders give the same bytes"
        else
            fail "two identical .$ext renders give the same bytes" "they differ"
        fi
        rm -f first.$ext second.$ext
    done
}


# --format: an unknown name lists the valid ones; integer data refuses every sampler filter (hw-* modes,
# hardware taps) before any work, on either backend, in a manifest too.
bad_formats() {
    printf '%s\n0.5,0.5,0.01,0,0,0.01\n' "$LOOKUPS_HEADER" >formats.csv
    expect_error "render --format bogus" "expected one of: rgba32f, rgba8-srgb, rgba8, rgba16f, r8, r16f, r32f, r16ui, r32ui" out.png -- \
        "${RENDER[@]}" --format bogus -o out.png
    expect_error "render --format r16ui --filter hw-bilinear" "--format r16ui holds integer data" out.png -- \
        "$TEXFILTER" render --scene zoom --texture checker --filter hw-bilinear --format r16ui "${REF[@]}" -o out.png
    expect_error "sample --format r32ui --filter ewa --taps hardware" "--taps hardware needs a float format" out.csv -- \
        "$TEXFILTER" sample --texture checker --filter ewa --taps hardware --format r32ui --lookups formats.csv -o out.csv
    expect_error "sample --format r16ui --filter catmull-rom --taps hardware" "--taps hardware needs a float format" out.csv -- \
        "$TEXFILTER" sample --texture checker --filter catmull-rom --taps hardware --format r16ui --lookups formats.csv -o out.csv
    expect_error "bench --format RGBA8 (names are lower case)" "unknown texture format 'RGBA8'" bench-out -- \
        "$TEXFILTER" bench --quick --format RGBA8 --out bench-out
    mkdir -p format-golden
    printf 'bad zoom checker hw-trilinear format=r16ui\n' >format-golden/manifest.txt
    expect_error "golden manifest: format=r16ui with hw-trilinear" "manifest.txt:1: --format r16ui holds integer data" out.png -- \
        "$TEXFILTER" golden --golden-dir format-golden --out format-golden-out
}

# --build gpu and texfilter build: what the device cannot build is refused before any work, on every
# command; build --out is a new or empty directory and nothing is left where it fails.
gpu_builds() {
    printf '%s\n0.5,0.5,0.01,0,0,0.01\n' "$LOOKUPS_HEADER" >builds.csv
    expect_error "render --build bogus" "unknown build 'bogus' (expected cpu or gpu)" out.png -- \
        "${RENDER[@]}" --build bogus -o out.png
    expect_error "render --build gpu --backend reference" "--build gpu builds on the Vulkan device" out.png -- \
        "${RENDER[@]}" --build gpu -o out.png
    expect_error "render --build gpu --texture mipcolors" "texture mipcolors gives every level its own colour" out.png -- \
        "$TEXFILTER" render --scene zoom --texture mipcolors --filter trilinear --build gpu -o out.png
    expect_error "sample --build gpu --format r16ui" "--format r16ui is integer data" out.csv -- \
        "$TEXFILTER" sample --texture checker --filter trilinear --build gpu --format r16ui --lookups builds.csv -o out.csv
    expect_error "sample --build gpu --resource array" "--build gpu is for --resource combined" out.csv -- \
        "$TEXFILTER" sample --texture checker --filter trilinear --build gpu --resource array --lookups builds.csv -o out.csv
    expect_error "bench --build gpu --texture mipcolors" "texture mipcolors" bench-out -- \
        "$TEXFILTER" bench --quick --build gpu --texture mipcolors --out bench-out
    expect_error "golden --update --build gpu" "--update renders the goldens with the CPU reference" - -- \
        "$TEXFILTER" golden --update --build gpu --golden-dir format-golden
    mkdir -p build-earlier && echo keep >build-earlier/notes.txt
    expect_error "build --out a non-empty directory" "not an empty directory" - -- \
        "$TEXFILTER" build --texture checker --out build-earlier
    if [[ $(cat build-earlier/notes.txt) != keep || $(ls build-earlier | wc -l) -ne 1 ]]; then
        fail "build --out a non-empty directory" "the directory's contents were changed"
    fi
    expect_error "build --out in a missing directory" "parent directory does not exist" missing/build-out -- \
        "$TEXFILTER" build --texture checker --out missing/build-out
    expect_error "build --level-format tiff" "bad value for --level-format: 'tiff'" build-out -- \
        "$TEXFILTER" build --texture checker --level-format tiff --out build-out
    expect_error "build --sat of a 5000-texel side" "4096" build-out -- \
        "$TEXFILTER" build --texture noise --texture-size 5000 --sat --out build-out
    expect_error "build --texture a missing file" "missing.png" build-out -- \
        "$TEXFILTER" build --texture missing.png --out build-out
    expect_error "build without a Vulkan driver" "no Vulkan driver" build-out -- \
        "${WITHOUT_VULKAN_DRIVER[@]}" "$TEXFILTER" build --texture checker --out build-out
    expect_error "render --texture-frame on a static texture" "--texture-frame applies to --texture dynamic only" out.png -- \
        "$TEXFILTER" render --scene plane --texture checker --texture-frame 3 --filter trilinear -o out.png
    expect_success "sample --build gpu --filter sat" ok_gpu_sat.csv -- \
        "$TEXFILTER" sample --texture noise --texture-size 37 --filter sat --build gpu --lookups builds.csv -o ok_gpu_sat.csv
    expect_success "render --build gpu --format rgba8-srgb" ok_gpu.png -- \
        "$TEXFILTER" render --scene plane --texture checker --texture-size 40 --filter trilinear --size 16x16 \
        --build gpu --format rgba8-srgb -o ok_gpu.png
    expect_success "build --build cpu --sat" build-cpu/sat.bin -- \
        "$TEXFILTER" build --texture checker --texture-size 64 --build cpu --sat --out build-cpu
}

environment_maps() {
    local env=("$TEXFILTER" render --scene skybox --size 16x16)
    expect_error "render --env sphere" "unknown environment map 'sphere' (cube, latlong)" out.png -- \
        "${env[@]}" --texture checker --filter trilinear --env sphere -o out.png
    expect_error "render --scene skybox --filter sat" "--filter sat has no environment-map form" out.png -- \
        "${env[@]}" --texture checker --filter sat -o out.png
    # No longer refused: the cubics' hardware taps on environment maps (cube.glsl, latlong.glsl _hw forms).
    expect_success "render --scene skybox --filter bspline --taps hardware" hw_cubic.png -- \
        "${env[@]}" --texture checker --filter bspline --taps hardware -o hw_cubic.png
    expect_error "render --scene reflect --stage compute" "fragment stage only" out.png -- \
        "$TEXFILTER" render --scene reflect --size 16x16 --texture checker --filter ewa --stage compute -o out.png
    expect_error "render --scene skybox --view lod" "--view lod is not available on the environment scenes" out.png -- \
        "${env[@]}" --texture checker --filter trilinear --view lod -o out.png
    expect_error "render --scene skybox --format rgba8-srgb" "environment maps are uploaded as rgba32f only" out.png -- \
        "${env[@]}" --texture checker --filter trilinear --format rgba8-srgb --backend reference -o out.png
    expect_error "render --scene skybox --texture dynamic" "has no environment form" out.png -- \
        "${env[@]}" --texture dynamic --filter trilinear --backend reference -o out.png
    write_constant_png square.png 24 24
    expect_error "render --env cube --texture a square image" "square.png" out.png -- \
        "${env[@]}" --texture square.png --filter trilinear --backend reference -o out.png
    expect_error "render --scene skybox --texture-size 16384 (six faces over the budget)" "over the memory budget" out.png -- \
        "${env[@]}" --texture checker --texture-size 16384 --memory-budget 1G --filter trilinear --backend reference -o out.png
    expect_error "view --scene skybox" "the viewer shows the 2D scenes" - -- \
        "$TEXFILTER" view --scene skybox --texture checker --filter trilinear
    write_constant_png cross.png 32 24
    expect_success "render --env cube --texture a 4:3 cross" ok_cross.png -- \
        "${env[@]}" --texture cross.png --filter trilinear --backend reference -o ok_cross.png
    expect_success "render --env latlong --scene reflect" ok_latlong.png -- \
        "$TEXFILTER" render --scene reflect --size 16x16 --texture checker --texture-size 16 --env latlong --filter trilinear -o ok_latlong.png
}

# Text inputs (view --script/--state, the golden manifest, sample --lookups) are read from regular files only,
# up to a cap (host/io/text_file.h): a device, a FIFO or a link to one is refused at once, naming it, and an
# oversized file from its size, before anything else is done. Each command must answer within seconds: a FIFO
# that was opened for reading would wait for a writer, /dev/zero would be read until memory runs out.
bounded_text_inputs() {
    local COMMAND_TIMEOUT=30 # read by run_command: a refusal is immediate
    local view=(env -u DISPLAY "$TEXFILTER" view) # the refusal comes before the window, so no display is needed
    mkfifo fifo.txt
    ln -s /dev/zero zero_link.txt
    truncate -s 3G sparse_3g.txt # over every cap, and no disk space taken
    local flag
    for flag in --script --state; do
        expect_error "view $flag /dev/zero" "/dev/zero: is a character device, not a regular file" - -- \
            "${view[@]}" "$flag" /dev/zero
        expect_error "view $flag a FIFO" "fifo.txt: is a pipe (FIFO), not a regular file" - -- \
            "${view[@]}" "$flag" fifo.txt
        expect_error "view $flag a link to /dev/zero" "zero_link.txt: is a character device, not a regular file" - -- \
            "${view[@]}" "$flag" zero_link.txt
        expect_error "view $flag a directory" ".: is a directory, not a regular file" - -- "${view[@]}" "$flag" .
    done
    expect_error "view --script a 3 GiB file" "sparse_3g.txt: the script is 3.0 GiB (3221225472 bytes), over its cap of 16.0 MiB" - -- \
        "${view[@]}" --script sparse_3g.txt
    expect_error "view --state a 3 GiB file" "sparse_3g.txt: the viewer state is 3.0 GiB (3221225472 bytes), over its cap of 1.0 MiB" - -- \
        "${view[@]}" --state sparse_3g.txt
    # golden --golden-dir DIR reads DIR/manifest.txt: a link to /dev/zero, a FIFO, an oversized file. No --out
    # directory is made (it was, with a report of "0 cases", after reading /dev/zero until memory ran out).
    mkdir -p manifest-zero manifest-fifo manifest-big
    ln -s /dev/zero manifest-zero/manifest.txt
    mkfifo manifest-fifo/manifest.txt
    truncate -s 3G manifest-big/manifest.txt
    expect_error "golden: manifest.txt a link to /dev/zero" \
        "manifest-zero/manifest.txt: is a character device, not a regular file (the golden manifest must be one)" \
        golden-out -- "$TEXFILTER" golden --golden-dir manifest-zero --out golden-out
    expect_error "golden: manifest.txt a FIFO" "manifest-fifo/manifest.txt: is a pipe (FIFO), not a regular file" \
        golden-out -- "$TEXFILTER" golden --golden-dir manifest-fifo --out golden-out
    expect_error "golden: a 3 GiB manifest.txt" "manifest-big/manifest.txt: the golden manifest is 3.0 GiB (3221225472 bytes), over its cap of 16.0 MiB" \
        golden-out -- "$TEXFILTER" golden --golden-dir manifest-big --out golden-out
    # The lookups file: the same rule (its /dev/zero and FIFO cases are in bad_lookups).
    expect_error "sample: --lookups a link to /dev/zero" "zero_link.txt: is a character device, not a regular file" \
        out.csv -- "${SAMPLE[@]}" --lookups zero_link.txt -o out.csv
    expect_error "sample: --lookups a 3 GiB file" "sparse_3g.txt: the lookups file is 3.0 GiB (3221225472 bytes), over its cap of 2.0 GiB" \
        out.csv -- "${SAMPLE[@]}" --lookups sparse_3g.txt -o out.csv
    # Image files too (textures, environment maps, diff's A and B): the image library opens them by name and
    # would wait on a FIFO for ever.
    mkfifo fifo.png
    expect_error "render --texture a FIFO" "fifo.png: is a pipe (FIFO), not a regular file" out.png -- \
        "$TEXFILTER" render --scene zoom --texture fifo.png --filter trilinear "${REF[@]}" -o out.png
    expect_error "render --texture a FIFO as an environment map" "fifo.png: is a pipe (FIFO), not a regular file" \
        out.png -- "$TEXFILTER" render --scene skybox --texture fifo.png --filter trilinear "${REF[@]}" -o out.png
    expect_error "render --texture /dev/zero" "/dev/zero: is a character device, not a regular file" out.png -- \
        "$TEXFILTER" render --scene zoom --texture /dev/zero --filter trilinear "${REF[@]}" -o out.png
    expect_error "diff A a FIFO" "fifo.png: is a pipe (FIFO), not a regular file" - -- "$TEXFILTER" diff fifo.png ok.png
    rm -rf fifo.txt fifo.png zero_link.txt sparse_3g.txt manifest-zero manifest-fifo manifest-big
}

# One rule for every flag: a flag the chosen filter (scene, texture, command) does not read is refused, naming
# the flag and what it applies to; numbers have one grammar (decimal only); messages escape control bytes.
flag_rules() {
    local trilinear=("$TEXFILTER" render --scene zoom --texture checker --filter trilinear "${REF[@]}")
    local flag
    for flag in "--probes 4" "--band 0.5" "--alpha 3" "--max-aniso 4" "--aniso 4" "--boxes 2" "--spp 16" \
        "--pixel-filter gaussian" "--aniso-shape feline" "--taps manual"; do
        # shellcheck disable=SC2086 # flag and value, two words
        EXPECT_ONE_LINE=1 expect_error "trilinear refuses ${flag%% *}" \
            "${flag%% *} is not read by --filter trilinear (it applies to " out.png -- "${trilinear[@]}" $flag -o out.png
    done
    expect_error "nearest refuses --lod-bias" "--lod-bias is not read by --filter nearest" out.png -- \
        "${RENDER[@]}" --lod-bias 1 -o out.png
    expect_error "sat refuses --lod-min (it has no levels)" "--lod-min is not read by --filter sat" out.png -- \
        "$TEXFILTER" render --scene zoom --texture checker --filter sat "${REF[@]}" --lod-min 1 -o out.png
    expect_error "none refuses --wrap" "--wrap is not read by --filter none" out.png -- \
        "$TEXFILTER" render --scene zoom --texture checker --filter none "${REF[@]}" --wrap clamp -o out.png
    expect_error "sample: trilinear refuses --probes" "--probes is not read by --filter trilinear" out.csv -- \
        "$TEXFILTER" sample --texture checker --filter trilinear --backend reference --probes 4 --lookups good.csv \
        -o out.csv
    # The scene's and the texture's flags.
    expect_error "--env on a 2D scene" "--env is not read by --scene zoom (it applies to the environment scenes" \
        out.png -- "${trilinear[@]}" --env latlong -o out.png
    expect_error "--wrap on an environment scene" "--wrap is not read on the environment scenes" out.png -- \
        "$TEXFILTER" render --scene skybox --texture checker --texture-size 16 --filter trilinear "${REF[@]}" \
        --wrap clamp -o out.png
    expect_error "view --env" "--env is not read by view" - -- "$TEXFILTER" view --texture checker --env latlong
    expect_error "sample --env" "--env is not read by sample" out.csv -- \
        "${SAMPLE[@]}" --env latlong --lookups good.csv -o out.csv
    expect_error "--linear on a procedural texture" "--linear is not read by --texture checker" out.png -- \
        "${trilinear[@]}" --linear -o out.png
    cp ok.png texture.png
    expect_error "--texture-size on a file" "--texture-size is not read by --texture texture.png" out.png -- \
        "$TEXFILTER" render --scene zoom --texture texture.png --texture-size 64 --filter trilinear "${REF[@]}" \
        -o out.png
    expect_error "bench --env without an environment scene" "--env is not read by --scenes without skybox" \
        bench-out -- "$TEXFILTER" bench --quick --scenes zoom --env latlong --out bench-out
    expect_error "bench --texture-size on a file" "--texture-size is not read by --texture texture.png" bench-out -- \
        "$TEXFILTER" bench --quick --scenes zoom --texture texture.png --texture-size 64 --out bench-out
    mkdir -p rules-golden
    printf 'a zoom checker trilinear size=16x16 texture-size=16 probes=4\n' >rules-golden/manifest.txt
    expect_error "golden manifest: trilinear with probes=" \
        "rules-golden/manifest.txt:1: --probes is not read by --filter trilinear" rules-golden/a.png -- \
        "$TEXFILTER" golden --golden-dir rules-golden --update
    rm -rf rules-golden
    printf 'filter trilinear --probes 4\nquit\n' >rules.txt
    if "$TEXFILTER" view --script rules.txt 2>&1 | grep -q 'left out of this build'; then
        skip "view script: trilinear with --probes" "the viewer was left out of this build"
    else
        expect_error "view script: trilinear with --probes" "--probes is not read by --filter trilinear" - -- \
            "$TEXFILTER" view --script rules.txt
        printf 'filter tri\033[2Jlinear\nquit\n' >rules.txt
        EXPECT_ONE_LINE=1 expect_error "view script: control bytes in a line" "unknown filter 'tri\x1b[2Jlinear'" - -- \
            "$TEXFILTER" view --script rules.txt
    fi
    rm -f rules.txt
    # Positive controls: the flags the filter reads still work.
    expect_success "aniso reads --probes" ok1.png -- \
        "$TEXFILTER" render --scene slanted --texture checker --filter aniso --probes 4 --aniso-shape feline \
        "${REF[@]}" -o ok1.png
    expect_success "brilinear reads --band, ewa --alpha, --max-aniso, --taps" ok2.png -- \
        "$TEXFILTER" render --scene slanted --texture checker --filter ewa --alpha 3 --max-aniso 4 --taps manual \
        --lod-bias 0.5 "${REF[@]}" -o ok2.png
    expect_success "sat reads --lod-bias, sat-assembly --boxes" ok3.png -- \
        "$TEXFILTER" render --scene slanted --texture checker --filter sat-assembly --boxes 2 --lod-bias 1 \
        "${REF[@]}" -o ok3.png
    expect_success "stochastic bilinear reads --taps" ok4.png -- \
        "$TEXFILTER" render --scene zoom --texture checker --filter bilinear --stochastic white --taps manual \
        "${REF[@]}" -o ok4.png
    expect_success "ground-truth reads --spp, --pixel-filter, --wrap" ok5.png -- \
        "$TEXFILTER" render --scene zoom --texture checker --filter ground-truth --spp 16 --pixel-filter gaussian \
        --wrap clamp "${REF[@]}" -o ok5.png
    expect_success "skybox reads --env" ok6.png -- \
        "$TEXFILTER" render --scene skybox --texture checker --texture-size 16 --filter trilinear --env latlong \
        "${REF[@]}" -o ok6.png
    expect_success "an 8-bit file reads --linear" ok7.png -- \
        "$TEXFILTER" render --scene zoom --texture texture.png --linear --filter trilinear "${REF[@]}" -o ok7.png
    rm -f ok[1-7].png
    # Numbers: decimal only, no spaces, no inf or nan, whole byte sizes.
    local ewa=("$TEXFILTER" render --scene zoom --texture checker --filter ewa "${REF[@]}")
    expect_error "--alpha 0x10 (hexadecimal)" "bad value for --alpha: '0x10'" out.png -- "${ewa[@]}" --alpha 0x10 -o out.png
    expect_error "--lod-bias inf" "bad value for --lod-bias: 'inf'" out.png -- "${trilinear[@]}" --lod-bias inf -o out.png
    expect_error "--lod-bias 1e999" "bad value for --lod-bias: '1e999'" out.png -- "${trilinear[@]}" --lod-bias 1e999 -o out.png
    expect_error "--texture-size ' 5' (a space)" "bad value for --texture-size: ' 5'" out.png -- \
        "${trilinear[@]}" --texture-size ' 5' -o out.png
    expect_error "--texture-size '5 ' (a space)" "bad value for --texture-size: '5 '" out.png -- \
        "${trilinear[@]}" --texture-size '5 ' -o out.png
    expect_error "--size 0x10x16 (hexadecimal)" "bad value for --size" out.png -- \
        "$TEXFILTER" render --scene zoom --texture checker --filter trilinear --backend reference --size 0x10x16 -o out.png
    expect_error "--spp 0x10" "bad value for --spp: '0x10'" out.png -- \
        "$TEXFILTER" render --scene zoom --texture checker --filter ground-truth "${REF[@]}" --spp 0x10 -o out.png
    expect_error "--camera 0x1,0,0,0,0" "camera X '0x1' is not a number" out.png -- \
        "${trilinear[@]}" --camera 0x1,0,0,0,0 -o out.png
    expect_error "--memory-budget 1.5 (a fraction of a byte)" "bad value for --memory-budget: '1.5' is not a size" \
        out.png -- "${trilinear[@]}" --memory-budget 1.5 -o out.png
    expect_error "--memory-budget 1.5G" "'1.5G' is not a size" out.png -- "${trilinear[@]}" --memory-budget 1.5G -o out.png
    expect_error "--memory-budget ' 5G'" "' 5G' is not a size" out.png -- "${trilinear[@]}" --memory-budget ' 5G' -o out.png
    expect_success "--memory-budget 1536M, --lod-bias +0.5, --lod-max 2e0 (the grammar's forms)" ok.png -- \
        "${trilinear[@]}" --memory-budget 1536M --lod-bias +0.5 --lod-max 2e0 -o ok.png
    # Messages: the system's reason for an unreadable file; the procedural names for an unknown name, before any
    # Vulkan start-up; control bytes escaped; TEXFILTER_VALIDATE checked.
    if [[ $(id -u) -eq 0 ]] && ! command -v setpriv >/dev/null; then
        skip "unreadable texture" "running as root without setpriv"
    else
        chmod 755 "$WORK"
        mkdir -p writable && chmod 777 writable
        cp ok.png unreadable.png && chmod 000 unreadable.png
        expect_error "unreadable texture" "unreadable.png: Permission denied" writable/out.png -- \
            "${AS_USER[@]}" "$TEXFILTER" render --scene zoom --texture unreadable.png --filter trilinear "${REF[@]}" \
            -o writable/out.png
        expect_error "diff an unreadable image" "unreadable.png: Permission denied" - -- \
            "${AS_USER[@]}" "$TEXFILTER" diff unreadable.png ok.png
        rm -rf unreadable.png writable
        chmod 700 "$WORK"
    fi
    expect_error "unknown texture name" \
        "unknown texture 'chekcer': not a procedural texture (cube-labels, cube-hash, cube-smooth, checker, zoneplate, grid, noise, mipcolors or dynamic) and no such file" \
        out.png -- "$TEXFILTER" render --scene zoom --texture chekcer --filter trilinear "${REF[@]}" -o out.png
    EXPECT_ONE_LINE=1 expect_error "unknown texture name without a Vulkan driver" "unknown texture 'chekcer'" out.png -- \
        "${WITHOUT_VULKAN_DRIVER[@]}" "$TEXFILTER" render --scene zoom --texture chekcer --filter trilinear \
        --size 16x16 --backend vulkan -o out.png
    EXPECT_ONE_LINE=1 expect_error "bench: unknown texture name without a Vulkan driver" "unknown texture 'chekcer'" \
        bench-out -- "${WITHOUT_VULKAN_DRIVER[@]}" "$TEXFILTER" bench --quick --scenes zoom --texture chekcer \
        --out bench-out
    EXPECT_ONE_LINE=1 expect_error "control bytes in a flag value" "unknown filter 'tri\x1b[2Jlinear\x0aforged'" out.png -- \
        "$TEXFILTER" render --scene zoom --texture checker --filter $'tri\e[2Jlinear\nforged' "${REF[@]}" -o out.png
    EXPECT_ONE_LINE=1 expect_error "control bytes in a texture name" "unknown texture 'a\x07b'" out.png -- \
        "$TEXFILTER" render --scene zoom --texture $'a\ab' --filter trilinear "${REF[@]}" -o out.png
    if [[ -n $("$TEXFILTER" render --scene zoom --texture checker --filter $'a\e' "${REF[@]}" -o out.png 2>&1 | tr -d '\n -~') ]]; then
        fail "control bytes in a flag value" "a byte outside printable ASCII reached stderr"
    fi
    EXPECT_ONE_LINE=1 expect_error "TEXFILTER_VALIDATE=yes" "TEXFILTER_VALIDATE='yes' is neither 1" out.png -- \
        env TEXFILTER_VALIDATE=yes "${trilinear[@]}" -o out.png
    expect_error "TEXFILTER_VALIDATE=true (info)" "TEXFILTER_VALIDATE='true'" - -- env TEXFILTER_VALIDATE=true "$TEXFILTER" info
    expect_success "TEXFILTER_VALIDATE=0" validate0.png -- env TEXFILTER_VALIDATE=0 "${trilinear[@]}" -o validate0.png
    rm -f validate0.png texture.png
}

# Texture values and memory bounds: PFM headers, NaN/Inf texels for every filter, nan in CSVs, and the memory
# budget covering what a command allocates (device memory on a CPU device, the output image, the lookups).
# Commands that would allocate gigabytes on a regression run under a virtual memory limit, so they fail fast.
texture_values_and_budgets() {
    local limited=(bash -c 'ulimit -v 3000000 && exec "$@"' limited)
    local render=("$TEXFILTER" render --scene zoom --filter nearest "${REF[@]}")
    printf '%s\n0.5,0.5,0.01,0,0,0.01\n' "$LOOKUPS_HEADER" >values.csv
    # 32x32 PFMs: scale 0 and nan say nothing about the byte order; one 100 bytes short; one with 3 bad texels.
    python3 - <<'EOF'
import struct
def pfm(name, scale, bad=(), cut=0):
    values = [0.5] * (32 * 32 * 3)
    for x, y, c, v in bad:
        values[((31 - y) * 32 + x) * 3 + c] = v  # PFM rows run bottom first
    data = struct.pack("<%df" % len(values), *values)
    with open(name, "wb") as f:
        f.write(b"PF\n32 32\n" + scale + b"\n" + (data[:-cut] if cut else data))
pfm("scale_zero.pfm", b"0")
pfm("scale_nan.pfm", b"nan")
pfm("short.pfm", b"-1.0", cut=100)
pfm("three_bad.pfm", b"-1.0", bad=[(7, 3, 1, float("nan")), (20, 9, 0, float("inf")), (1, 30, 2, float("-inf"))])
# Finite texels that rgba16f cannot hold: +-1e6 side by side become +-Inf, and a lookup between them NaN.
values = [0.5] * 48
values[0], values[3] = 1e6, -1e6
with open("over_half.pfm", "wb") as f:
    f.write(b"PF\n4 4\n-1.0\n" + struct.pack("<48f", *values))
EOF
    oiiotool three_bad.pfm -d half -o three_bad.exr
    expect_error "PFM with scale 0" "scale_zero.pfm: bad PFM header: scale '0'" out.png -- \
        "${render[@]}" --texture scale_zero.pfm -o out.png
    expect_error "PFM with scale nan" "scale_nan.pfm: bad PFM header: scale 'nan'" out.png -- \
        "${render[@]}" --texture scale_nan.pfm -o out.png
    expect_error "PFM shorter than its header says" "short.pfm: truncated" out.png -- \
        "${render[@]}" --texture short.pfm -o out.png
    local file filter backend
    for file in three_bad.pfm three_bad.exr; do
        for backend in reference vulkan; do
            for filter in trilinear ewa bilinear sat; do
                expect_error "$file, 3 non-finite texels: sample --filter $filter --backend $backend" \
                    "$file: texel (7, 3) is NaN (channel G; 3 of 1024 texels hold NaN or Inf)" out.csv -- \
                    "$TEXFILTER" sample --texture "$file" --filter $filter --backend $backend --lookups values.csv -o out.csv
            done
        done
    done
    expect_error "3 non-finite texels: render --build gpu" "three_bad.exr: texel (7, 3) is NaN" out.png -- \
        "$TEXFILTER" render --scene plane --size 16x16 --texture three_bad.exr --filter trilinear --build gpu -o out.png
    expect_error "3 non-finite texels: an environment map" "three_bad.pfm: texel (7, 3) is NaN" out.png -- \
        "$TEXFILTER" render --scene skybox --size 16x16 --env latlong --texture three_bad.pfm --filter trilinear \
        --backend reference -o out.png
    # A NaN result is written "nan" (printf writes "-nan" for a negative one), on both backends.
    printf '%s\n0.25,0.875,0.01,0,0,0.01\n' "$LOOKUPS_HEADER" >between.csv
    for backend in reference vulkan; do
        run_command "$TEXFILTER" sample --texture over_half.pfm --format rgba16f --filter bilinear --backend $backend \
            --lookups between.csv -o nan_out.csv
        if [[ $rc -ne 0 ]] || ! grep -q '^nan,' nan_out.csv || grep -q -- '-nan' nan_out.csv; then
            fail "sample's CSV writes nan, not -nan ($backend)" "exit $rc; $(tail -1 nan_out.csv 2>/dev/null)"
        else
            pass "sample's CSV writes nan, not -nan ($backend)"
        fi
        rm -f nan_out.csv
    done
    # Every side of bench --gpu-build is checked before the first is built: nothing printed, no 9 GB allocated.
    run_command "${limited[@]}" "$TEXFILTER" bench --gpu-build --sizes 64,16384 --dynamic-size 0 --memory-budget 1G
    if [[ $rc -ne 2 ]] || ! grep -q '^texfilter: bench --gpu-build --sizes 16384' stderr || [[ -s stdout ]]; then
        fail "bench --gpu-build --sizes 64,16384 refused before any work" "exit $rc; stdout $(wc -l <stdout) lines"
    else
        pass "bench --gpu-build --sizes 64,16384 refused before any work"
    fi
    rm -f stdout stderr
    # The same by the device's own limit, where it has one the 16384^2 chain (5.3 GiB) exceeds (lavapipe: 2 GiB).
    local limit
    limit=$("$TEXFILTER" info 2>/dev/null | sed -n 's/.*maxMemoryAllocationSize \([0-9.]*\) GiB.*/\1/p' | awk 'NR == 1')
    if [[ -n $limit ]] && awk "BEGIN { exit !($limit < 5.3) }"; then
        expect_error "bench --gpu-build --sizes 64,16384 over the device's allocation limit" maxMemoryAllocationSize - -- \
            "${limited[@]}" "$TEXFILTER" bench --gpu-build --sizes 64,16384 --dynamic-size 0
    else
        skip "bench --gpu-build --sizes 64,16384 over the device's allocation limit" "no device with a limit under 5.3 GiB"
    fi
    expect_error "bench --mip-build --texture-size 16384 over the budget" "bench --mip-build --texture-size 16384" - -- \
        "${limited[@]}" "$TEXFILTER" bench --mip-build --texture-size 16384 --memory-budget 1G
    # The output image is in the budget: an 8192x8192 render holds 3-5.5 GiB, whatever its texture.
    for backend in reference vulkan; do
        expect_error "render --size 8192x8192 --memory-budget 64M ($backend)" "a 8192x8192 render" out.png -- \
            "${limited[@]}" "$TEXFILTER" render --scene plane --texture checker --filter trilinear --size 8192x8192 \
            --backend $backend --memory-budget 64M -o out.png
    done
    # So are the lookups: 200000 of them take tens of MiB.
    python3 -c "
print('$LOOKUPS_HEADER')
for i in range(200000): print('0.5,0.5,0.01,0,0,0.01')" >many.csv
    expect_error "sample: 200000 lookups over --memory-budget 16M" "200000 lookups" out.csv -- \
        "$TEXFILTER" sample --texture checker --filter trilinear --backend reference --lookups many.csv \
        --memory-budget 16M -o out.csv
    # On a CPU device (lavapipe) the device's images are the process's memory: a 2048x2048 PNG streamed to it
    # peaks near 150 MiB (level 0 staged, 64 MiB, and the chain's images, 85 MiB), not 64 MiB.
    write_constant_png k2048.png 2048 2048
    if "$TEXFILTER" info 2>/dev/null | grep -q '^texfilter would use: .*llvmpipe'; then
        expect_error "2048x2048 PNG on lavapipe over --memory-budget 100M" "the CPU device's images" out.png -- \
            "$TEXFILTER" render --scene plane --size 16x16 --texture k2048.png --filter trilinear --memory-budget 100M \
            -o out.png
    else
        skip "2048x2048 PNG on lavapipe over --memory-budget 100M" "the device is not lavapipe"
    fi
    expect_success "2048x2048 PNG under --memory-budget 400M (control)" out.png -- \
        "$TEXFILTER" render --scene plane --size 16x16 --texture k2048.png --filter trilinear --memory-budget 400M \
        -o out.png
    rm -f out.png values.csv between.csv many.csv scale_zero.pfm scale_nan.pfm short.pfm three_bad.pfm three_bad.exr \
        over_half.pfm k2048.png
}

# The groups, in order; ctest runs each as its own entry (bad_inputs.GROUP), listed by --list.
# ewa-fast: no options of its own (ewa's --alpha, --max-aniso and --taps are refused), and it needs a sampler that
# filters (no integer formats, no TF_SOURCE kinds) and a 2D texture (no environment-map form); checked before work.
bad_ewa_fast() {
    printf '%s\n0.5,0.5,0.01,0,0,0.01\n' "$LOOKUPS_HEADER" >fast.csv
    local fast=("$TEXFILTER" render --scene slanted --texture checker --filter ewa-fast "${REF[@]}")
    expect_error "ewa-fast --alpha" "--alpha is not read by --filter ewa-fast (it applies to ewa)" out.png -- \
        "${fast[@]}" --alpha 2 -o out.png
    expect_error "ewa-fast --max-aniso" "--max-aniso is not read by --filter ewa-fast (it applies to ewa)" out.png -- \
        "${fast[@]}" --max-aniso 8 -o out.png
    expect_error "ewa-fast --taps hardware" "--taps is not read by --filter ewa-fast" out.png -- \
        "${fast[@]}" --taps hardware -o out.png
    expect_error "ewa-fast --magnify bspline" "--magnify is not read by --filter ewa-fast" out.png -- \
        "${fast[@]}" --magnify bspline -o out.png
    expect_error "ewa-fast --stochastic" "--stochastic is not read by --filter ewa-fast" out.png -- \
        "${fast[@]}" --stochastic white -o out.png
    expect_error "ewa-fast --format r32ui" "--format r32ui holds integer data, which no sampler filters: --filter ewa-fast" \
        out.csv -- "$TEXFILTER" sample --texture checker --filter ewa-fast --format r32ui --lookups fast.csv -o out.csv
    expect_error "ewa-fast --resource atlas" "--resource atlas cannot run --filter ewa-fast" out.csv -- \
        "$TEXFILTER" sample --texture checker --filter ewa-fast --resource atlas --lookups fast.csv -o out.csv
    expect_error "ewa-fast on an environment scene" "--filter ewa-fast has no environment-map form" out.png -- \
        "$TEXFILTER" render --scene skybox --texture checker --filter ewa-fast "${REF[@]}" -o out.png
    expect_error "ewa-fast --lod-min above --lod-max" "--lod-min" out.png -- \
        "${fast[@]}" --lod-min 3 --lod-max 1 -o out.png
}

CASE_GROUPS=(bad_texture_files bad_flag_values bad_outputs bad_lookups sample_resources sample_spirv diff_contract ground_truth_and_bench_errors
    golden_errors vulkan_errors golden_output_directory outputs_and_inputs unwritable_outputs
    signals_remove_temporaries truncated_images memory_budgets lookups_and_texels reproducible_outputs
    bad_formats gpu_builds environment_maps
    exclusive_temporaries
    outputs_created_first
    bounded_text_inputs
    flag_rules
    texture_values_and_budgets
    oiio_peer_refusals
    oiio_peer_temporaries
    footprint_bench_errors
    bad_ewa_fast
)
if [[ ${#SELECTED[@]} -eq 0 ]]; then
    SELECTED=("${CASE_GROUPS[@]}")
fi
for group in "${SELECTED[@]}"; do
    if [[ " ${CASE_GROUPS[*]} " != *" $group "* ]]; then
        echo "bad_inputs.sh: no group '$group' (--list shows them)" >&2
        exit 2
    fi
done

positive_control
for group in "${SELECTED[@]}"; do
    started=$SECONDS
    "$group"
    echo "--- $group: $((SECONDS - started)) s"
done

echo "$passed passed, $failed failed, $skipped skipped"
[[ $failed -eq 0 ]]
