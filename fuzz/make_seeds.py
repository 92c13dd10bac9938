#!/usr/bin/env python3
"""Writes the fuzz targets' seed corpus, fuzz/corpus/<target>/ (run once; the output is committed).

Text seeds are spelled out here; image seeds are tiny files made by oiiotool (Debian's openimageio-tools,
which tools/setup.sh installs) plus PFM files written by hand, so every format the image target sniffs
(PNG, JPEG, EXR, TIFF, PFM) starts from a valid file of a few hundred bytes. The reference-filter seeds
follow the byte layout documented at the top of fuzz/fuzz_reference_filters.cpp.

    python3 fuzz/make_seeds.py          # rewrites fuzz/corpus/ (deterministic, stdlib only)
"""
import os
import shutil
import struct
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
CORPUS = os.path.join(HERE, "corpus")


def write(target, name, data):
    folder = os.path.join(CORPUS, target)
    os.makedirs(folder, exist_ok=True)
    if isinstance(data, str):
        data = data.encode("utf-8")
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data)


def lookups_csv():
    header = "u,v,dudx,dvdx,dudy,dvdy\n"
    write("lookups_csv", "valid.csv", header + "0.5,0.5,0.00390625,0,0,0.00390625\n0.1,0.9,0.01,0.002,-0.003,0.02\n")
    write("lookups_csv", "bom-crlf.csv", "\ufeff" + header.replace("\n", "\r\n") + "0.25, 0.75 ,0,0,0,0\r\n\r\n")
    write("lookups_csv", "extremes.csv",
          header + "nan,inf,-inf,1e300,-0,4.9e-324\n1e37,-1e154,0x1p-3,1e100,2.2250738585072014e-308,1\n")
    write("lookups_csv", "spaces-blank.csv", " u , v ,dudx,dvdx,dudy,dvdy \n\n  \t\n0,0,0,0,0,0\n")
    write("lookups_csv", "bad-header.csv", "u,v,dudx,dvdx\n0,0,0,0\n")
    write("lookups_csv", "bad-number.csv", header + "0.5,0.5,abc,0,0,0\n")
    write("lookups_csv", "seven-values.csv", header + "1,2,3,4,5,6,7\n1,2,3\n")
    write("lookups_csv", "empty-cell.csv", header + "1,,3,4,5,6\n")


def manifest():
    write("manifest", "cases.txt",
          "# comment\n"
          "plane-checker-trilinear plane checker trilinear lod-bias=1\n"
          "tunnel-mipcolors-clamp tunnel mipcolors trilinear lod-min=1 lod-max=3 wrap=clamp\n"
          "zoom-noise zoom noise bilinear texture-size=64 size=128x64 fail=0.01 failpercent=0.5 hardfail=0.2\n"
          "slanted-ewa slanted zoneplate ewa alpha=3 max-aniso=8 taps=hardware  # trailing comment\n"
          "minify-aniso minify grid aniso probes=8 aniso-shape=feline stage=compute derivatives=coarse\n"
          "plane-sat plane checker sat-assembly boxes=6\n"
          "mesh-bri mesh checker brilinear band=0.5 derivatives=ray\n")
    write("manifest", "errors.txt", "a plane checker\nb plane checker nearest size=1x1\n")
    write("manifest", "duplicate.txt", "x plane checker nearest\nx plane checker nearest\n")
    write("manifest", "unknown-key.txt", "y plane checker nearest colour=red\nz plane checker nearest wrap\n")


def args():
    def argv(max_positional, *tokens):
        return bytes([max_positional]) + b"\0".join(t.encode() for t in tokens)
    write("args", "render.bin", argv(0, "--scene", "plane", "--texture", "checker", "--filter", "ewa", "--size",
                                     "256x128", "--alpha", "3", "--max-aniso", "8", "-o", "out.png"))
    write("args", "inline.bin", argv(1, "--texture=noise", "--texture-size=64", "--filter=aniso", "--probes=4",
                                     "--aniso-shape=feline", "--taps=hardware", "--wrap=mirror", "positional"))
    write("args", "lod.bin", argv(0, "--texture", "x.png", "--linear", "--filter", "trilinear", "--lod-bias",
                                  "-1.5", "--lod-min", "2", "--lod-max", "1", "--backend", "reference"))
    write("args", "truth.bin", argv(0, "--texture", "grid", "--filter", "ground-truth", "--pixel-filter",
                                    "gaussian", "--spp", "64", "--device", "0", "--validate", "--stats"))
    write("args", "errors.bin", argv(0, "--size", "0x99999999999999999999", "--band", "nan", "--boxes", "17",
                                     "--unknown", "--filter"))


def pfm_bytes(width, height, values, little=True):
    header = b"PF\n%d %d\n%s\n" % (width, height, b"-1.0" if little else b"1.0")
    return header + struct.pack(("<" if little else ">") + "%df" % len(values), *values)


def pfm():
    write("pfm", "2x1-little.pfm", pfm_bytes(2, 1, [0.0, 0.5, 1.0, -2.0, 1e30, float("inf")]))
    write("pfm", "1x2-big.pfm", pfm_bytes(1, 2, [0.25, 0.5, 0.75, float("nan"), -0.0, 3.0], little=False))
    write("pfm", "truncated.pfm", pfm_bytes(2, 2, [0.1] * 11))
    write("pfm", "grey.pfm", b"Pf\n1 1\n-1.0\n" + struct.pack("<f", 0.5))


def images():
    oiiotool = shutil.which("oiiotool")
    if not oiiotool:
        sys.exit("make_seeds.py: oiiotool not found (Debian: openimageio-tools, see tools/setup.sh)")
    checker = "--pattern checker:width=2:height=2:color1=0.1,0.5,0.9:color2=1,0.2,0"
    ramp = "--pattern fill:topleft=0,0,0,1:topright=1,0,0,1:bottomleft=0,1,0,1:bottomright=0,0,1,0.5"
    made = [  # name, oiiotool arguments before -o
        ("rgb8.png", checker + " 8x8 3 -d uint8"),
        ("grey-alpha16.png", ramp + " 4x4 4 --ch R,A -d uint16"),
        ("rgb.jpg", checker + " 8x8 3 -d uint8"),
        ("rgba-half.exr", ramp + " 4x4 4 -d half --compression none"),
        ("rgb-float-zip.exr", ramp + " 4x2 3 -d float --compression zip"),
        ("rgb16.tif", checker + " 4x4 3 -d uint16 --compression none"),
        ("grey-float.tif", ramp + " 3x5 1 -d float --compression none"),
    ]
    with tempfile.TemporaryDirectory() as tmp:
        # A fixed DateTime (oiiotool writes the current time otherwise) keeps the seeds reproducible.
        for name, arguments in made:
            out = os.path.join(tmp, name)
            fixed_date = ["--attrib", "DateTime", "2026:01:01 00:00:00"]
            subprocess.run([oiiotool, "--nosoftwareattrib"] + arguments.split() + fixed_date + ["-o", out], check=True)
            with open(out, "rb") as f:
                write("image", name, f.read())
    write("image", "rgb.pfm", pfm_bytes(2, 2, [0.0, 0.25, 0.5, 0.75, 1.0, 2.0, 1e-3, 0.5, 0.5, 0.1, 0.2, 0.3]))


def reference_filters():
    # Options bytes [0..13] (see fuzz_reference_filters.cpp), then 6 selector-coded values a lookup.
    def options(kind, width, height, wrap=0, bias=128, lod_min=0, lod_max=255, band=64, probes=15, bits=0,
                alpha=32, max_aniso=60, boxes=3, lookups=1):
        return bytes([kind, width, height, wrap, bias, lod_min, lod_max, band, probes, bits, alpha, max_aniso,
                      boxes, lookups - 1])

    def special(index):  # index into the specials table
        return bytes([index])

    def uv(x):  # s in [96, 160): ((s - 96) * 256 + b) / 8192 - 1
        code = int(round((x + 1.0) * 8192))
        return bytes([96 + code // 256, code % 256])

    def scaled(mantissa_code, exponent):  # s >= 160: +-(s - 160) / 95 * 2^(b - 128)
        return bytes([160 + mantissa_code, exponent + 128])

    def raw(x):
        return bytes([64]) + struct.pack("<d", x)

    texel_bytes = bytes((i * 37) % 256 for i in range(4 * 6 * 5))
    ZERO, NAN, INF, NINF, E300, E154, E100, E37, DENORM = (special(i) for i in (0, 2, 4, 5, 6, 8, 10, 11, 17))
    write("reference_filters", "plain.bin",
          options(0, 15, 15) + uv(0.3) + uv(0.6) + uv(1 / 64) + uv(0) + uv(0) + uv(1 / 64))
    write("reference_filters", "anisotropic.bin",
          options(2, 31, 31, wrap=1, bits=1, probes=7, lookups=2) + uv(0.5) + uv(0.5) + uv(0.25) + uv(0.01) +
          uv(-0.01) + uv(0.002) + uv(0.9) + uv(0.1) + scaled(95, -3) + scaled(40, -10) + ZERO + scaled(94, -2))
    write("reference_filters", "extremes.bin",
          options(5, 5, 4, wrap=2, bits=2, lookups=8) +
          uv(0.5) + uv(0.5) + E100 + E100 + E100 + E100 +
          uv(0.5) + uv(0.5) + E154 + ZERO + ZERO + E154 +
          E37 + uv(0.5) + uv(0.01) + uv(0) + uv(0) + uv(0.01) +
          uv(0.1) + uv(0.2) + NAN + INF + NINF + ZERO +
          E300 + E300 + E300 + E300 + E300 + E300 +
          NAN + uv(0.2) + uv(0.01) + uv(0) + uv(0) + uv(0.01) +
          uv(0.3) + uv(0.3) + DENORM + DENORM + DENORM + DENORM +
          raw(1e-310) + raw(-7.5) + raw(3e38) + raw(-3e38) + raw(1e-20) + raw(2.0) + texel_bytes)
    write("reference_filters", "mipcolors-clamped.bin",
          options(4, 16, 16, bias=255, lod_min=20, lod_max=60, lookups=2) +
          uv(0.7) + uv(0.2) + uv(0.5) + uv(0.5) + uv(0) + uv(0.5) +
          uv(0.0) + uv(0.999) + scaled(1, 20) + scaled(3, 20) + scaled(2, -20) + scaled(5, -20))
    write("reference_filters", "sat-boxes.bin",
          options(6, 9, 3, boxes=15, alpha=255, max_aniso=0, lookups=2) +
          uv(0.5) + uv(0.5) + uv(0.9) + uv(0.05) + uv(-0.05) + uv(0.3) +
          uv(-0.99) + uv(0.99) + uv(0.5) + uv(0.5) + uv(0.5) + uv(-0.5) + texel_bytes)


def main():
    if os.path.isdir(CORPUS):
        shutil.rmtree(CORPUS)
    lookups_csv()
    manifest()
    args()
    pfm()
    images()
    reference_filters()
    total = 0
    for root, _, files in os.walk(CORPUS):
        for f in files:
            total += os.path.getsize(os.path.join(root, f))
    print("make_seeds.py: wrote %s (%d bytes)" % (os.path.relpath(CORPUS), total))


if __name__ == "__main__":
    main()
