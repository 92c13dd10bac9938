#!/usr/bin/env python3
"""prototypes.current: every public overload the includes instantiate per resource kind is declared by its
full signature in its family's file, so that `grep "tf_ewa(sampler2DArray"` finds it.

usage: prototypes.py GLSLANG INCLUDE_DIR --check    (ctest prototypes.current)
       prototypes.py GLSLANG INCLUDE_DIR --write    (rewrites the blocks after a change of signatures)

A family's functions for each resource kind are written once against access macros (detail/NAME_kind.glsl), so
their signatures appear nowhere in the source. This preprocesses texfilter.glsl with glslang once per
TF_RESOURCES bit and once for a TF_SOURCE alone, collects the `tf_` definitions that come from each
detail/NAME_kind.glsl (by the #line directives), and writes them into NAME.glsl between the lines
`// BEGIN prototypes` and `// END prototypes`, each under the #if of the bits that instantiate it. --check fails
when a block differs from what the sources instantiate, or a public signature names an internal (tfi_) type.
Standard library only.
"""
import os
import re
import subprocess
import sys
import tempfile

BITS = [("TF_RESOURCE_SAMPLER_2D", 1), ("TF_RESOURCE_TEXTURE_2D", 2), ("TF_RESOURCE_SAMPLER_2D_ARRAY", 4),
        ("TF_RESOURCE_TEXTURE_2D_ARRAY", 8), ("TF_RESOURCE_INTEGER", 16), ("TF_RESOURCE_SHADOW", 32),
        ("TF_RESOURCE_CUBE", 64), ("TF_RESOURCE_CUBE_ARRAY", 128), ("TF_RESOURCE_LATLONG", 256)]
SOURCE = "TF_SOURCE"  # the preprocessed type name stands for the user's type
LINE = re.compile(r'^#line \d+ "([^"]+)"', re.M)
DEFINITION = re.compile(r'^[ \t]*(\w+)[ \t]+(tf_\w+)[ \t]*\(([^(){};]*)\)\s*\{', re.M)
BEGIN, END = "// BEGIN prototypes", "// END prototypes"


def preprocess(glslang, include_dir, prelude):
    source = ("#version 460\n#extension GL_GOOGLE_include_directive : require\n" + prelude +
              '#include "texfilter/texfilter.glsl"\nvoid main() {}\n')
    with tempfile.TemporaryDirectory() as work:
        path = os.path.join(work, "p.frag")
        with open(path, "w") as f:
            f.write(source)
        r = subprocess.run([glslang, "-E", "-I" + include_dir, path], stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, text=True)
    if r.returncode != 0:
        sys.exit(f"FAIL  glslang -E failed:\n{r.stdout[-2000:]}")
    return r.stdout


def definitions(text):
    """{family: set of normalised signatures} of the tf_ functions defined in detail/FAMILY_kind.glsl."""
    marks = [(m.start(), m.group(1)) for m in LINE.finditer(text)]
    out, k = {}, 0
    for m in DEFINITION.finditer(text):
        while k + 1 < len(marks) and marks[k + 1][0] < m.start():
            k += 1
        path = marks[k][1] if marks and marks[k][0] < m.start() else ""
        family = re.search(r"detail/(\w+)_kind\.glsl$", path)
        if not family:
            continue
        params = ", ".join(" ".join(p.split()) for p in m.group(3).split(",")) if m.group(3).strip() else ""
        out.setdefault(family.group(1), set()).add(f"{m.group(1)} {m.group(2)}({params});")
    return out


def collect(glslang, include_dir):
    """{family: {signature: guard}}, guard a TF_RESOURCES mask or SOURCE."""
    masks = {}
    for name, bit in BITS:
        for family, sigs in definitions(preprocess(glslang, include_dir, f"#define TF_RESOURCES {bit}\n")).items():
            for sig in sigs:
                masks.setdefault(family, {}).setdefault(sig, 0)
                masks[family][sig] |= bit
    prelude = ("struct tfi_UserSource { int id; };\n#define TF_SOURCE tfi_UserSource\n#define TF_RESOURCES 0\n"
               "ivec2 tf_source_size(tfi_UserSource src, int level);\nint tf_source_levels(tfi_UserSource src);\n"
               "vec4 tf_source_fetch(tfi_UserSource src, ivec2 texel, int level);\n")
    for family, sigs in definitions(preprocess(glslang, include_dir, prelude)).items():
        for sig in sigs:
            masks.setdefault(family, {})[sig.replace("tfi_UserSource", SOURCE)] = SOURCE
    return masks


def guard_line(guard):
    if guard == SOURCE:
        return "#ifdef TF_SOURCE"
    names = [name for name, bit in BITS if guard & bit]
    return f"#if (TF_RESOURCES & ({' | '.join(names)})) != 0" if len(names) > 1 else \
        f"#if (TF_RESOURCES & {names[0]}) != 0"


def order(guard):
    return (1 << 20) if guard == SOURCE else guard


def block(sigs):
    lines = [BEGIN + " (generated: tests/prototypes.py --write; ctest prototypes.current checks it)",
             "// Every overload below is defined by this file's detail/*_kind.glsl for the kinds its #if names."]
    for guard in sorted(set(sigs.values()), key=order):
        lines.append(guard_line(guard))
        lines += sorted(s for s, g in sigs.items() if g == guard)
        lines.append("#endif")
    lines.append(END)
    return "\n".join(lines) + "\n"


def main(argv):
    if len(argv) != 4 or argv[3] not in ("--check", "--write"):
        print(__doc__.strip().splitlines()[3].strip(), file=sys.stderr)
        return 2
    glslang, include_dir, mode = argv[1:]
    failures = 0
    for family, sigs in sorted(collect(glslang, include_dir).items()):
        internal = [s for s in sigs if "tfi_" in s.replace("tfi_UserSource", "")]
        for s in internal:
            print(f"FAIL  {family}.glsl: public signature names an internal type: {s}")
            failures += 1
        path = os.path.join(include_dir, "texfilter", family + ".glsl")
        text = open(path).read()
        wanted = block(sigs)
        found = re.search(re.escape(BEGIN) + r".*?" + re.escape(END) + r"\n", text, re.S)
        if mode == "--write":
            if found:
                text = text[:found.start()] + wanted + text[found.end():]
            else:  # before the family's instantiation
                at = text.index(f"#define TFI_FAMILY TFI_FAMILY_{family.upper()}\n")
                text = text[:at] + wanted + "\n" + text[at:]
            with open(path, "w") as f:
                f.write(text)
            print(f"wrote {family}.glsl: {len(sigs)} prototypes")
        elif not found or found.group(0) != wanted:
            print(f"FAIL  {family}.glsl: its prototype block differs from the {len(sigs)} overloads the sources "
                  f"instantiate (run tests/prototypes.py GLSLANG INCLUDE_DIR --write)")
            failures += 1
        else:
            print(f"ok    {family}.glsl: {len(sigs)} prototypes")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
