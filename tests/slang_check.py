#!/usr/bin/env python3
"""texfilter under Slang's compiler (slangc from tools/.venv: tools/slangc.sh), as ctest entries slang.GROUP.

usage: slang_check.py --list
       slang_check.py SOURCE_DIR OUT_DIR GLSLANG SPIRV_VAL SPIRV_DIS GROUP
Groups:
  sample_spirv   shaders/harness/sample.comp.glsl (the combined kind, filter_select.glsl) compiled by
                 `slangc -allow-glsl -target spirv -O0` to OUT_DIR/sample.spv, then spirv-val --target-env
                 vulkan1.2. The fixture of slang.interface and slang.sample.* (tests/test_slang.cpp runs
                 `texfilter sample --spirv OUT_DIR/sample.spv`).
  interface      that module and glslang's of the same source agree with shaders/harness/config.h: each
                 push-constant member at its HARNESS_PUSH_* offset (the member's name in upper case with
                 underscores), each specialization constant NAME_ID at HARNESS_SPEC_NAME, the workgroup size
                 HARNESS_SAMPLE_LOCAL_SIZE; every resource slangc keeps at the (set, binding) where glslang puts
                 it, as the same kind (storage class and type). Without slangc here, glslang's module alone.
  target.TARGET  tests/slang/uses_texfilter.slang (a Slang shader that #includes texfilter/texfilter.glsl and
                 calls every 2D family on a Sampler2D and on a Texture2D through TF_SOURCE) compiles to TARGET,
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
# sampler2D) only where slangc emits valid code for it: its HLSL, Metal and WGSL output for texelFetch,
# textureSize and textureQueryLevels on a sampler2D passed to a function pass the SamplerState where the
# coordinate or the level goes (e.g. HLSL `t.Load(sampler, coord)`, WGSL `textureDimensions(t, sampler)`), so
# those targets take the TF_SOURCE kind alone (a Texture2D read with Load/GetDimensions), docs/API.md "Slang".
SOURCE_ONLY = ["-DTEXFILTER_SAMPLER_2D=0"]
TARGETS = {
    "spirv": ("spirv", ["-O0"], "spv", "spirv-val"),
    "glsl": ("glsl", [], "comp", "glslang"),
    "hlsl": ("hlsl", SOURCE_ONLY, "hlsl", None),  # no HLSL compiler on Debian bookworm
    "metal": ("metal", SOURCE_ONLY, "metal", None),  # no Metal compiler off macOS
    "wgsl": ("wgsl", SOURCE_ONLY, "wgsl", "naga"),  # naga (wgpu's validator) where installed
}
GROUPS = ["sample_spirv", "interface"] + [f"target.{t}" for t in TARGETS]
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


def sample_spirv(source_dir, out_dir, spirv_val):
    shaders = os.path.join(source_dir, "shaders")
    raw = os.path.join(out_dir, "sample.slangc.spv")
    out = os.path.join(out_dir, "sample.spv")
    for stale in (raw, out, skip_marker(out_dir)):  # a failed run leaves no module for the checks to run
        if os.path.exists(stale):
            os.remove(stale)
    version = run(slangc(source_dir) + ["-v"], "slangc -v", out_dir).strip()
    run(slangc(source_dir) + ["-allow-glsl", "-target", "spirv", "-O0", "-stage", "compute", "-entry", "main",
                              "-I", shaders, "-I", os.path.join(shaders, "harness"),
                              os.path.join(shaders, "harness", "sample.comp.glsl"), "-o", raw],
        "slangc of sample.comp.glsl")
    rewritten = source_language_unknown(raw, raw + ".tmp")
    validate(spirv_val, raw + ".tmp")
    os.replace(raw + ".tmp", out)
    print(f"slangc {version}: {out} ({os.path.getsize(out)} bytes), {rewritten} OpSource operand(s) 11 -> 0, "
          "spirv-val vulkan1.2 passed")


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
    variables = {m.group(1): (m.group(3), types.get(pointers.get(m.group(2), ("", ""))[1], "?"))
                 for m in re.finditer(r"%(\d+) = OpVariable %(\d+) (\w+)", text)}
    # (set, binding): (storage class, pointee type) -- names differ (glslang leaves a nameless block's empty)
    resources = {(sets.get(i), int(b)): variables.get(i) for i, b in re.findall(r"OpDecorate %(\d+) Binding (\d+)", text)}
    return push, spec, tuple(int(x) for x in local.groups()) if local else None, resources


def interface(source_dir, out_dir, glslang, spirv_dis):
    slang_spv = os.path.join(out_dir, "sample.spv")
    no_slangc = os.path.exists(skip_marker(out_dir))  # then glslang's module is checked alone
    if not no_slangc and not os.path.exists(slang_spv):
        fail(f"{slang_spv} missing: slang.sample_spirv (the fixture) failed or did not run")
    glslang_spv = os.path.join(out_dir, "sample.glslang.spv")
    shaders = os.path.join(source_dir, "shaders")
    run([glslang, "-V", "--target-env", "vulkan1.2", f"-I{shaders}", f"-I{os.path.join(shaders, 'harness')}",
         "-S", "comp", os.path.join(shaders, "harness", "sample.comp.glsl"), "-o", glslang_spv],
        "glslangValidator of sample.comp.glsl")
    config = config_defines(source_dir)
    problems = []
    facts = {}
    modules = [("glslang", glslang_spv)] + ([] if no_slangc else [("slangc", slang_spv)])
    for compiler, spv in modules:
        push, spec, local, resources = module_facts(spirv_dis, spv)
        facts[compiler] = resources
        if not push:
            problems.append(f"{compiler}: no push-constant block")
        for member, offset in push.items():
            expected = config.get("HARNESS_PUSH_" + upper_snake(member))
            if expected != offset:
                problems.append(f"{compiler}: push constant {member} at {offset}, config.h says {expected}")
        for name, spec_id in spec.items():
            expected = config.get("HARNESS_SPEC_" + re.sub(r"_ID$", "", name))
            if expected != spec_id:
                problems.append(f"{compiler}: specialization constant {name} has id {spec_id}, config.h says {expected}")
        if "FILTER_ID" not in spec:
            problems.append(f"{compiler}: no specialization constant FILTER_ID")
        if local != (config["HARNESS_SAMPLE_LOCAL_SIZE"], 1, 1):
            problems.append(f"{compiler}: local size {local}")
        print(f"{compiler}: {len(push)} push-constant members, spec ids {spec}, local size {local}, "
              f"resources {dict(sorted(resources.items()))}")
    # slangc drops resources the shader never reads (the SAT's tables in this kind); what it keeps must sit
    # where glslang puts it, as the same kind of resource, and the lookups, results, stats and texture be there.
    if no_slangc:
        print("slangc: not checked, " + open(skip_marker(out_dir), encoding="utf-8").read().strip())
    else:
        for where, kind in facts["slangc"].items():
            if facts["glslang"].get(where) != kind:
                problems.append(f"(set, binding) {where}: slangc {kind}, glslang {facts['glslang'].get(where)}")
        for binding in ("LOOKUPS", "RESULTS", "STATS", "TEXTURE"):
            if (0, config["HARNESS_BINDING_" + binding]) not in facts["slangc"]:
                problems.append(f"slangc: nothing at set 0, HARNESS_BINDING_{binding}")
    if problems:
        fail("\n  ".join(["the sample shader's interface:"] + problems))


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
    if group == "sample_spirv":
        sample_spirv(source_dir, out_dir, spirv_val)
    elif group == "interface":
        interface(source_dir, out_dir, glslang, spirv_dis)
    else:
        target(source_dir, out_dir, glslang, spirv_val, group.split(".", 1)[1])


if __name__ == "__main__":
    main(sys.argv)
