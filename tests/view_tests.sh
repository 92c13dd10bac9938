#!/usr/bin/env bash
# The viewer in a real window: texfilter view --script under Xvfb (lavapipe presents there), with the
# validation layers on (any message fails the viewer's run, exit 2).
#
# usage: view_tests.sh TEXFILTER XWD_COMPARE GROUP   (--list names the groups; one ctest entry each)
#
# Screenshots are read back from the swapchain; each writes beside it the `texfilter render` lines that
# reproduce it offscreen, which this script runs and compares: the same renderer, so the only difference
# allowed is the sRGB encode of the 8-bit swapchain against the PNG writer's (one 8-bit step).
set -euo pipefail

CASE_GROUPS=(no-display bad-script scene-plane scene-tunnel scene-zoom scene-minify scene-slanted scene-triangles
             scene-mesh split debug-views truth camera state x-capture window-events ui dynamic-texture alpha
             side-files)
if [[ ${1:-} == --list ]]; then
    printf '%s\n' "${CASE_GROUPS[@]}"
    exit 0
fi
if [[ $# -ne 3 ]]; then
    echo "usage: $0 TEXFILTER XWD_COMPARE GROUP   (or: $0 --list)" >&2
    exit 2
fi
TEXFILTER=$(realpath "$1")
XWD_COMPARE=$(realpath "$2")
GROUP=$3
export TEXFILTER_VALIDATE=1
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
cd "$WORK"
SIZE=256x256
# One 8-bit sRGB step: the swapchain's encode against the PNG writer's (both from the same float pixels).
ONE_STEP=0.0040

failed=0
pass() { echo "PASS  $1"; }
fail() {
    echo "FAIL  $1: $2"
    for f in view.stderr stderr; do [[ -s $f ]] && sed "s/^/      $f| /" "$f"; done
    failed=1
}

# with_xvfb SCREEN COMMAND...: runs COMMAND with DISPLAY on an X server of its own (SCREEN: WxHxDEPTH), stopped
# afterwards; returns COMMAND's status. Xvfb picks a free display and writes its number to -displayfd's
# descriptor, so two tests never race for one (xvfb-run -a can), and nothing is left in /tmp.
with_xvfb() {
    local screen=$1 xvfb status=0
    shift
    : >display.txt # emptied before Xvfb starts: the wait below must not read an earlier server's number
    Xvfb -displayfd 3 -screen 0 "$screen" -nolisten tcp 3>display.txt >xvfb.log 2>&1 &
    xvfb=$!
    for _ in $(seq 100); do [[ -s display.txt ]] && break; sleep 0.1; done
    if [[ ! -s display.txt ]]; then
        kill "$xvfb" 2>/dev/null || true
        echo "Xvfb did not start: $(cat xvfb.log)" >&2
        return 1
    fi
    DISPLAY=:$(head -n1 display.txt) "$@" || status=$?
    kill "$xvfb" 2>/dev/null || true
    wait "$xvfb" 2>/dev/null || true
    return "$status"
}

# view SCRIPT_TEXT [FLAGS...]: runs the viewer on a script under its own X server; sets rc.
view() {
    printf '%s\n' "$1" >script.txt
    shift
    rc=0
    with_xvfb 1280x1024x24 timeout 300 "$TEXFILTER" view --script script.txt --size "$SIZE" "$@" \
        >view.stdout 2>view.stderr || rc=$?
}

# render_like SHOT.png LINE OUT.png: runs line LINE of SHOT.txt (a texfilter render command) with -o OUT.png.
render_like() {
    local shot=$1 number=$2 out=$3 line
    line=$(sed -n "${number}p" "${shot%.png}.txt")
    [[ $line == "texfilter render "* ]] || { echo "no render line $number in ${shot%.png}.txt" >stderr; return 1; }
    # The line ends in -o PATH; the test writes its own file instead.
    eval "set -- ${line#texfilter render }"
    local args=()
    while [[ $# -gt 0 ]]; do
        if [[ $1 == -o ]]; then shift 2; continue; fi
        args+=("$1"); shift
    done
    "$TEXFILTER" render "${args[@]}" -o "$out" 2>stderr >/dev/null
}

# same_as_render DESCRIPTION SHOT.png: the screenshot equals its render line within one 8-bit step.
same_as_render() {
    if ! render_like "$2" 1 offscreen.png; then
        fail "$1" "the render line of $2 failed"
    elif ! "$TEXFILTER" diff "$2" offscreen.png --fail "$ONE_STEP" >diff.out 2>stderr; then
        fail "$1" "screenshot and render differ: $(cat diff.out)"
    else
        pass "$1"
    fi
}

# view_and_capture SHOT.json: runs script.txt under its own X server (640x480) and, once SHOT.json is written
# and the script holds its frame, captures the X root into root.xwd (the server is the test's own); sets rc.
view_and_capture() {
    rc=0
    with_xvfb 640x480x24 bash -c '
        "$1" view --script script.txt --size 256x256 >view.stdout 2>view.stderr & pid=$!
        for i in $(seq 600); do [[ -s $2 ]] && break; sleep 0.1; done
        sleep 1
        xwd -root -screen -silent -out root.xwd
        wait $pid' _ "$TEXFILTER" "$1" || rc=$?
}

viewer_ok() { # DESCRIPTION: the viewer ran the script to the end, exit 0, no validation message
    if [[ $rc -ne 0 ]]; then
        fail "$1" "view exited $rc"
        return 1
    elif grep -q "validation" view.stderr; then
        fail "$1" "validation messages"
        return 1
    fi
    return 0
}

scene_group() { # SCENE: each filter's screenshot equals texfilter render of its printed line
    local scene=$1 script="scene $1
texture checker --texture-size 64
ui off" filters=(trilinear)
    # and one more family a scene, so that every family is on the window somewhere
    case $scene in
    plane) filters+=(ewa) ;; tunnel) filters+=(aniso) ;; zoom) filters=(bilinear nearest) ;;
    minify) filters+=(sat) ;; slanted) filters+=(aniso) ;; triangles) filters+=(brilinear) ;; mesh) filters+=(ewa) ;;
    esac
    for f in "${filters[@]}"; do script+="
filter $f
screenshot $scene-$f.png"; done
    script+="
quit"
    view "$script"
    viewer_ok "view $scene" || return
    for f in "${filters[@]}"; do same_as_render "$scene $f: swapchain screenshot = texfilter render" "$scene-$f.png"; done
}

case $GROUP in
no-display)
    rc=0
    env -u DISPLAY "$TEXFILTER" view --size 64x64 >stdout 2>stderr || rc=$?
    if [[ $rc -eq 2 ]] && grep -q "DISPLAY" stderr && grep -q "xvfb-run" stderr && [[ $(wc -l <stderr) -eq 1 ]]; then
        pass "no display: one sentence, exit 2"
    else
        fail "no display" "exit $rc, expected 2 and one line naming DISPLAY and xvfb-run"
    fi
    ;;
bad-script)
    printf 'scene plane\nfilter nosuchfilter\n' >bad.txt
    rc=0
    env -u DISPLAY "$TEXFILTER" view --script bad.txt >stdout 2>stderr || rc=$?
    if [[ $rc -eq 2 ]] && grep -q "bad.txt:2" stderr; then pass "bad script line named before any window"; else
        fail "bad script" "exit $rc; expected 2 and bad.txt:2 on stderr"; fi
    # A screenshot whose .txt is the script itself: refused before any window, the script kept.
    printf 'screenshot self.png\nquit\n' >self.txt
    sum=$(cksum <self.txt)
    rc=0
    env -u DISPLAY "$TEXFILTER" view --script self.txt >stdout 2>stderr || rc=$?
    if [[ $rc -eq 2 ]] && grep -q "self.txt:1: screenshot" stderr && [[ $(cksum <self.txt) == "$sum" && ! -e self.png ]]; then
        pass "a screenshot onto the script refused before any window"; else
        fail "screenshot onto the script" "exit $rc, $(head -c 300 stderr); expected 2 naming self.txt:1, the script unchanged"; fi
    # A screenshot's .txt that this viewer did not write (here: someone's notes): refused before any window,
    # naming it, and nothing written.
    echo "my notes" >notes.txt
    printf 'screenshot notes.png\nquit\n' >notes-script.txt
    rc=0
    env -u DISPLAY "$TEXFILTER" view --script notes-script.txt >stdout 2>stderr || rc=$?
    if [[ $rc -eq 2 ]] && grep -q "notes-script.txt:1: screenshot: notes.txt: exists, and this viewer did not write it" stderr &&
        [[ $(cat notes.txt) == "my notes" && ! -e notes.png && ! -e notes.json ]]; then
        pass "a screenshot over an existing .txt refused before any window"; else
        fail "screenshot over an existing .txt" "exit $rc, $(head -c 300 stderr); expected 2 naming notes.txt, it unchanged, no notes.png"; fi
    ;;
scene-*) scene_group "${GROUP#scene-}" ;;
split)
    view "texture checker --texture-size 64
filter trilinear
compare ewa
divider 0.5
ui off
screenshot split.png
stage compute
screenshot split-compute.png
quit"
    viewer_ok split || exit 1
    # Fragment stage: the window is made by blits from the render targets; compute stage: by the composition
    # pass from the pixel buffers. Both must show the renders.
    for shot in split split-compute; do
        [[ $(wc -l <$shot.txt) -eq 2 ]] || fail $shot "$shot.txt should hold two render lines"
        render_like $shot.png 1 a.png && render_like $shot.png 2 b.png || fail $shot "render lines failed"
        # left half from A's render, right half from B's: A's left half (the foreground) pasted over B's render.
        oiiotool a.png --cut 128x256+0+0 b.png --paste +0+0 -o expected.png 2>stderr
        if "$TEXFILTER" diff $shot.png expected.png --fail "$ONE_STEP" >diff.out 2>stderr; then
            pass "$shot: left = A's render, right = B's"; else fail $shot "$(cat diff.out)"; fi
    done
    ;;
debug-views)
    script="scene slanted
texture checker --texture-size 64
ui off"
    for v in lod anisotropy fetches; do script+="
filter aniso
view $v
screenshot view-$v.png"; done
    view "$script
quit"
    viewer_ok debug-views || exit 1
    for v in lod anisotropy fetches; do same_as_render "debug view $v = texfilter render --view $v" "view-$v.png"; done
    ;;
truth)
    view "scene minify
texture checker --texture-size 64
filter trilinear --spp 16
truth on
ui off
screenshot truth.png
view error
screenshot error.png
quit"
    viewer_ok truth || exit 1
    render_like truth.png 2 gt.png || fail truth "ground-truth line failed"
    oiiotool truth.png --cut 128x256+128+0 -o right.png && oiiotool gt.png --cut 128x256+128+0 -o gt-right.png
    if "$TEXFILTER" diff right.png gt-right.png --fail "$ONE_STEP" >diff.out 2>stderr; then
        pass "truth: progressive accumulation = texfilter render --filter ground-truth"; else fail truth "$(cat diff.out)"; fi
    ;;
camera)
    view "scene plane
texture checker --texture-size 64
ui off
camera fly 0.1 0.05 0.3
camera turn 10 -5
frame 7
screenshot moved.png
camera reset
frame 0
screenshot home.png
quit"
    viewer_ok camera || exit 1
    grep -q -- "--camera" moved.txt && grep -q -- "--frame 7" moved.txt || fail camera "moved.txt lacks --camera/--frame"
    same_as_render "moved camera and frame 7 = texfilter render --camera --frame" moved.png
    if "$TEXFILTER" diff moved.png home.png >/dev/null 2>&1; then fail camera "the camera did not move the image"; else
        pass "the camera moves the image"; fi
    ;;
state)
    view "scene tunnel
texture grid --texture-size 64
filter ewa --alpha 3
ui off
screenshot first.png
quit"
    viewer_ok "state: first" || exit 1
    view "ui off
screenshot again.png
quit" --state first.json
    viewer_ok "state: again" || exit 1
    if cmp -s first.png again.png; then pass "--state reproduces the screenshot bit for bit"; else
        fail state "the screenshot from --state differs"; fi
    # A screenshot whose .json is the --state file: refused before any window, the state kept.
    printf 'screenshot first.png\nquit\n' >onto-state.txt
    sum=$(cksum <first.json)
    rc=0
    env -u DISPLAY "$TEXFILTER" view --state first.json --script onto-state.txt >stdout 2>stderr || rc=$?
    if [[ $rc -eq 2 ]] && grep -q "first.json" stderr && [[ $(cksum <first.json) == "$sum" ]]; then
        pass "a screenshot onto the --state file refused before any window"; else
        fail "screenshot onto --state" "exit $rc, $(head -c 300 stderr); expected 2 naming first.json, it unchanged"; fi
    ;;
x-capture)
    printf '%s\n' "texture zoneplate --texture-size 64" "ui off" "screenshot shown.png" "hold 6000" "quit" >script.txt
    view_and_capture shown.json
    viewer_ok x-capture || exit 1
    if "$XWD_COMPARE" root.xwd shown.png --at 0,0 >cmp.out 2>stderr; then
        pass "X-side capture of the window = swapchain readback"; else fail x-capture "$(cat cmp.out)"; fi
    ;;
window-events)
    view "texture checker --texture-size 64
ui off
screenshot before.png
resize 320x200
wait 3
screenshot resized.png
minimize
wait 5
restore
wait 3
texture /nonexistent/texture.png
resize 256x256
wait 3
screenshot after.png
close"
    viewer_ok window-events || exit 1
    grep -q "/nonexistent/texture.png" view.stderr || fail window-events "no message for the bad texture path"
    read -r w h < <(oiiotool --info resized.png | sed -n 's/.* : *\([0-9]*\) x *\([0-9]*\).*/\1 \2/p')
    [[ "$w $h" == "320 200" ]] || fail window-events "resized screenshot is ${w}x${h}, expected 320x200"
    same_as_render "after resize: screenshot = render" resized.png
    if cmp -s before.png after.png; then pass "resize, minimise, restore and a bad texture keep the frame"; else
        fail window-events "the frame after the bad texture differs from before"; fi
    ;;
ui)
    view "texture checker --texture-size 64
screenshot-ui whole.png
ui off
screenshot bare.png
quit"
    viewer_ok ui || exit 1
    if "$TEXFILTER" diff whole.png bare.png >/dev/null 2>&1; then fail ui "the UI screenshot shows no panels"; else
        pass "screenshot-ui holds the panels, screenshot does not"; fi
    ;;
dynamic-texture)
    # --build gpu: the texture is made and built on the device every drawn frame; each screenshot's line names
    # its frame (--texture-frame) and renders it the offscreen way (level 0 uploaded, the chain built there).
    # (--build cpu and --texture-frame on other textures: tests/test_view_state.cpp, no window needed.)
    view "ui off
wait 3
screenshot animated.png
texture-animate on
wait 4
screenshot later.png
texture-frame 40
screenshot chosen.png
filter sat
screenshot still.png
quit" --texture dynamic --texture-size 128 --build gpu --filter trilinear
    viewer_ok "dynamic texture" || exit 1
    frames=()
    for shot in animated later chosen; do
        frames+=("$(sed -n 's/.*--texture-frame \([0-9]*\).*/\1/p' $shot.txt)")
        grep -q -- "--build gpu" $shot.txt || fail $shot "$shot.txt lacks --build gpu"
    done
    # wait N draws N frames, each one texture frame on; a screenshot stops the animation where it is.
    [[ "${frames[*]}" == "3 7 40" ]] || fail dynamic-texture "texture frames ${frames[*]}, expected 3 7 40"
    # Two frames (animated to, and set) each equal their render; frames differ from each other.
    for shot in animated chosen; do
        same_as_render "dynamic texture $shot: screenshot = texfilter render --texture-frame --build gpu" $shot.png
    done
    for pair in "animated later" "animated chosen"; do
        set -- $pair
        if "$TEXFILTER" diff $1.png $2.png >/dev/null 2>&1; then fail dynamic-texture "$1 and $2 look the same"; else
            pass "the texture moves: $1 and $2 differ"; fi
    done
    grep -q "sat filters need a static texture" view.stderr || fail dynamic-texture "no message refusing sat"
    if cmp -s chosen.png still.png; then pass "sat refused on the dynamic texture, the frame kept"; else
        fail dynamic-texture "the frame changed after the refused sat filter"; fi
    ;;
alpha)
    # A texture whose alpha varies (0..255) with a colour that does not follow it: the screenshot's PNG is the
    # render line's RGBA (straight alpha, as render -o writes it), from the blits (fragment stage) and from the
    # composition pass (compute stage); the window shows the colour as rendered, alpha not applied (the X
    # server's capture of it equals the screenshot's RGB).
    python3 - <<'PYTHON'
import struct, zlib
size = 64
rows = b"".join(b"\0" + bytes(v for x in range(size) for v in
                              ((x * 4) % 256, (y * 4) % 256, ((x ^ y) * 8) % 256, (x * 37 + y * 91) % 256))
                for y in range(size))
def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff)
ihdr = struct.pack(">IIBBBBB", size, size, 8, 6, 0, 0, 0)  # 8-bit RGBA
with open("rgba.png", "wb") as f:
    f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))
PYTHON
    printf '%s\n' "scene tunnel" "texture rgba.png" "filter trilinear" "ui off" "screenshot alpha.png" "hold 6000" \
        "stage compute" "filter aniso" "screenshot alpha-compute.png" "quit" >script.txt
    view_and_capture alpha.json
    viewer_ok alpha || exit 1
    for shot in alpha alpha-compute; do
        # The case proves something only where the alpha is far from 1: the render's PNG goes below 32 of 255.
        render_like $shot.png 1 offscreen.png || fail $shot "its render line failed"
        min_alpha=$(oiiotool --iconfig oiio:UnassociatedAlpha 1 offscreen.png --printstats 2>/dev/null |
            sed -n 's/.*Stats Min: *[0-9.]* [0-9.]* [0-9.]* \([0-9]*\).*/\1/p')
        [[ -n $min_alpha && $min_alpha -lt 32 ]] ||
            fail $shot "the render's alpha stays at or above 32 of 255 (min '$min_alpha'): the case proves nothing"
        same_as_render "alpha $shot: screenshot RGBA = texfilter render's" $shot.png
    done
    if "$XWD_COMPARE" root.xwd alpha.png --at 0,0 >cmp.out 2>stderr; then
        pass "alpha: the window shows the rendered colour, not composited (X capture = the screenshot's RGB)"; else
        fail alpha "$(cat cmp.out)"; fi
    ;;
side-files)
    # A screenshot replaces its own files from earlier in the run, and refuses one that appeared since the
    # script was checked (someone's late.txt, made while the viewer holds), naming it, writing nothing.
    printf '%s\n' "texture checker --texture-size 64" "ui off" "screenshot twice.png" "camera fly 0.1 0.05 0.3" \
        "screenshot twice.png" "hold 5000" "screenshot late.png" "quit" >script.txt
    rc=0
    with_xvfb 640x480x24 bash -c '
        "$1" view --script script.txt --size 256x256 >view.stdout 2>view.stderr & pid=$!
        for i in $(seq 600); do grep -q -- --camera twice.txt 2>/dev/null && break; sleep 0.1; done
        echo "my notes" >late.txt
        wait $pid' _ "$TEXFILTER" || rc=$?
    if [[ $rc -eq 2 ]] && grep -q "script.txt:7: late.txt: exists, and this viewer did not write it" view.stderr &&
        [[ $(cat late.txt) == "my notes" && ! -e late.png && ! -e late.json ]]; then
        pass "a screenshot over a file that appeared while the viewer ran: refused, naming it"; else
        fail side-files "exit $rc; expected 2 naming script.txt:7 and late.txt, it unchanged, no late.png"; fi
    grep -q "validation" view.stderr && fail side-files "validation messages"
    if grep -q -- "--camera" twice.txt; then
        same_as_render "the second screenshot replaced the first's files (its own)" twice.png; else
        fail side-files "twice.txt is the first screenshot's: the second did not replace it"; fi
    ;;
*) echo "unknown group $GROUP" >&2; exit 2 ;;
esac
exit $failed
