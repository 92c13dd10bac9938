#!/usr/bin/env python3
"""Check that a `texfilter bench --out DIR` results directory is complete and finite.

Usage:
    python3 tools/bench_check.py DIR [--require-flip]

Checks bench.json (schema 1) against its own config: one result per (scene, label) in
config.scenes x config.labels (the environment scenes skybox and reflect: but brilinear, sat and
sat-assembly), every numeric field present and finite with sane ranges, every
image and truth PFM present with the configured size, a baseline per scene and well-formed goals.
The analytic truth (config.analytic_truth: the texture is checker, zoneplate or grid): on every 2D scene
a truth.SCENE.analytic image and finite error.analytic / flicker.analytic in each result; null (or absent)
on the environment scenes and wherever config.analytic_truth is false.
--require-flip also wants result.flip.box/gaussian in [0,1] (added by tools/bench_report.py).
Prints "bench_check: N results complete and finite" and exits 0, or prints every problem found
(one per line) and exits 1. Standard library only, so it runs without tools/python_env.sh.
"""

import argparse
import json
import math
import os
import sys

TRUTHS = ("box", "gaussian")
# The environment scenes (cube and lat-long maps) have no brilinear, SAT or bicubic form (nor --magnify): no
# result is expected there.
ENVIRONMENT_SCENES = {"skybox", "reflect"}
NO_ENVIRONMENT_FORM = {"brilinear", "sat", "sat-assembly", "bspline", "bspline-hw", "catmull-rom", "catmull-rom-hw",
                       "trilinear-catmull-rom", "ewa-bspline"}
ANALYTIC = "analytic"  # the box pixel over the procedural texture's analytic definition


def has_analytic(config, scene):
    """Where the analytic truth must exist: a texture with a definition, on a 2D scene."""
    return config.get("analytic_truth") is True and scene not in ENVIRONMENT_SCENES


def expected(scene, label):
    return not (scene in ENVIRONMENT_SCENES and label in NO_ENVIRONMENT_FORM)
GOAL_STATUSES = {"met", "missed", "not-applicable"}
MISSING = object()  # distinct from a JSON null, which is present but wrong


class Checker:
    """Collects problems instead of stopping at the first, so one run shows everything wrong."""

    def __init__(self, out_dir, width, height):
        self.out_dir = out_dir
        self.width, self.height = width, height
        self.problems = []
        self.checked_images = {}  # path -> problem text or None; truth files are shared

    def problem(self, where, text):
        self.problems.append(f"{where}: {text}")

    def get(self, obj, path, where):
        """Follow a dotted key path; reports and returns MISSING when a step is missing."""
        for key in path.split("."):
            if not isinstance(obj, dict) or key not in obj:
                self.problem(where, f"{path}: missing")
                return MISSING
            obj = obj[key]
        return obj

    def number(self, obj, path, where, minimum=None, positive=False, maximum=None):
        """A finite number at obj[path] within the given bounds; returns it or None."""
        value = self.get(obj, path, where)
        if value is MISSING:
            return None
        if not is_finite(value):
            self.problem(where, f"{path}: not a finite number (got {value!r})")
            return None
        if positive and value <= 0:
            self.problem(where, f"{path}: must be > 0 (got {value!r})")
        if minimum is not None and value < minimum:
            self.problem(where, f"{path}: must be >= {minimum} (got {value!r})")
        if maximum is not None and value > maximum:
            self.problem(where, f"{path}: must be <= {maximum} (got {value!r})")
        return value

    def timing(self, obj, path, where):
        """min/median/max, each > 0, in order."""
        value = self.get(obj, path, where)
        if value is MISSING:
            return  # one line for a missing timing, not three
        if not isinstance(value, dict):
            self.problem(where, f"{path}: expected an object with min, median, max (got {value!r})")
            return
        lo, mid, hi = (self.number(obj, f"{path}.{k}", where, positive=True) for k in ("min", "median", "max"))
        frames = value.get("frames")
        if not (isinstance(frames, int) and not isinstance(frames, bool) and frames >= 1):
            self.problem(where, f"{path}.frames: expected a count of timed frames >= 1 (got {frames!r})")
        if None not in (lo, mid, hi) and not lo <= mid <= hi:
            self.problem(where, f"{path}: expected min <= median <= max (got {lo}, {mid}, {hi})")

    def images(self, paths, where, field):
        """A list holding frame 0 of the camera path, a valid PFM of the configured size."""
        if not isinstance(paths, list) or len(paths) != 1:
            self.problem(where, f"{field}: expected a list of one image path (frame 0), got {paths!r}")
            return
        for i, rel in enumerate(paths):
            if not isinstance(rel, str):
                self.problem(where, f"{field}[{i}]: not a path ({rel!r})")
                continue
            if rel not in self.checked_images:
                self.checked_images[rel] = pfm_problem(os.path.join(self.out_dir, rel), self.width, self.height)
            if self.checked_images[rel]:
                self.problem(where, f"{field}[{i}]: {rel}: {self.checked_images[rel]}")


def is_finite(value):
    # bool is an int subclass in Python, but true/false is never a valid measurement.
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)


def pfm_problem(path, width, height):
    """None if path is a colour PFM of width x height with exactly its pixel data, else why not."""
    try:
        size = os.path.getsize(path)
        with open(path, "rb") as f:
            head = f.read(256)
    except OSError as e:
        return f"cannot read ({e.strerror})"
    lines = head.split(b"\n", 3)
    if len(lines) < 4 or lines[0].strip() != b"PF":
        return "not a colour PFM (expected 'PF' header)"
    try:
        w, h = (int(v) for v in lines[1].split())
        scale = float(lines[2])
    except ValueError:
        return "malformed PFM header"
    if (w, h) != (width, height):
        return f"PFM is {w}x{h}, config says {width}x{height}"
    if scale == 0 or not math.isfinite(scale):
        return f"PFM scale {scale} is not a non-zero finite number"
    header = len(head) - len(lines[3])
    expected = header + w * h * 3 * 4
    if size != expected:
        return f"file is {size} bytes, expected {expected} (header {header} + {w}x{h}x3 float32)"
    return None


def check_config(bench, c):
    """Scenes and labels as lists of unique strings; returns them (empty on failure)."""
    lists = {}
    for key in ("scenes", "labels"):
        value = c.get(bench, f"config.{key}", "config")
        ok = isinstance(value, list) and value and all(isinstance(v, str) for v in value)
        if value is not MISSING and not ok:
            c.problem("config", f"config.{key}: expected a non-empty list of strings")
        elif ok and len(set(value)) != len(value):
            c.problem("config", f"config.{key}: has duplicates")
        lists[key] = value if ok else []
    return lists["scenes"], lists["labels"]


def check_sat_sweep(bench, labels, c):
    """sat and sat-assembly, when they ran, are also timed at minify 2x and 64x."""
    sweep = c.get(bench, "sat_sweep", "bench.json")
    if sweep is MISSING:
        return
    if not isinstance(sweep, list):
        c.problem("bench.json", "sat_sweep: not a list")
        return
    expected = [label for label in labels if label in ("sat", "sat-assembly")]
    found = [entry.get("label") for entry in sweep if isinstance(entry, dict)]
    if sorted(found) != sorted(expected):
        c.problem("bench.json", f"sat_sweep: labels {found}, expected {expected}")
    for entry in sweep:
        if isinstance(entry, dict):
            for key in ("minify_2x_ms", "minify_64x_ms"):
                c.timing(entry, key, f"sat_sweep/{entry.get('label', '?')}")


def check_ewa_sweep(bench, labels, c):
    """When both ewa and ewa-hw ran: their PSNR against the Gaussian truth at 1..64 texels a pixel."""
    sweep = c.get(bench, "ewa_sweep", "bench.json")
    if sweep is MISSING:
        return
    if not isinstance(sweep, list):
        c.problem("bench.json", "ewa_sweep: not a list")
        return
    expected = [1, 2, 4, 8, 16, 32, 64] if "ewa" in labels and "ewa-hw" in labels else []
    found = [entry.get("texels_per_pixel") for entry in sweep if isinstance(entry, dict)]
    if found != expected:
        c.problem("bench.json", f"ewa_sweep: footprint sizes {found}, expected {expected}")
    for entry in sweep:
        for key in ("psnr_gaussian_manual", "psnr_gaussian_hardware"):
            value = entry.get(key) if isinstance(entry, dict) else None
            if not isinstance(value, (int, float)) or not math.isfinite(value) or not 0 < value < 200:
                c.problem("bench.json", f"ewa_sweep: {key} {value!r} is not a PSNR in (0, 200) dB")


def check_stochastic(bench, labels, c):
    """Stochastic rows (not in --quick): each with a frame time and finite errors after 1, 4, 16, 64 frames."""
    rows = c.get(bench, "stochastic", "bench.json")
    if rows is MISSING:
        return
    if not isinstance(rows, list):
        c.problem("bench.json", "stochastic: not a list")
        return
    quick = isinstance(bench.get("config"), dict) and bench["config"].get("quick") is True
    if quick and rows:
        c.problem("bench.json", "stochastic: rows in a --quick run")
    for row in rows:
        where = f"stochastic/{row.get('label', '?')}/{row.get('noise', '?')}" if isinstance(row, dict) else "stochastic"
        if not isinstance(row, dict) or row.get("label") not in labels or row.get("noise") not in ("white", "blue"):
            c.problem(where, "expected a label of the run and noise white or blue")
            continue
        c.timing(row, "frame_ms", where)
        if row.get("frames") != [1, 4, 16, 64]:
            c.problem(where, f"frames {row.get('frames')!r}, expected [1, 4, 16, 64]")
        for truth in TRUTHS:
            errors = row.get("error", {}).get(truth) if isinstance(row.get("error"), dict) else None
            if not isinstance(errors, list) or len(errors) != 4 or not all(
                    isinstance(e, dict) and isinstance(e.get("rmse"), (int, float)) and math.isfinite(e["rmse"])
                    for e in errors):
                c.problem(where, f"error.{truth}: expected 4 finite rmse values")


def check_scene_data(bench, scenes, c):
    config = bench.get("config") if isinstance(bench.get("config"), dict) else {}
    if not isinstance(config.get("analytic_truth"), bool):
        c.problem("config", f"config.analytic_truth: expected true or false (got {config.get('analytic_truth')!r})")
    for scene in scenes:
        c.timing(bench, f"baseline_ms.{scene}", f"{scene}/baseline")
        for kind in TRUTHS:
            paths = c.get(bench, f"truth.{scene}.{kind}", f"{scene}/truth")
            if paths is not MISSING:
                c.images(paths, f"{scene}/truth", f"truth.{scene}.{kind}")
        per_scene = bench.get("truth", {}).get(scene) if isinstance(bench.get("truth"), dict) else None
        analytic = per_scene.get(ANALYTIC) if isinstance(per_scene, dict) else None
        if has_analytic(config, scene):
            paths = c.get(bench, f"truth.{scene}.{ANALYTIC}", f"{scene}/truth")
            if paths is not MISSING:
                c.images(paths, f"{scene}/truth", f"truth.{scene}.{ANALYTIC}")
        elif analytic is not None:
            c.problem(f"{scene}/truth", f"truth.{scene}.{ANALYTIC}: expected none here (got {analytic!r})")


def check_analytic(result, c, where, wanted):
    """error.analytic {rmse, psnr} and flicker.analytic: finite where wanted, else null or absent."""
    if wanted:
        c.number(result, f"error.{ANALYTIC}.rmse", where, minimum=0)
        c.number(result, f"error.{ANALYTIC}.psnr", where)
        c.number(result, f"flicker.{ANALYTIC}", where, minimum=0)
        return
    for group in ("error", "flicker"):
        value = result.get(group, {}).get(ANALYTIC) if isinstance(result.get(group), dict) else None
        if value is not None:
            c.problem(where, f"{group}.{ANALYTIC}: expected null, no analytic truth here (got {value!r})")


def check_result(result, c, require_flip, config):
    where = f"{result.get('scene', '?')}/{result.get('label', '?')}"
    for key in ("filter", "args"):
        if not isinstance(result.get(key), str):
            c.problem(where, f"{key}: missing or not a string")
    if not isinstance(result.get("hardware"), bool):
        c.problem(where, "hardware: missing or not true/false")
    c.timing(result, "time_ms", where)
    c.number(result, "time_vs_hw_trilinear", where, positive=True)
    c.number(result, "time_vs_baseline", where, positive=True)
    c.number(result, "fetches_per_pixel", where, minimum=0)
    c.number(result, "hw_lookups_per_pixel", where, minimum=0)
    for kind in TRUTHS:
        c.number(result, f"error.{kind}.rmse", where, minimum=0)
        c.number(result, f"error.{kind}.psnr", where)
        c.number(result, f"flicker.{kind}", where, minimum=0)
        if require_flip:
            c.number(result, f"flip.{kind}", where, minimum=0, maximum=1)
    check_analytic(result, c, where, has_analytic(config, result.get("scene")))
    paths = c.get(result, "images", where)
    if paths is not MISSING:
        c.images(paths, where, "images")


def check_results(bench, scenes, labels, c, require_flip):
    """Exactly one result per (scene, label); returns how many results there are."""
    results = c.get(bench, "results", "bench.json")
    if not isinstance(results, list):
        if results is not MISSING:
            c.problem("bench.json", "results: not a list")
        return 0
    seen = set()
    for i, result in enumerate(results):
        if not isinstance(result, dict):
            c.problem(f"results[{i}]", "not an object")
            continue
        key = tuple(v if isinstance(v, str) else repr(v) for v in (result.get("scene"), result.get("label")))
        if key in seen:
            c.problem(f"{key[0]}/{key[1]}", "more than one result")
        elif key[0] not in scenes or key[1] not in labels or not expected(key[0], key[1]):
            c.problem(f"{key[0]}/{key[1]}", "scene/label pair not in config.scenes x config.labels")
        seen.add(key)
        check_result(result, c, require_flip, bench.get("config") if isinstance(bench.get("config"), dict) else {})
    for scene in scenes:
        for label in labels:
            if (scene, label) not in seen and expected(scene, label):
                c.problem(f"{scene}/{label}", "no result")
    return len(results)


def check_goals(bench, c):
    goals = c.get(bench, "goals", "bench.json")
    if goals is MISSING:
        return
    if not isinstance(goals, list):
        c.problem("goals", "not a list")
        return
    for i, goal in enumerate(goals):
        if not isinstance(goal, dict) or not isinstance(goal.get("goal"), str):
            c.problem(f"goals[{i}]", "expected an object with a 'goal' string")
        elif goal.get("status") not in GOAL_STATUSES:
            c.problem(f"goals[{i}]", f"status {goal.get('status')!r} not in {sorted(GOAL_STATUSES)}")


def check(out_dir, require_flip):
    """Returns (number of results, list of problems)."""
    path = os.path.join(out_dir, "bench.json")
    try:
        with open(path) as f:
            bench = json.load(f)
    except OSError as e:
        return 0, [f"{path}: cannot read ({e.strerror})"]
    except json.JSONDecodeError as e:
        return 0, [f"{path}: invalid JSON ({e})"]
    if not isinstance(bench, dict):
        return 0, [f"{path}: top level is not an object"]
    config = bench.get("config") if isinstance(bench.get("config"), dict) else {}
    width, height = config.get("width"), config.get("height")
    c = Checker(out_dir, width, height)
    if bench.get("schema") != 1:
        c.problem("bench.json", f"schema: expected 1 (got {bench.get('schema')!r})")
    for key in ("device", "driver", "vulkan", "date"):
        if not isinstance(bench.get(key), str):
            c.problem("bench.json", f"{key}: missing or not a string")
    if not all(isinstance(v, int) and not isinstance(v, bool) and v > 0 for v in (width, height)):
        c.problem("config", f"config.width/height: expected positive integers (got {width!r}, {height!r})")
    scenes, labels = check_config(bench, c)
    check_scene_data(bench, scenes, c)
    count = check_results(bench, scenes, labels, c, require_flip)
    check_sat_sweep(bench, labels, c)
    check_ewa_sweep(bench, labels, c)
    check_stochastic(bench, labels, c)
    check_goals(bench, c)
    return count, c.problems


def main():
    parser = argparse.ArgumentParser(description="Check a texfilter bench results directory.")
    parser.add_argument("dir", help="directory written by `texfilter bench --out DIR`")
    parser.add_argument("--require-flip", action="store_true",
                        help="also require FLIP scores (run tools/bench_report.py first)")
    args = parser.parse_args()
    count, problems = check(args.dir, args.require_flip)
    if problems:
        for line in problems:
            print(f"bench_check: {line}", file=sys.stderr)
        print(f"bench_check: {len(problems)} problem(s) in {args.dir}", file=sys.stderr)
        return 1
    print(f"bench_check: {count} results complete and finite")
    return 0


if __name__ == "__main__":
    sys.exit(main())
