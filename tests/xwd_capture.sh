#!/usr/bin/env bash
# The X-side capture path end to end, as the viewer's tests use it: a known image shown on an Xvfb screen
# (xwud displays a dump written here, in a window titled "xwud: NAME"), `xwd -root` captures the screen, and
# xwd_compare finds the image at the window's position exactly (exit 0) and not one pixel off (exit 1).
# usage: xwd_capture.sh XWD_COMPARE   (exit 77, ctest's skip, where Xvfb, xwd, xwud or xwininfo is missing)
set -euo pipefail
XWD_COMPARE=$(realpath "$1")
for tool in Xvfb xwd xwud xwininfo python3; do
    if ! command -v "$tool" > /dev/null; then
        echo "SKIP: $tool is not installed (tools/setup.sh installs xvfb and x11-apps)"
        exit 77
    fi
done

WORK=$(mktemp -d)
pids=()
cleanup() {
    for pid in "${pids[@]}"; do kill "$pid" 2> /dev/null || true; done
    wait 2> /dev/null || true
    rm -rf "$WORK"
}
trap cleanup EXIT
cd "$WORK"

# A 64x48 pattern (every pixel a different colour) as a PNG and as a depth-24 TrueColor XWD for xwud.
python3 - <<'PY'
import struct, zlib
w, h, name = 64, 48, b"texfilter-xwd-check\0"
def colour(x, y): return (x * 4 + 1, y * 5 + 2, (x * 7 + y * 11) % 256)
def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff)
rows = b"".join(b"\0" + bytes(c for x in range(w) for c in colour(x, y)) for y in range(h))
with open("pattern.png", "wb") as f:
    f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))
header = [100 + len(name), 7, 2, 24, w, h, 0, 0, 32, 0, 32, 32, 4 * w, 4, 0xff0000, 0xff00, 0xff, 8, 256, 0,
          w, h, 0, 0, 0]  # ... ZPixmap, depth 24, LSBFirst, 32 bpp, TrueColor, masks, no colour entries
pixels = b"".join(struct.pack("<I", r << 16 | g << 8 | b) for y in range(h) for x in range(w) for r, g, b in [colour(x, y)])
with open("pattern.xwd", "wb") as f:
    f.write(struct.pack(">25I", *header) + name + pixels)
PY

# A free display: Xvfb picks it and writes its number to the descriptor -displayfd names.
exec 3> display.txt
Xvfb -displayfd 3 -screen 0 320x240x24 -nolisten tcp > xvfb.log 2>&1 &
pids+=($!)
exec 3>&-
for _ in $(seq 100); do [[ -s display.txt ]] && break; sleep 0.1; done
[[ -s display.txt ]] || { echo "FAIL: Xvfb did not start"; cat xvfb.log; exit 1; }
export DISPLAY=:$(head -n1 display.txt)
echo "Xvfb on $DISPLAY"

xwud -in pattern.xwd -geometry +20+30 > xwud.log 2>&1 &
pids+=($!)
# Mapping and drawing are asynchronous: capture until the pattern is there (or give up after 10 s).
for _ in $(seq 50); do
    if info=$(xwininfo -name "xwud: texfilter-xwd-check" 2> /dev/null); then
        x=$(sed -n 's/.*Absolute upper-left X: *//p' <<< "$info")
        y=$(sed -n 's/.*Absolute upper-left Y: *//p' <<< "$info")
        xwd -root -silent -out root.xwd
        if "$XWD_COMPARE" root.xwd pattern.png --at "$x,$y" > compare.txt; then
            cat compare.txt
            echo "PASS: the pattern shown at $x,$y is in the root capture exactly"
            rc=0
            "$XWD_COMPARE" root.xwd pattern.png --at "$((x + 1)),$y" > shifted.txt || rc=$?
            cat shifted.txt
            if [[ $rc -ne 1 ]]; then
                echo "FAIL: one pixel to the right should differ (exit 1), got exit $rc"
                exit 1
            fi
            echo "PASS: one pixel off differs"
            exit 0
        fi
    fi
    sleep 0.2
done
echo "FAIL: the pattern never appeared in the root capture"
cat compare.txt 2> /dev/null || true
cat xwud.log
exit 1
