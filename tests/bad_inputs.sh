#!/usr/bin/env bash
# Bad input must give a clear error, exit status 2 (1 only for a failed `diff`), no crash, and no
# output file (not even a half-written temporary one).
#
# usage: bad_inputs.sh TEXFILTER
#
# Everything that is not about Vulkan uses --backend reference, so the script is fast and needs no
# GPU. The Vulkan cases fake a machine without a driver through the loader's environment variables;
# the --device case is skipped where no Vulkan device is usable at all.
set -euo pipefail

if [[ $# -ne 1 ]]; then
    echo "usage: $0 TEXFILTER" >&2
    exit 2
fi
TEXFILTER=$(realpath "$1")
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

# Temporary outputs are named OUT.tmp-PID; any left behind means a failure path forgot to clean up.
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
    # Quad derivatives: bad values, and combinations the mesh scene cannot do.
    expect_error "--stage bogus" --stage out.png -- "${RENDER[@]}" --stage bogus -o out.png
    expect_error "--derivatives bogus" --derivatives out.png -- "${RENDER[@]}" --derivatives bogus -o out.png
    expect_error "mesh in the compute stage" "mesh scene is rasterized" out.png -- \
        "$TEXFILTER" render --scene mesh --texture checker --filter nearest "${REF[@]}" --stage compute -o out.png
    expect_error "mesh with ray differentials" "ray differentials need a ray-cast scene" out.png -- \
        "$TEXFILTER" render --scene mesh --texture checker --filter nearest "${REF[@]}" --derivatives ray -o out.png
}

bad_outputs() {
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
    expect_error "sample: --stats with the reference backend" --stats out.csv -- \
        "${SAMPLE[@]}" --lookups good.csv --stats -o out.csv
    expect_error "sample: -o in a missing directory" /nonexistent/dir/out.csv /nonexistent/dir/out.csv -- \
        "${SAMPLE[@]}" --lookups good.csv -o /nonexistent/dir/out.csv
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
    expect_error "sample --filter ground-truth" ground-truth out.csv -- \
        "$TEXFILTER" sample --texture checker --filter ground-truth --lookups good.csv --backend reference -o out.csv
    local bench=("$TEXFILTER" bench --quick --scenes zoom)
    expect_error "bench --filters bogus" bogus bench-out -- "${bench[@]}" --filters bogus --out bench-out
    expect_error "bench --scenes bogus" bogus bench-out -- "$TEXFILTER" bench --quick --scenes bogus --out bench-out
    expect_error "bench --spp 10" --spp bench-out -- "${bench[@]}" --spp 10 --out bench-out
    expect_error "bench --frames 0" --frames bench-out -- "${bench[@]}" --frames 0 --out bench-out
    expect_error "bench --flicker-frames 1" --flicker-frames bench-out -- "${bench[@]}" --flicker-frames 1 --out bench-out
    expect_error "bench --timer bogus" bogus bench-out -- "${bench[@]}" --timer bogus --out bench-out
    expect_error "bench without --out" --out - -- "${bench[@]}"
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

golden_errors() {
    expect_error "golden --case nonexistent" nonexistent golden-out -- \
        "$TEXFILTER" golden --case nonexistent --out golden-out
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

positive_control
bad_texture_files
bad_flag_values
bad_outputs
bad_lookups
diff_contract
ground_truth_and_bench_errors
golden_errors
vulkan_errors

echo "$passed passed, $failed failed, $skipped skipped"
[[ $failed -eq 0 ]]
