"""The atlas picture of docs/API.md "Texel sources" (tools/api_pictures.sh runs it; standard library only).

  atlas_picture.py lookups SIDE FOOTPRINT TILE > lookups.csv
      a SIDE x SIDE grid of lookups over the whole tile (pixel centres), each footprint FOOTPRINT texels of
      a TILE-texel tile (isotropic, axis-aligned)
  atlas_picture.py png SIDE LEFT.csv RIGHT.csv OUT.png
      two `sample` outputs of those lookups side by side, 8 white pixels apart, as an 8-bit sRGB PNG
"""
import struct
import sys
import zlib

GAP = 8


def lookups(side, footprint, tile):
    d = footprint / tile
    print("u,v,dudx,dvdx,dudy,dvdy")
    for y in range(side):
        for x in range(side):
            print(f"{(x + 0.5) / side!r},{(y + 0.5) / side!r},{d!r},0,0,{d!r}")


def srgb(c):
    c = min(max(c, 0.0), 1.0)
    return round(255 * (12.92 * c if c <= 0.0031308 else 1.055 * c ** (1 / 2.4) - 0.055))


def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)


def png(side, left, right, out):
    panels = []
    for path in (left, right):
        with open(path) as f:
            next(f)  # header r,g,b,a
            panels.append([bytes(srgb(float(c)) for c in line.split(",")[:3]) for line in f])
        if len(panels[-1]) != side * side:
            sys.exit(f"atlas_picture.py: {path} has {len(panels[-1])} rows, not {side * side}")
    rows = bytearray()
    for y in range(side):
        rows += b"\x00"  # PNG filter type: none
        rows += b"".join(panels[0][y * side:(y + 1) * side]) + b"\xff" * (3 * GAP)
        rows += b"".join(panels[1][y * side:(y + 1) * side])
    header = struct.pack(">IIBBBBB", 2 * side + GAP, side, 8, 2, 0, 0, 0)  # 8-bit RGB
    data = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"sRGB", b"\x00")
    data += chunk(b"IDAT", zlib.compress(bytes(rows), 9)) + chunk(b"IEND", b"")
    with open(out, "wb") as f:
        f.write(data)


if __name__ == "__main__":
    if len(sys.argv) == 5 and sys.argv[1] == "lookups":
        lookups(*(int(a) for a in sys.argv[2:]))
    elif len(sys.argv) == 6 and sys.argv[1] == "png":
        png(int(sys.argv[2]), *sys.argv[3:])
    else:
        sys.exit(__doc__)
