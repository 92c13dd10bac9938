#!/usr/bin/env python3
"""Turn a `texfilter bench --out DIR` results directory into FLIP scores, images and an HTML report.

Usage:
    py=$(tools/python_env.sh | tail -1)
    "$py" tools/bench_report.py DIR

Reads DIR/bench.json, DIR/bench.csv and the PFM images they name (format: docs of the bench, schema 1),
then writes:
    DIR/bench.json, DIR/bench.csv         each result gains FLIP (LDR) mean vs the box and gaussian truth
    DIR/png/<scene>/<label>.png           frame 0, sRGB 8-bit (also truth-box.png, truth-gaussian.png)
    DIR/heatmaps/<scene>/<label>.png      FLIP error map vs the gaussian truth, magma, 0..1
    DIR/quality_vs_cost.png               FLIP vs gaussian truth against time / hw-trilinear
    DIR/quality_vs_cost_box.png           the same against the box truth
    DIR/quality_vs_reads.png              PSNR vs gaussian truth against texel fetches + hardware lookups a
                                          pixel, with each scene's frontier (no other filter both better and cheaper)
    DIR/index.html                        self-contained report linking all of the above
A `bench --footprints` directory gets its figures instead (tools/footprint_report.py).
Exits 1 with a message naming the file when an input is missing or malformed.
"""

import csv
import html
import json
import math
import os
import re
import sys
import time

import matplotlib

matplotlib.use("Agg")  # headless: no display on CI or the GPU machine
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402
import numpy as np  # noqa: E402
import flip_evaluator  # noqa: E402

import footprint_report  # noqa: E402  (beside this file)

TRUTHS = ("box", "gaussian")
FLIP_COLUMNS = ("flip_box", "flip_gaussian")
SAFE_NAME = re.compile(r"^[A-Za-z0-9][A-Za-z0-9._-]*$")


class InputError(Exception):
    """A bench input file is missing or malformed; the message names the file."""


# ---------------------------------------------------------------- images

def read_pfm(path):
    """Return a colour PFM as float32 HxWx3, top row first."""
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as e:
        raise InputError(f"{path}: cannot read image ({e.strerror})")
    # Header is three whitespace-separated lines; the binary part starts after the scale's newline.
    parts = data.split(b"\n", 3)
    if len(parts) < 4 or parts[0].strip() != b"PF":
        raise InputError(f"{path}: not a colour PFM (expected 'PF' header)")
    try:
        width, height = (int(v) for v in parts[1].split())
        scale = float(parts[2])
    except ValueError:
        raise InputError(f"{path}: malformed PFM header")
    if width <= 0 or height <= 0 or scale == 0 or not math.isfinite(scale):
        raise InputError(f"{path}: malformed PFM header ({width}x{height}, scale {scale})")
    pixels = parts[3]
    expected = width * height * 3 * 4
    if len(pixels) != expected:
        raise InputError(f"{path}: {len(pixels)} bytes of pixel data, expected {expected} "
                         f"for {width}x{height} RGB float32")
    dtype = "<f4" if scale < 0 else ">f4"  # negative scale means little-endian
    img = np.frombuffer(pixels, dtype=dtype).reshape(height, width, 3)
    return np.ascontiguousarray(img[::-1]).astype(np.float32)  # PFM stores the bottom row first


def srgb_encode(linear):
    """Display transform of the bench: clamp linear to [0,1], IEC 61966-2-1 sRGB curve."""
    # NaN/Inf would poison FLIP; NaN shows as black, +Inf as white, like a clamp would for huge values.
    x = np.clip(np.nan_to_num(linear, nan=0.0, posinf=1.0, neginf=0.0), 0.0, 1.0)
    encoded = np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1.0 / 2.4) - 0.055)
    return np.ascontiguousarray(encoded, dtype=np.float32)


def load_display(path, width, height):
    """Frame as sRGB-encoded float32 in [0,1], checked against the configured size."""
    img = read_pfm(path)
    if img.shape[:2] != (height, width):
        raise InputError(f"{path}: image is {img.shape[1]}x{img.shape[0]}, config says {width}x{height}")
    if not np.isfinite(img).all():
        print(f"bench_report: warning: {path}: non-finite pixels (shown black/white)", file=sys.stderr)
    return srgb_encode(img)


def save_png(path, srgb):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    plt.imsave(path, np.round(srgb * 255.0).astype(np.uint8))


def save_heatmap(path, error_map):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    plt.imsave(path, error_map, cmap="magma", vmin=0.0, vmax=1.0)


def flip_ldr(reference, test):
    """FLIP (LDR) of test against reference; returns (HxW error map, mean error).

    flip_evaluator 1.7 facts (read from its flip_python_api.py and checked on arrays):
    evaluate(reference, test, "LDR", inputsRGB=True, applyMagma=True, computeMeanError=True,
    parameters={}) takes HxWxC float arrays with values in [0,1]. For "LDR" the inputs are taken
    as sRGB-ENCODED unless inputsRGB=False (then linear); feeding linear data with the default
    gives a different (wrong) score. So we pass our sRGB-encoded display images with the default.
    applyMagma=False returns the raw error map as HxWx1 float32 in [0,1]; the mean it returns is
    that map's mean. Default viewing condition: 67 pixels per degree. Reference goes first: FLIP
    is not symmetric.
    """
    error_map, mean, _params = flip_evaluator.evaluate(reference, test, "LDR", applyMagma=False)
    return error_map[..., 0], float(mean)


# ---------------------------------------------------------------- bench.json

def need(obj, key, where, kind, source):
    """obj[key], checked to be of the given type; `where` names the key path for the message."""
    if not isinstance(obj, dict) or key not in obj:
        raise InputError(f"{source}: missing {where}{key}")
    value = obj[key]
    if not isinstance(value, kind) or isinstance(value, bool) and kind is not bool:
        raise InputError(f"{source}: {where}{key} has the wrong type ({type(value).__name__})")
    return value


def safe_name(name, what, source):
    # Scene and label become file names: refuse anything that could escape DIR.
    if not SAFE_NAME.match(name):
        raise InputError(f"{source}: {what} {name!r} is not file-name safe")
    return name


def load_bench(out_dir):
    """Parse and structurally check bench.json; returns the whole document."""
    path = os.path.join(out_dir, "bench.json")
    try:
        with open(path) as f:
            bench = json.load(f)
    except OSError as e:
        raise InputError(f"{path}: cannot read ({e.strerror})")
    except json.JSONDecodeError as e:
        raise InputError(f"{path}: invalid JSON ({e})")
    if not isinstance(bench, dict):
        raise InputError(f"{path}: top level is not an object")
    config = need(bench, "config", "", dict, path)
    for key in ("width", "height"):
        if need(config, key, "config.", int, path) <= 0:
            raise InputError(f"{path}: config.{key} must be positive")
    scenes = need(config, "scenes", "config.", list, path)
    for scene in scenes:
        if not isinstance(scene, str):
            raise InputError(f"{path}: config.scenes holds a non-string {scene!r}")
        safe_name(scene, "scene", path)
    truth = need(bench, "truth", "", dict, path)
    for scene in scenes:
        per_scene = need(truth, scene, "truth.", dict, path)
        for kind in TRUTHS:
            image_list(per_scene, kind, f"truth.{scene}.", path)
    for i, result in enumerate(need(bench, "results", "", list, path)):
        where = f"results[{i}]."
        scene = need(result, "scene", where, str, path)
        if scene not in scenes:
            raise InputError(f"{path}: {where}scene {scene!r} is not in config.scenes")
        safe_name(need(result, "label", where, str, path), "label", path)
        image_list(result, "images", where, path)
    if not isinstance(bench.get("goals", []), list):
        raise InputError(f"{path}: goals is not a list")
    return bench


def image_list(obj, key, where, source):
    """A non-empty list of image paths (frame 0 first)."""
    images = need(obj, key, where, list, source)
    if not images or not all(isinstance(p, str) for p in images):
        raise InputError(f"{source}: {where}{key} must be a non-empty list of paths")
    return images


def write_json(path, bench):
    # Write then rename, so an interrupted run never leaves a half-written bench.json.
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        json.dump(bench, f, indent=1)
        f.write("\n")
    os.replace(tmp, path)


def rewrite_csv(path, bench):
    """Append flip_box, flip_gaussian to bench.csv (replacing them if a previous run added them)."""
    try:
        with open(path, newline="") as f:
            rows = list(csv.reader(f))
    except OSError as e:
        raise InputError(f"{path}: cannot read ({e.strerror})")
    if not rows or "scene" not in rows[0] or "label" not in rows[0]:
        raise InputError(f"{path}: missing header with scene and label columns")
    header = rows[0]
    keep = len(header) - 2 if tuple(header[-2:]) == FLIP_COLUMNS else len(header)
    si, li = header.index("scene"), header.index("label")
    flips = {(r["scene"], r["label"]): r.get("flip", {}) for r in bench["results"]}
    out = [header[:keep] + list(FLIP_COLUMNS)]
    for n, row in enumerate(rows[1:], start=2):
        if len(row) < keep:
            raise InputError(f"{path}: line {n} has {len(row)} fields, header has {keep}")
        flip = flips.get((row[si], row[li]), {})
        out.append(row[:keep] + [fmt_csv(flip.get(t)) for t in TRUTHS])
    tmp = path + ".tmp"
    with open(tmp, "w", newline="") as f:
        csv.writer(f, lineterminator="\n").writerows(out)
    os.replace(tmp, path)


def fmt_csv(value):
    return "" if value is None else f"{value:.6g}"


# ---------------------------------------------------------------- processing

def process_scene(out_dir, bench, scene):
    """FLIP, display PNGs and heat maps for one scene; returns the scene's results."""
    config = bench["config"]
    width, height = config["width"], config["height"]
    truth = {}
    for kind in TRUTHS:
        truth[kind] = load_display(os.path.join(out_dir, bench["truth"][scene][kind][0]), width, height)
        save_png(os.path.join(out_dir, "png", scene, f"truth-{kind}.png"), truth[kind])
    results = [r for r in bench["results"] if r["scene"] == scene]
    for result in results:
        label = result["label"]
        image = load_display(os.path.join(out_dir, result["images"][0]), width, height)
        save_png(os.path.join(out_dir, "png", scene, f"{label}.png"), image)
        flip = {}
        for kind in TRUTHS:
            error_map, flip[kind] = flip_ldr(truth[kind], image)
            if kind == "gaussian":
                save_heatmap(os.path.join(out_dir, "heatmaps", scene, f"{label}.png"), error_map)
        result["flip"] = {kind: float(f"{flip[kind]:.6g}") for kind in TRUTHS}
    return results


def scene_panels(count):
    """A figure with one panel a scene, three a row; the unused panels hidden."""
    cols = min(count, 3) or 1
    rows = max(1, math.ceil(count / cols))
    fig, axes = plt.subplots(rows, cols, figsize=(5.5 * cols, 4.5 * rows), squeeze=False)
    for ax in axes.flat[count:]:
        ax.axis("off")
    return fig, axes


def finish_panels(fig, axes, count, title, path):
    """One legend for every panel's entries (a scene may lack a kind), the title, and the PNG at `path`."""
    handles, names = [], []
    for ax in axes.flat[:count]:
        for h, n in zip(*ax.get_legend_handles_labels()):
            if n not in names:
                handles.append(h)
                names.append(n)
    fig.legend(handles, names, loc="upper right", fontsize=8)
    fig.suptitle(title)
    fig.tight_layout(rect=(0, 0, 1, 0.95))  # leave room for the title and legend
    fig.savefig(path, dpi=110)
    plt.close(fig)


def scatter(out_dir, bench, kind, file_name):
    """One subplot per scene: FLIP vs `kind` truth against time relative to hw-trilinear."""
    scenes = bench["config"]["scenes"]
    fig, axes = scene_panels(len(scenes))
    for ax, scene in zip(axes.flat, scenes):
        for hardware, marker, colour, name in ((False, "o", "tab:blue", "shader filter"),
                                               (True, "s", "tab:orange", "hardware filter")):
            pts = [(r["time_vs_hw_trilinear"], r["flip"][kind], r["label"]) for r in bench["results"]
                   if r["scene"] == scene and bool(r.get("hardware")) == hardware and "flip" in r
                   and is_positive(r.get("time_vs_hw_trilinear"))]  # log axis needs x > 0
            if pts:
                ax.scatter([p[0] for p in pts], [p[1] for p in pts], marker=marker, c=colour, label=name)
            for x, y, label in pts:
                ax.annotate(label, (x, y), textcoords="offset points", xytext=(4, 3), fontsize=6)
        ax.axvline(1.0, color="grey", lw=0.8, ls="--")  # hw-trilinear itself
        ax.set_xscale("log")
        log_ticks(ax)
        ax.tick_params(axis="x", which="both", labelsize=7)
        ax.set_title(scene)
        ax.set_xlabel("time / hw-trilinear (median, log scale)")
        ax.set_ylabel(f"FLIP vs {kind} truth (lower is better)")
        ax.grid(True, which="both", alpha=0.3)
    finish_panels(fig, axes, len(scenes), f"quality vs cost on {bench.get('device', '?')}: FLIP vs {kind} truth",
                  os.path.join(out_dir, file_name))


def reads_per_pixel(result):
    """Texel fetches plus hardware lookups a pixel (the shader's counts), or None where the bench has none."""
    fetches, lookups = result.get("fetches_per_pixel"), result.get("hw_lookups_per_pixel")
    if not all(isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v) for v in (fetches, lookups)):
        return None
    return fetches + lookups


def frontier_points(pts):
    """The points no other point beats in both: fewer or equal reads and a higher PSNR (x ascending)."""
    best, out = -math.inf, []
    for x, y, label in sorted(pts, key=lambda p: (p[0], -p[1])):
        if y > best:
            out.append((x, y, label))
            best = y
    return out


def frontier(out_dir, bench, file_name):
    """One subplot per scene: PSNR vs the gaussian truth against reads a pixel, and the quality-vs-reads frontier."""
    scenes = bench["config"]["scenes"]
    fig, axes = scene_panels(len(scenes))
    for ax, scene in zip(axes.flat, scenes):
        pts = []
        for r in bench["results"]:
            reads, psnr = reads_per_pixel(r), number(r, lambda r: r["error"]["gaussian"]["psnr"])
            if r["scene"] == scene and reads is not None and psnr is not None:
                pts.append((max(reads, 0.5), psnr, r["label"]))  # log axis: the no-read filters at 0.5
        for hardware, marker, colour, name in ((False, "o", "tab:blue", "shader filter"),
                                               (True, "s", "tab:orange", "hardware filter")):
            mine = [p for p in pts if any(bool(r.get("hardware")) == hardware for r in bench["results"]
                                          if r["scene"] == scene and r["label"] == p[2])]
            if mine:
                ax.scatter([p[0] for p in mine], [p[1] for p in mine], marker=marker, c=colour, label=name)
        edge = frontier_points(pts)
        if edge:
            ax.step([p[0] for p in edge], [p[1] for p in edge], where="post", color="tab:green", lw=1,
                    label="frontier")
        for x, y, label in pts:
            ax.annotate(label, (x, y), textcoords="offset points", xytext=(4, 3), fontsize=6)
        ax.set_xscale("log")
        ax.set_title(scene)
        ax.set_xlabel("texel fetches + hardware lookups a pixel (log scale)")
        ax.set_ylabel("PSNR vs gaussian truth, dB (higher is better)")
        ax.grid(True, which="both", alpha=0.3)
    finish_panels(fig, axes, len(scenes), f"quality vs reads on {bench.get('device', '?')}: PSNR vs gaussian truth",
                  os.path.join(out_dir, file_name))


def log_ticks(ax):
    """Plain "0.5×" labels instead of 5×10^-1; over wide ranges label only minor ticks 2 and 5."""
    lo, hi = ax.get_xlim()
    digits = "123456789" if hi / lo < 20 else "25"
    ax.xaxis.set_major_formatter(matplotlib.ticker.FuncFormatter(lambda x, _pos: f"{x:g}×"))
    ax.xaxis.set_minor_formatter(matplotlib.ticker.FuncFormatter(
        lambda x, _pos: f"{x:g}×" if f"{x:.0e}"[0] in digits else ""))


def is_positive(value):
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value) \
        and value > 0


# ---------------------------------------------------------------- HTML

STYLE = """
body { font-family: sans-serif; margin: 1.5em; }
table { border-collapse: collapse; margin: 0.5em 0 1.5em; }
th, td { border: 1px solid #ccc; padding: 2px 6px; text-align: right; }
th { background: #eee; }
td.l { text-align: left; }
td.met { background: #c8efc8; } td.missed { background: #f5c2c2; } td.not-applicable { background: #e4e4e4; }
img.t { width: 96px; height: 96px; image-rendering: pixelated; vertical-align: middle; }
img.truth { width: 192px; image-rendering: pixelated; }
.best { font-weight: bold; }
"""

# (heading, getter, digits, which end is best: "min", "max" or None)
COLUMNS = [
    ("median ms", lambda r: r["time_ms"]["median"], 3, "min"),
    ("× hw-trilinear", lambda r: r["time_vs_hw_trilinear"], 2, "min"),
    ("fetches/px", lambda r: r["fetches_per_pixel"], 1, None),
    ("hw lookups/px", lambda r: r["hw_lookups_per_pixel"], 1, None),
    ("PSNR box", lambda r: r["error"]["box"]["psnr"], 2, "max"),
    ("PSNR gaussian", lambda r: r["error"]["gaussian"]["psnr"], 2, "max"),
    ("FLIP box", lambda r: r["flip"]["box"], 4, "min"),
    ("FLIP gaussian", lambda r: r["flip"]["gaussian"], 4, "min"),
    ("flicker box", lambda r: r["flicker"]["box"], 4, "min"),
    ("flicker gaussian", lambda r: r["flicker"]["gaussian"], 4, "min"),
]


def number(result, getter):
    """Column value, or None when the bench left it out or it is not a finite number."""
    try:
        value = getter(result)
    except (KeyError, TypeError):
        return None
    ok = isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)
    return value if ok else None


def esc(value):
    return html.escape(str(value), quote=True)


def header_html(bench):
    config = bench["config"]
    items = [f"{esc(k)}={esc(v)}" for k, v in config.items() if k not in ("scenes", "labels")]
    lines = [
        f"<h1>texfilter bench: {esc(bench.get('device', '?'))}</h1>",
        f"<p>driver {esc(bench.get('driver', '?'))}, Vulkan {esc(bench.get('vulkan', '?'))}, "
        f"date {esc(bench.get('date', '?'))}</p>",
        f"<p>config: {', '.join(items)}</p>",
        f"<p>{len(config['scenes'])} scenes, {len(config.get('labels', []))} filters. "
        "PSNR, FLIP and flicker are on sRGB-encoded display values (clamped linear, IEC 61966-2-1); "
        "FLIP is LDR-FLIP at 67 pixels per degree, heat maps show it against the gaussian truth "
        "(magma, black 0 to white 1).</p>",
        '<p>quality vs cost: <a href="quality_vs_cost.png">vs gaussian truth</a>, '
        '<a href="quality_vs_cost_box.png">vs box truth</a>; quality vs reads a pixel: '
        '<a href="quality_vs_reads.png">the frontier</a></p>',
        '<a href="quality_vs_cost.png"><img src="quality_vs_cost.png" style="max-width:100%"></a>',
    ]
    return "\n".join(lines)


def goals_html(goals):
    rows = ["<h2>goals</h2>", "<table><tr><th>goal</th><th>measured</th><th>status</th><th>note</th></tr>"]
    for goal in goals:
        goal = goal if isinstance(goal, dict) else {}
        status = str(goal.get("status", "?"))
        css = status if status in ("met", "missed", "not-applicable") else ""
        rows.append(f'<tr><td class="l">{esc(goal.get("goal", ""))}</td><td>{esc(goal.get("measured", ""))}</td>'
                    f'<td class="l {css}">{esc(status)}</td><td class="l">{esc(goal.get("note", ""))}</td></tr>')
    rows.append("</table>")
    return "\n".join(rows)


def scene_html(bench, scene, results):
    base = bench.get("baseline_ms", {}).get(scene, {})
    parts = [f'<h2 id="{esc(scene)}">{esc(scene)}</h2>']
    if isinstance(base, dict) and "median" in base:
        parts.append(f"<p>no-texture baseline: median {esc(base['median'])} ms</p>")
    parts.append("<p>" + " ".join(
        f'<a href="png/{esc(scene)}/truth-{k}.png"><img class="truth" src="png/{esc(scene)}/truth-{k}.png" '
        f'title="truth ({k})" alt="truth {k}"></a> truth ({k})' for k in TRUTHS) + "</p>")
    values = [[number(r, col[1]) for col in COLUMNS] for r in results]
    best = []
    for c, col in enumerate(COLUMNS):
        present = [v[c] for v in values if v[c] is not None]
        best.append(None if not present or col[3] is None else (min if col[3] == "min" else max)(present))
    head = "".join(f"<th>{esc(col[0])}</th>" for col in COLUMNS)
    parts.append(f"<table><tr><th>filter</th><th>hw</th>{head}<th>image</th><th>FLIP map</th></tr>")
    for result, row in zip(results, values):
        label = esc(result["label"])
        cells = []
        for value, col, top in zip(row, COLUMNS, best):
            text = "–" if value is None else f"{value:.{col[2]}f}"
            css = ' class="best"' if value is not None and value == top else ""
            cells.append(f"<td{css}>{text}</td>")
        img = f"png/{esc(scene)}/{label}.png"
        heat = f"heatmaps/{esc(scene)}/{label}.png"
        parts.append(
            f'<tr><td class="l" title="{esc(result.get("args", ""))}">{label}</td>'
            f'<td>{"yes" if result.get("hardware") else ""}</td>{"".join(cells)}'
            f'<td><a href="{img}"><img class="t" src="{img}" alt="{label}"></a></td>'
            f'<td><a href="{heat}"><img class="t" src="{heat}" alt="FLIP {label}"></a></td></tr>')
    parts.append("</table>")
    return "\n".join(parts)


def write_html(out_dir, bench, per_scene):
    scenes = bench["config"]["scenes"]
    toc = " · ".join(f'<a href="#{esc(s)}">{esc(s)}</a>' for s in scenes)
    body = [header_html(bench), goals_html(bench.get("goals", [])), f"<p>scenes: {toc}</p>"]
    body += [scene_html(bench, s, per_scene[s]) for s in scenes]
    page = ("<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>texfilter bench</title>"
            f"<style>{STYLE}</style></head><body>\n" + "\n".join(body) + "\n</body></html>\n")
    with open(os.path.join(out_dir, "index.html"), "w", encoding="utf-8") as f:
        f.write(page)


def ordered(results, labels):
    """Results in config.labels order (the bench's run order), unknown labels last."""
    rank = {label: i for i, label in enumerate(labels)}
    return sorted(results, key=lambda r: rank.get(r["label"], len(rank)))


def main(argv):
    if len(argv) != 2 or argv[1].startswith("-"):
        print(f"usage: {argv[0]} DIR   (DIR written by `texfilter bench --out DIR`)", file=sys.stderr)
        return 2
    out_dir = argv[1]
    if footprint_report.is_footprints(out_dir):  # bench --footprints: its own figures
        return footprint_report.main(out_dir)
    start = time.monotonic()
    try:
        bench = load_bench(out_dir)
        labels = bench["config"].get("labels", [])
        per_scene = {}
        for scene in bench["config"]["scenes"]:
            t0 = time.monotonic()
            per_scene[scene] = ordered(process_scene(out_dir, bench, scene), labels)
            done = [r for r in per_scene[scene] if "flip" in r]
            best = min(done, key=lambda r: r["flip"]["gaussian"], default=None)
            note = f", best FLIP vs gaussian {best['flip']['gaussian']:.4f} ({best['label']})" if best else ""
            print(f"bench_report: {scene}: {len(done)} filters{note} ({time.monotonic() - t0:.1f} s)",
                  flush=True)
        rewrite_csv(os.path.join(out_dir, "bench.csv"), bench)
        write_json(os.path.join(out_dir, "bench.json"), bench)
    except InputError as e:
        print(f"bench_report: error: {e}", file=sys.stderr)
        return 1
    scatter(out_dir, bench, "gaussian", "quality_vs_cost.png")
    scatter(out_dir, bench, "box", "quality_vs_cost_box.png")
    frontier(out_dir, bench, "quality_vs_reads.png")
    write_html(out_dir, bench, per_scene)
    print(f"bench_report: wrote {os.path.join(out_dir, 'index.html')} ({time.monotonic() - start:.1f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
