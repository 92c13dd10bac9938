"""Figures of a `texfilter bench --footprints --out DIR` run; tools/bench_report.py DIR calls it for such a DIR.

Reads DIR/bench.json ("kind": "footprints") and writes
    DIR/footprints_major.png        PSNR against the footprint's major axis (level-0 texels), one line a filter,
                                    a panel a texture (rows) and truth (columns); the noise floor dashed
    DIR/footprints_anisotropy.png   the same against anisotropy
    DIR/footprints_major-isotropic.png  against the major axis, the footprints of anisotropy below 2 alone
"""

import json
import os
import sys

import matplotlib

matplotlib.use("Agg")  # headless
import matplotlib.pyplot as plt  # noqa: E402


AXIS_TITLES = {
    "major": "major axis (level-0 texels)",
    "anisotropy": "anisotropy",
    "major-isotropic": "major axis (level-0 texels), anisotropy below 2",
}


class FootprintInputError(Exception):
    """bench.json is missing or malformed; the message names the file."""


def is_footprints(out_dir):
    """True when DIR/bench.json is a footprints run (any other content: False, for bench_report to judge)."""
    try:
        with open(os.path.join(out_dir, "bench.json")) as f:
            return json.load(f).get("kind") == "footprints"
    except (OSError, ValueError, AttributeError):
        return False


def load(out_dir):
    path = os.path.join(out_dir, "bench.json")
    with open(path) as f:
        bench = json.load(f)
    rows = bench.get("rows")
    config = bench.get("config")
    if not isinstance(rows, list) or not isinstance(config, dict):
        raise FootprintInputError(f"{path}: no rows or config")
    for i, row in enumerate(rows):
        for key in ("texture", "truth", "label", "axis", "bucket"):
            if not isinstance(row.get(key), str):
                raise FootprintInputError(f"{path}: rows[{i}].{key} is missing or not a string")
        for key in ("psnr", "floor_psnr"):
            if not (row.get(key) is None or isinstance(row.get(key), (int, float))):
                raise FootprintInputError(f"{path}: rows[{i}].{key} is not a number")
    return bench


def in_order(values):
    seen = []
    for v in values:
        if v not in seen:
            seen.append(v)
    return seen


def figure(bench, axis, path):
    rows = [r for r in bench["rows"] if r["axis"] == axis]
    textures = in_order(r["texture"] for r in rows)
    truths = in_order(r["truth"] for r in rows)
    labels = bench["config"].get("labels") or in_order(r["label"] for r in rows)
    buckets = [b["name"] for b in bench["config"]["buckets"] if b["axis"] == axis]
    fig, axes = plt.subplots(len(textures), len(truths), figsize=(6 * len(truths), 3.6 * len(textures)),
                             squeeze=False, sharex=True)
    x = list(range(len(buckets)))
    for ti, texture in enumerate(textures):
        for ci, truth in enumerate(truths):
            ax = axes[ti][ci]
            mine = [r for r in rows if r["texture"] == texture and r["truth"] == truth]
            for label in labels:
                by_bucket = {r["bucket"]: r["psnr"] for r in mine if r["label"] == label}
                y = [by_bucket.get(b) for b in buckets]
                ax.plot(x, [float("nan") if v is None else v for v in y], marker="o", markersize=3, label=label)
            floor = {r["bucket"]: r["floor_psnr"] for r in mine}
            ax.plot(x, [float("nan") if floor.get(b) is None else floor[b] for b in buckets], "k--", linewidth=1,
                    label="noise floor (truth vs truth)")
            ax.set_title(f"{os.path.basename(texture)}, {truth} truth", fontsize=9)
            ax.set_ylabel("PSNR (dB)")
            ax.set_xticks(x)
            ax.set_xticklabels(buckets, fontsize=8)
            ax.grid(True, alpha=0.3)
    for ci in range(len(truths)):
        axes[-1][ci].set_xlabel(AXIS_TITLES[axis])
    handles, names = axes[0][0].get_legend_handles_labels()
    height = 3.6 * len(textures)
    top = 1.0 - 1.1 / height  # the title and a legend of two rows above the panels, whatever the figure's height
    fig.legend(handles, names, loc="upper center", bbox_to_anchor=(0.5, 1.0 - 0.35 / height), ncol=5, fontsize=8)
    fig.suptitle(f"texfilter bench --footprints: PSNR by {AXIS_TITLES[axis]}"
                 f" ({bench.get('device', '')}, {bench.get('date', '')})", y=1.0 - 0.08 / height)
    fig.tight_layout(rect=(0, 0, 1, top))
    fig.savefig(path, dpi=100)
    plt.close(fig)


def main(out_dir):
    """Writes the two figures; 1 with a message for a malformed bench.json."""
    try:
        bench = load(out_dir)
    except (OSError, ValueError, FootprintInputError) as e:
        print(f"bench_report: error: {e}", file=sys.stderr)
        return 1
    for axis in AXIS_TITLES:
        path = os.path.join(out_dir, f"footprints_{axis}.png")
        figure(bench, axis, path)
        print(f"bench_report: wrote {path}")
    return 0
