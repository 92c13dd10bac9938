#!/usr/bin/env python3
"""texfilter under Slang's compiler (slangc from tools/.venv: tools/slangc.sh), as ctest entries slang.GROUP.

usage: slang_check.py --list
       slang_check.py SOURCE_DIR OUT_DIR GLSLANG SPIRV_VAL SPIRV_DIS GROUP
Groups:
  sample_spirv   shaders/harness/sample.comp.glsl (the combined kind, filter_select.glsl) compiled by
                 `slangc -allow-glsl -target spirv -O0` to OUT_DIR/sample.spv, then spirv-val --target-env
                 vulkan1.2. A fixture of slang.interface and slang.sample.* (tests/test_slang.cpp runs
                 `texfilter sample --spirv OUT_DIR/sample.spv`).
  sample_spirv_separate, sample_spirv_separate_array
                 the same with -DHARNESS_RESOURCE=HARNESS_RESOURCE_SEPARATE (texture2D + sampler: Slang's
                 Texture2D + SamplerState, read through the includes' tfi_slang_* wrappers) and _SEPARATE_ARRAY,
                 to OUT_DIR/sample_separate.spv, sample_separate_array.spv: the fixtures of
                 slang.sample_separate.* and slang.sample_separate_array.* (`sample --resource K --spirv`).
  interface      each of those modules and glslang's of the same source and kind agree with
                 shaders/harness/config.h: each push-constant member at its HARNESS_PUSH_* offset (the member's
                 name in upper case with underscores), each specialization constant NAME_ID at
                 HARNESS_SPEC_NAME, the workgroup size HARNESS_SAMPLE_LOCAL_SIZE; every resource slangc keeps at
                 the (set, binding) where glslang puts it, as the same kind (storage class and type; an image's
                 Dim, Arrayed, MS and Sampled operands). Without slangc here, glslang's modules alone.
  target.TARGET  tests/slang/uses_texfilter.slang (a Slang shader that #includes texfilter/texfilter.glsl and
                 calls every 2D family on a Sampler2D, a Texture2D and a TF_SOURCE) compiles to TARGET,
                 and the output is validated where a tool for it is here: SPIR-V by spirv-val, GLSL by
                 glslangValidator, WGSL by naga where installed; HLSL and Metal are not (no compiler here).
                 TARGETS below says which kinds each target takes (docs/API.md "Slang").
Why -O0: the wheel carries no spirv-opt (slangc's optimised SPIR-V path needs it). Why the OpSource rewrite:
slangc names its source language 11 (Slang), which SPIRV-Tools 2023.1 (Debian bookworm's spirv-val) does not
know and refuses before it validates anything else; the operand is set to 0 (Unknown), nothing else changes.
Where tools/.venv cannot be made (tools/slangc.sh exits 3: offline, say) a group exits 77, ctest's skip.
Standard library only.
"""
import os
import re
import shutil
import struct
import subprocess
import sys

SKIP = 77  # ctest SKIP_RETURN_CODE
# target: (slangc -target, flags, output suffix, the validator of the output, or None). Sampler2D (GLSL's
# sampler2D) only where slangc emits valid code for it: its HLSL, Metal and WGSL output for a Sampler2D's
# Load, GetDimensions (and so texelFetch, textureSize, textureQueryLevels) passes the SamplerState where the
# coordinate or the level goes (e.g. HLSL `t.Load(sampler, coord)`, WGSL `textureDimensions(t, sampler)`), so
# those targets take Texture2D (+ SamplerState) and the TF_SOURCE kind, docs/API.md "Slang".
SOURCE_ONLY = ["-DTEXFILTER_SAMPLER_2D=0"]
TARGETS = {
    "spirv": ("spirv", ["-O0"], "spv", "spirv-val"),  # every kind: Sampler2D, Texture2D, TF_SOURCE
    "glsl": ("glsl", [], "comp", "glslang"),
    "hlsl": ("hlsl", SOURCE_ONLY, "hlsl", None),  # no HLSL compiler on Debian bookworm
    "metal": ("metal", SOURCE_ONLY, "metal", None),  # no Metal compiler off macOS
    "wgsl": ("wgsl", SOURCE_ONLY, "wgsl", "naga"),  # naga (wgpu's validator) where installed
}
# The harness variants slangc compiles: group suffix -> (HARNESS_RESOURCE_* name in config.h, module file,
# the bindings besides the lookups, results and stats buffers every module must keep).
VARIANTS = {
    "": ("HARNESS_RESOURCE_COMBINED", "sample.spv", ["TEXTURE"]),
    "_separate": ("HARNESS_RESOURCE_SEPARATE", "sample_separate.spv", ["TEXTURE", "SAMPLER"]),
    "_separate_array": ("HARNESS_RESOURCE_SEPARATE_ARRAY", "sample_separate_array.spv", ["TEXTURE", "SAMPLER"]),
}
GROUPS = [f"sample_spirv{v}" for v in VARIANTS] + ["interface"] + [f"target.{t}" for t in TARGETS]
OP_SOURCE = 3
SLANG_LANGUAGE = 11


def fail(message):
    print(f"FAIL: {message}")
    sys.exit(1)


def skip_marker(out_dir):
    """Written by sample_spirv when slangc cannot be had here: the groups and tests that need its module skip."""
    return os.path.join(out_dir, "sample.skipped")


def run(command, what, out_dir=None):
    """Runs COMMAND; exits SKIP when slangc.sh says the venv cannot be made (and, given OUT_DIR, leaves the
    skip marker there), fails naming WHAT otherwise."""
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode == 3 and command[0].endswith("slangc.sh"):
        print(result.stderr, end="")
        reason = "this machine lacks slangc: tools/.venv cannot be made here (tools/python_env.sh exit 3)"
        if out_dir:
            with open(skip_marker(out_dir), "w", encoding="utf-8") as marker:
                marker.write(reason + "\n")
        print("SKIP: " + reason)
        sys.exit(SKIP)
    if result.returncode != 0:
        fail(f"{what} failed ({result.returncode}):\n  {' '.join(command)}\n{result.stdout}{result.stderr}")
    return result.stdout + result.stderr


def slangc(source_dir):
    return [os.path.join(source_dir, "tools", "slangc.sh")]


def source_language_unknown(spv_in, spv_out):
    """Copies the module with every OpSource's language operand 11 (Slang) set to 0 (Unknown)."""
    data = open(spv_in, "rb").read()
    if len(data) < 20 or len(data) % 4:
        fail(f"{spv_in}: not a SPIR-V module ({len(data)} bytes)")
    words = list(struct.unpack(f"<{len(data) // 4}I", data))
    if words[0] != 0x07230203:
        fail(f"{spv_in}: no SPIR-V magic number")
    i, rewritten = 5, 0
    while i < len(words):
        count = words[i] >> 16
        if count == 0:
            fail(f"{spv_in}: an instruction of 0 words at word {i}")
        if (words[i] & 0xFFFF) == OP_SOURCE and words[i + 1] == SLANG_LANGUAGE:
            words[i + 1] = 0
            rewritten += 1
        i += count
    open(spv_out, "wb").write(struct.pack(f"<{len(words)}I", *words))
    return rewritten


def validate(spirv_val, spv):
    run([spirv_val, "--target-env", "vulkan1.2", spv], f"spirv-val of {spv}")


def sample_spirv(source_dir, out_dir, spirv_val, variant):
    kind, module, _ = VARIANTS[variant]
    resource = config_defines(source_dir)[kind]
    shaders = os.path.join(source_dir, "shaders")
    out = os.path.join(out_dir, module)
    raw = out + ".slangc"
    for stale in (raw, out, skip_marker(out_dir)):  # a failed run leaves no module for the checks to run
        if os.path.exists(stale):
            os.remove(stale)
    version = run(slangc(source_dir) + ["-v"], "slangc -v", out_dir).strip()
    run(slangc(source_dir) + ["-allow-glsl", "-target", "spirv", "-O0", "-stage", "compute", "-entry", "main",
                              f"-DHARNESS_RESOURCE={resource}", "-I", shaders, "-I", os.path.join(shaders, "harness"),
                              os.path.join(shaders, "harness", "sample.comp.glsl"), "-o", raw],
        f"slangc -DHARNESS_RESOURCE={resource} ({kind}) of sample.comp.glsl")
    rewritten = source_language_unknown(raw, raw + ".tmp")
    validate(spirv_val, raw + ".tmp")
    os.replace(raw + ".tmp", out)
    print(f"slangc {version}, {kind}: {out} ({os.path.getsize(out)} bytes), {rewritten} OpSource operand(s) "
          "11 -> 0, spirv-val vulkan1.2 passed")


def config_defines(source_dir):
    """shaders/harness/config.h's integer #defines."""
    defines = {}
    for line in open(os.path.join(source_dir, "shaders", "harness", "config.h"), encoding="utf-8"):
        m = re.match(r"#define (\w+) (\d+)\b", line)
        if m:
            defines[m.group(1)] = int(m.group(2))
    return defines


def upper_snake(name):
    return re.sub(r"(?<=[a-z0-9])(?=[A-Z])", "_", name).upper()


def module_facts(spirv_dis, spv):
    """From the disassembly: push-constant members {name: offset}, spec ids {name: id}, local size, and
    resources {name: (set, binding)}."""
    text = subprocess.run([spirv_dis, "--raw-id", spv], capture_output=True, text=True, check=True).stdout
    names, member_names = {}, {}
    for m in re.finditer(r'OpName %(\d+) "([^"]*)"', text):
        names[m.group(1)] = m.group(2)
    for m in re.finditer(r'OpMemberName %(\d+) (\d+) "([^"]*)"', text):
        member_names[(m.group(1), int(m.group(2)))] = m.group(3)
    # The push-constant block: the struct a PushConstant pointer points to.
    pointers = dict((m.group(1), (m.group(2), m.group(3)))
                    for m in re.finditer(r"%(\d+) = OpTypePointer (\w+) %(\d+)", text))
    push_structs = {target for storage, target in pointers.values() if storage == "PushConstant"}
    push = {}
    for m in re.finditer(r"OpMemberDecorate %(\d+) (\d+) Offset (\d+)", text):
        if m.group(1) in push_structs:
            push[member_names.get((m.group(1), int(m.group(2))), f"#{m.group(2)}")] = int(m.group(3))
    spec = {names.get(m.group(1), m.group(1)): int(m.group(2))
            for m in re.finditer(r"OpDecorate %(\d+) SpecId (\d+)", text)}
    local = re.search(r"OpExecutionMode %\d+ LocalSize (\d+) (\d+) (\d+)", text)
    sets = {m.group(1): int(m.group(2)) for m in re.finditer(r"OpDecorate %(\d+) DescriptorSet (\d+)", text)}
    types = dict(re.findall(r"%(\d+) = (OpType\w+)", text))
    # An image's Dim, Arrayed, MS and Sampled operands (not Depth: slangc says 2, "unknown", glslang 0, "not a
    # depth image"; the same to Vulkan for a non-comparison image), a sampled image's image's.
    images = {m.group(1): "Dim {} Arrayed {} MS {} Sampled {}".format(*(m.group(2).split()[i] for i in (1, 3, 4, 5)))
              for m in re.finditer(r"%(\d+) = OpTypeImage ([^\n]*)", text)}
    images.update({m.group(1): images.get(m.group(2), "?")
                   for m in re.finditer(r"%(\d+) = OpTypeSampledImage %(\d+)", text)})

    def kind(type_id):
        return " ".join(filter(None, [types.get(type_id, "?"), images.get(type_id)]))

    variables = {m.group(1): (m.group(3), kind(pointers.get(m.group(2), ("", ""))[1]))
                 for m in re.finditer(r"%(\d+) = OpVariable %(\d+) (\w+)", text)}
    # (set, binding): (storage class, pointee type) -- names differ (glslang leaves a nameless block's empty)
    resources = {(sets.get(i), int(b)): variables.get(i) for i, b in re.findall(r"OpDecorate %(\d+) Binding (\d+)", text)}
    return push, spec, tuple(int(x) for x in local.groups()) if local else None, resources


def interface(source_dir, out_dir, glslang, spirv_dis):
    no_slangc = os.path.exists(skip_marker(out_dir))  # then glslang's modules are checked alone
    config = config_defines(source_dir)
    problems = []
    for variant, (kind, module, kept) in VARIANTS.items():
        problems += interface_of(source_dir, out_dir, glslang, spirv_dis, config, kind, module, kept, no_slangc)
    if no_slangc:
        print("slangc: not checked, " + open(skip_marker(out_dir), encoding="utf-8").read().strip())
    if problems:
        fail("\n  ".join(["the sample shader's interface:"] + problems))


def interface_of(source_dir, out_dir, glslang, spirv_dis, config, kind, module, kept, no_slangc):
    """The problems of one variant's modules (see the top)."""
    slang_spv = os.path.join(out_dir, module)
    if not no_slangc and not os.path.exists(slang_spv):
        fail(f"{slang_spv} missing: its fixture slang.sample_spirv* failed or did not run")
    glslang_spv = os.path.join(out_dir, module.replace(".spv", ".glslang.spv"))
    shaders = os.path.join(source_dir, "shaders")
    run([glslang, "-V", "--target-env", "vulkan1.2", f"-I{shaders}", f"-I{os.path.join(shaders, 'harness')}",
         f"-DHARNESS_RESOURCE={config[kind]}", "-S", "comp", os.path.join(shaders, "harness", "sample.comp.glsl"),
         "-o", glslang_spv],
        f"glslangValidator -DHARNESS_RESOURCE={config[kind]} ({kind}) of sample.comp.glsl")
    problems = []
    facts = {}
    modules = [("glslang", glslang_spv)] + ([] if no_slangc else [("slangc", slang_spv)])
    for compiler, spv in modules:
        push, spec, local, resources = module_facts(spirv_dis, spv)
        facts[compiler] = resources
        who = f"{kind} {compiler}"
        if not push:
            problems.append(f"{who}: no push-constant block")
        for member, offset in push.items():
            expected = config.get("HARNESS_PUSH_" + upper_snake(member))
            if expected != offset:
                problems.append(f"{who}: push constant {member} at {offset}, config.h says {expected}")
        for name, spec_id in spec.items():
            expected = config.get("HARNESS_SPEC_" + re.sub(r"_ID$", "", name))
            if expected != spec_id:
                problems.append(f"{who}: specialization constant {name} has id {spec_id}, config.h says {expected}")
        if "FILTER_ID" not in spec:
            problems.append(f"{who}: no specialization constant FILTER_ID")
        if local != (config["HARNESS_SAMPLE_LOCAL_SIZE"], 1, 1):
            problems.append(f"{who}: local size {local}")
        print(f"{who}: {len(push)} push-constant members, spec ids {spec}, local size {local}, "
              f"resources {dict(sorted(resources.items()))}")
    # slangc may drop a resource the shader never reads; what it keeps must
    # sit where glslang puts it, as the same kind of resource, and the buffers and the kind's texture be there.
    if not no_slangc:
        for where, what in facts["slangc"].items():
            if facts["glslang"].get(where) != what:
                problems.append(f"{kind} (set, binding) {where}: slangc {what}, glslang {facts['glslang'].get(where)}")
        for binding in ["LOOKUPS", "RESULTS", "STATS"] + kept:
            if (0, config["HARNESS_BINDING_" + binding]) not in facts["slangc"]:
                problems.append(f"{kind} slangc: nothing at set 0, HARNESS_BINDING_{binding}")
    return problems


def target(source_dir, out_dir, glslang, spirv_val, name):
    slang_target, flags, suffix, validator = TARGETS[name]
    shaders = os.path.join(source_dir, "shaders")
    out = os.path.join(out_dir, f"uses_texfilter.{suffix}")
    if os.path.exists(out):
        os.remove(out)
    run(slangc(source_dir) + ["-allow-glsl", "-target", slang_target] + flags +
        ["-stage", "compute", "-entry", "main", "-I", shaders,
         os.path.join(source_dir, "tests", "slang", "uses_texfilter.slang"), "-o", out],
        f"slangc -target {slang_target} {' '.join(flags)} of tests/slang/uses_texfilter.slang")
    if not os.path.exists(out) or not os.path.getsize(out):
        fail(f"slangc wrote no {out}")
    checked = "not validated (no compiler for it here)"
    if validator == "spirv-val":
        source_language_unknown(out, out + ".val")
        validate(spirv_val, out + ".val")
        checked = "spirv-val vulkan1.2 passed"
    elif validator == "glslang":
        run([glslang, "-V", "--target-env", "vulkan1.2", "-S", "comp", out, "-o", out + ".spv"],
            f"glslangValidator of slangc's GLSL {out}")
        checked = "glslangValidator -V passed"
    elif validator == "naga":
        naga = shutil.which("naga")
        if naga:
            run([naga, out], f"naga of slangc's WGSL {out}")
            checked = "naga passed"
        else:
            checked = "not validated: naga (wgpu's WGSL validator) is not installed here"
    print(f"{out}: {os.path.getsize(out)} bytes, {checked}")


def main(argv):
    if argv[1:] == ["--list"]:
        print("\n".join(GROUPS))
        return
    if len(argv) != 7 or argv[6] not in GROUPS:
        sys.exit(__doc__)
    source_dir, out_dir, glslang, spirv_val, spirv_dis, group = argv[1:]
    os.makedirs(out_dir, exist_ok=True)
    if group.startswith("sample_spirv"):
        sample_spirv(source_dir, out_dir, spirv_val, group[len("sample_spirv"):])
    elif group == "interface":
        interface(source_dir, out_dir, glslang, spirv_dis)
    else:
        target(source_dir, out_dir, glslang, spirv_val, group.split(".", 1)[1])


if __name__ == "__main__":
    main(sys.argv)
